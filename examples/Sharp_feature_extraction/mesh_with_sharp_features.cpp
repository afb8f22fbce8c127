// Surface reconstruction with sharp features (the paper's reconstruction application): point
// cloud in, closed triangle mesh out, its creases on the extracted curves. extract_sharp_features()
// gives the curves and the scales of the cloud, reconstruct_surface_with_sharp_features() the rest;
// --no-features runs the same reconstruction without any curve, for comparison.
//
//   mesh_with_sharp_features cloud.xyz out          # writes out.off and out.ply

#include "utilities/feature_curve_files.h"
#include "utilities/progress_bar.h"
#include "utilities/surface_mesh_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/reconstruct_surface_with_sharp_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Feature_polyline<K> Curve;
namespace sfe = CGAL::Sharp_feature_extraction;

namespace {

const char* usage =
  "usage: mesh_with_sharp_features [options] <points> <output>\n"
  "\n"
  "Meshes the surface sampled by <points> (XYZ, PLY, OFF, ...: only the positions are read)\n"
  "with Mesh_3 over a Poisson implicit surface, the extracted sharp feature curves protected.\n"
  "Writes <output>.off and <output>.ply. Exit status: 0 success, 1 bad input or failure,\n"
  "3 mesh written but incomplete (Mesh_3 stopped) or not closed, not manifold or\n"
  "self-intersecting; the last line on stderr says why.\n"
  "\n"
  "options:\n"
  "  --no-features          the same pipeline without any feature curve (for comparison)\n"
  "  --curves FILE          use these curves instead of the extracted ones; one curve per line:\n"
  "                         n x1 y1 z1 ... xn yn zn, or with both normals of every vertex\n"
  "                         n x1 y1 z1 a1 b1 c1 d1 e1 f1 ... (9 numbers per vertex)\n"
  "  --no-protection        use the curves for normals and the implicit surface only\n"
  "  --no-sharpening        do not replace the implicit surface near the curves\n"
  "  --no-normal-correction keep the jet normals near the curves\n"
  "  --spacing S            sampling spacing (default: the extraction's, the mean distance to\n"
  "                         the 6th neighbour)\n"
  "  --facet-size X         Mesh_3 sizes: a length, or a multiple of the spacing written\n"
  "  --facet-distance X       with a trailing s (\"2s\"). Defaults: facet size 1.875s, facet\n"
  "  --edge-size X            distance 0.0625s or the noise scale if larger, edge size\n"
  "                           (along the curves) 1.875s,\n"
  "  --facet-angle DEG        facet angle 25\n"
  "  --time-limit SEC       stop Mesh_3 after this long (default 1800; 0: none); Mesh_3 is\n"
  "                         also stopped beyond 2 vertices per input point (a runaway)\n"
  "  --curves-out FILE      write the curves given to Mesh_3 (one polyline per line)\n"
  "  --stats FILE           write timings and counts as key=value lines\n"
  "  --quiet                no progress and no summary\n"
  "  --help                 this text\n";

[[noreturn]] void fail(const std::string& message)
{
  std::cerr << "mesh_with_sharp_features: " << message << std::endl;
  std::exit(EXIT_FAILURE);
}

struct Arguments
{
  bool features = true, protect = true, sharpen = true, correct_normals = true, quiet = false;
  std::string curves_path, curves_out, stats_path, input, output;
  double spacing = 0, facet_angle = 25, time_limit = 1800;
  /// a length, or a multiple of the spacing (negative)
  double facet_size = 0, facet_distance = 0, edge_size = 0;
};

double parse_number(const std::string& option, const std::string& text, bool multiple_of_spacing_allowed = false)
{
  std::string number = text;
  const bool relative = multiple_of_spacing_allowed && !number.empty() && number.back() == 's';
  if(relative)
    number.pop_back();
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if(number.empty() || *end != '\0' || !(value >= 0) || (multiple_of_spacing_allowed && value == 0))
    fail(option + " expects a " + (multiple_of_spacing_allowed ? "positive length or a multiple of the spacing like 2s"
                                                               : "non-negative number") + ", not '" + text + "'");
  return relative ? -value : value;
}

Arguments parse_arguments(int argc, char* argv[])
{
  Arguments a;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        fail(arg + " expects a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") {
      std::cout << usage;
      std::exit(EXIT_SUCCESS);
    } else if(arg == "--no-features") a.features = false;
    else if(arg == "--curves") a.curves_path = value();
    else if(arg == "--no-protection") a.protect = false;
    else if(arg == "--no-sharpening") a.sharpen = false;
    else if(arg == "--no-normal-correction") a.correct_normals = false;
    else if(arg == "--spacing") a.spacing = parse_number(arg, value());
    else if(arg == "--facet-size") a.facet_size = parse_number(arg, value(), true);
    else if(arg == "--facet-distance") a.facet_distance = parse_number(arg, value(), true);
    else if(arg == "--edge-size") a.edge_size = parse_number(arg, value(), true);
    else if(arg == "--facet-angle") a.facet_angle = parse_number(arg, value());
    else if(arg == "--time-limit") a.time_limit = parse_number(arg, value());
    else if(arg == "--curves-out") a.curves_out = value();
    else if(arg == "--stats") a.stats_path = value();
    else if(arg == "--quiet") a.quiet = true;
    else if(!arg.empty() && arg[0] == '-' && arg.size() > 1) fail("unknown option " + arg + " (see --help)");
    else files.push_back(arg);
  }
  if(files.size() != 2)
    fail("expected an input point file and an output name (see --help)");
  a.input = files[0];
  a.output = files[1];
  if(!a.features)
    a.protect = a.sharpen = a.correct_normals = false;
  return a;
}

/// The curves and the scales of the cloud. Without features the extraction still runs: the
/// reconstruction takes its sizes from the scales it measures.
CGAL::Feature_curve_network<K> extract(const std::vector<Point_3>& points, const Arguments& a,
                                       const sfe_utilities::Terminal_progress_bar& bar)
{
  CGAL::Sharp_features<K> extracted;
  CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(
    points, extracted, CGAL::parameters::callback([&](double f) { return a.quiet || bar(f); }));
  CGAL::Feature_curve_network<K> network = extracted.network;
  if(!a.curves_path.empty()) {
    try {
      network.polylines = sfe_utilities::read_feature_curves<K>(a.curves_path);
    } catch(const std::exception& e) {
      fail(e.what());
    }
    network.corners.clear();
  }
  if(a.spacing > 0)
    network.scales.spacing = a.spacing;
  return network;
}

/// Mesh_3 stuck where it does not read its stop flag (see unresponsive_mesher_handler): only the
/// process can end it.
[[noreturn]] void stop_when_stuck(double seconds, double time_limit)
{
  std::cerr << "\nmesh_with_sharp_features: Mesh_3 failed: still protecting the feature curves " << seconds
            << " s after the start, past its time limit of " << time_limit << " s" << std::endl;
  std::_Exit(EXIT_FAILURE);
}

/// the reconstruction with the options of the command line; fails in one line if it makes no surface.
CGAL::Surface_reconstruction_report<K> reconstruct(const std::vector<Point_3>& points,
                                                   const CGAL::Feature_curve_network<K>& network, const Arguments& a,
                                                   const sfe_utilities::Terminal_progress_bar& bar,
                                                   std::vector<Point_3>& mesh_points,
                                                   std::vector<std::array<std::size_t, 3>>& triangles)
{
  // a size given as a multiple of the spacing (negative) becomes a length
  auto length = [&](double size) { return size < 0 ? -size * network.scales.spacing : size; };
  const auto mesh_3 = CGAL::parameters::maximum_running_time(a.time_limit)
                        .callback(std::function<bool(double)>([&](double f) { return a.quiet || bar(f); }));
  const auto sizes = sfe::parameters::facet_size(
    length(a.facet_size),
    sfe::parameters::facet_distance(
      length(a.facet_distance),
      sfe::parameters::edge_size(length(a.edge_size), sfe::parameters::facet_angle(a.facet_angle, mesh_3))));
  const auto uses = sfe::parameters::protect_polylines(
    a.protect, sfe::parameters::correct_normals(a.correct_normals, sfe::parameters::sharpen_creases(a.sharpen, sizes)));
  const std::function<void(double)> when_stuck = [&a](double seconds) { stop_when_stuck(seconds, a.time_limit); };
  CGAL::Surface_reconstruction_report<K> report;
  try {
    report = CGAL::reconstruct_surface_with_sharp_features<CGAL::Parallel_if_available_tag>(
      points, network, mesh_points, triangles, sfe::parameters::unresponsive_mesher_handler(when_stuck, uses));
  } catch(const CGAL::Surface_reconstruction_error& e) {
    bar.finish();
    fail(e.what());
  }
  bar.finish();
  if(triangles.empty())
    fail(report.stop_reason.empty() ? "no surface" : report.stop_reason);
  return report;
}

/// writes the soup as a halfedge mesh, facing outward, in OFF and PLY.
void write_mesh(const std::string& output, std::vector<Point_3> points,
                const std::vector<std::array<std::size_t, 3>>& triangles, bool closed_manifold)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::vector<std::size_t>> polygons;
  for(const auto& t : triangles)
    polygons.push_back(std::vector<std::size_t>(t.begin(), t.end()));
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    PMP::orient_polygon_soup(points, polygons);
  CGAL::Surface_mesh<Point_3> mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(closed_manifold && !PMP::is_outward_oriented(mesh))
    PMP::reverse_face_orientations(mesh);
  for(const std::string extension : {".off", ".ply"})
    if(!CGAL::IO::write_polygon_mesh(output + extension, mesh, CGAL::parameters::stream_precision(17)))
      fail("cannot write " + output + extension);
}

void write_summary(std::ostream& out, std::size_t points, const CGAL::Surface_reconstruction_report<K>& r,
                   const sfe_meshing::Surface_check& check, bool features, double seconds_extraction,
                   double seconds_total)
{
  out << points << " points, spacing " << r.spacing << ", noise " << r.noise << "\n";
  if(features)
    out << "curves: " << r.repair.summary() << "; " << r.protected_polylines.size() << " protected ("
        << r.protected_vertices << " protected vertices), " << r.projected_onto_creases
        << " curve vertices moved onto the fitted creases, " << r.moved_onto_surface << " onto the surface, "
        << r.cut_off_surface << " curves cut off the surface, " << r.cut_near_other_sheet
        << " near another sheet of it\n"
        << "curves repaired again on the surface: " << r.repair_after_projection.summary() << "\n";
  out << "normals: " << r.corrected_normals << " corrected near creases, " << r.unoriented_points
      << " left unoriented (dropped)\nsizes: facet " << r.facet_size << ", distance " << r.facet_distance
      << ", edge " << r.edge_size << ", angle " << r.facet_angle << "\nmesh: " << check.summary()
      << "\ntime: extraction " << seconds_extraction << " s, normals " << r.seconds_normals << " s, Poisson "
      << r.seconds_poisson << " s, Mesh_3 " << r.seconds_meshing << " s, total " << seconds_total << " s\n";
}

void write_stats(const std::string& path, std::size_t points, const CGAL::Surface_reconstruction_report<K>& r,
                 const sfe_meshing::Surface_check& check, bool features, double seconds_extraction,
                 double seconds_total)
{
  std::ofstream stats(path);
  stats << "points=" << points << "\nspacing=" << r.spacing << "\nnoise=" << r.noise
        << "\nfacet_distance=" << r.facet_distance << "\nfar_field=" << r.far_field
        << "\nfeatures=" << (features ? 1 : 0) << "\ncurves_in=" << r.repair.input_polylines
        << "\ncurves_protected=" << r.protected_polylines.size() << "\ncurves_cut_off_surface=" << r.cut_off_surface
        << "\ncurves_cut_near_other_sheet=" << r.cut_near_other_sheet
        << "\ncurve_vertices_moved_onto_surface=" << r.moved_onto_surface
        << "\ncorrected_normals=" << r.corrected_normals << "\ntriangles=" << check.triangles
        << "\nvertices=" << check.vertices << "\nclosed=" << check.closed() << "\nmanifold=" << check.manifold()
        << "\nself_intersecting=" << check.self_intersecting() << "\nstopped=" << r.stopped
        << "\nseconds_extraction=" << seconds_extraction << "\nseconds_normals=" << r.seconds_normals
        << "\nseconds_poisson=" << r.seconds_poisson << "\nseconds_meshing=" << r.seconds_meshing
        << "\nseconds_total=" << seconds_total << "\n";
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char* argv[])
{
  const Arguments a = parse_arguments(argc, argv);
  std::vector<Point_3> points;
  if(!std::ifstream(a.input))
    fail("cannot open " + a.input);
  if(!CGAL::IO::read_points(a.input, std::back_inserter(points)) || points.empty())
    fail("cannot read points from " + a.input + " (XYZ, PLY, OFF, LAS)");

  const auto start = std::chrono::steady_clock::now();
  sfe_utilities::Terminal_progress_bar bar("extracting curves");
  const CGAL::Feature_curve_network<K> network = extract(points, a, bar);
  const double seconds_extraction = seconds_since(start);
  bar.set_stage("reconstructing");
  std::vector<Point_3> mesh_points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const CGAL::Surface_reconstruction_report<K> report = reconstruct(points, network, a, bar, mesh_points, triangles);
  const sfe_meshing::Surface_check check = sfe_meshing::check_triangle_soup(mesh_points, triangles);
  write_mesh(a.output, mesh_points, triangles, check.closed() && check.manifold());
  try {
    if(!a.curves_out.empty())
      sfe_utilities::write_feature_curves(a.curves_out, report.protected_polylines);
  } catch(const std::exception& e) {
    fail(e.what());
  }
  const double seconds_total = seconds_since(start);
  if(!a.quiet)
    write_summary(std::cout, points.size(), report, check, a.features, seconds_extraction, seconds_total);
  if(!a.stats_path.empty())
    write_stats(a.stats_path, points.size(), report, check, a.features, seconds_extraction, seconds_total);
  // a stopped Mesh_3 leaves an incomplete mesh, valid or not: say why, in one line
  if(report.stopped)
    std::cerr << "mesh_with_sharp_features: incomplete mesh written: " << report.stop_reason << std::endl;
  else if(!check.valid())
    std::cerr << "mesh_with_sharp_features: mesh written but " << check.summary() << std::endl;
  return check.valid() && !report.stopped ? EXIT_SUCCESS : 3;
}
