// Feature-protected meshing of a point cloud (the paper's reconstruction application).
//
// Point cloud in (no normals needed), closed triangle mesh out:
//   1. extract the sharp feature curves (extract_sharp_features(), default parameters);
//   2. estimate normals (jet fitting), orient them (a spanning tree along the surface's
//      sheets, meshing/orient_normals_along_sheets.h), then give the points near a curve
//      the normal of their own side of the crease, taken from the curve's two normals;
//   3. build an implicit surface from the oriented points (Poisson reconstruction), replaced
//      near the curves by the two surfaces that meet there, so that the creases stay sharp;
//   4. mesh it with Mesh_3, the curves protected as polyline features, manifold output;
//   5. write the surface as OFF and PLY and check it is closed, manifold, self-intersection free.
// --no-features runs the same steps without any curve, for comparison.
//
//   mesh_with_sharp_features cloud.xyz out          # writes out.off and out.ply
//   mesh_with_sharp_features --no-features cloud.xyz out_plain

#include "meshing/feature_curve_repair.h"
#include "meshing/point_cloud_meshing.h"
#include "meshing/surface_mesh_checks.h"
#include "utilities/progress_bar.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#if __has_include(<CGAL/Sharp_feature_extraction/extract_sharp_features.h>)
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#define SFE_HAS_EXTRACTION 1
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#ifndef _WIN32
#include <unistd.h>
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Feature_polyline<K> Curve;

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
  "  --curves FILE          use these curves instead of extracting them; one curve per line:\n"
  "                         n x1 y1 z1 ... xn yn zn, or with both normals of every vertex\n"
  "                         n x1 y1 z1 a1 b1 c1 d1 e1 f1 ... (9 numbers per vertex)\n"
  "  --no-protection        use the curves for normals and the implicit surface only\n"
  "  --no-sharpening        do not replace the implicit surface near the curves\n"
  "  --no-normal-correction keep the jet normals near the curves\n"
  "  --spacing S            sampling spacing (default: mean distance to the 6th neighbour)\n"
  "  --facet-size X         Mesh_3 sizes: a length, or a multiple of the spacing written\n"
  "  --facet-distance X       with a trailing s (\"3s\"). Defaults: facet size 3s, facet\n"
  "  --edge-size X            distance 0.1s or the noise scale if larger, edge size\n"
  "                           (along the curves) 3s,\n"
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

/// a length, or a multiple of the spacing when it ends with 's' (returned negative).
double parse_size(const std::string& option, const std::string& text)
{
  std::string number = text;
  const bool relative = !number.empty() && number.back() == 's';
  if(relative)
    number.pop_back();
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if(number.empty() || *end != '\0' || !(value > 0))
    fail(option + " expects a positive length or a multiple of the spacing like 3s, not '" + text + "'");
  return relative ? -value : value;
}

double parse_number(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !(value >= 0))
    fail(option + " expects a non-negative number, not '" + text + "'");
  return value;
}

std::vector<Curve> read_curves(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    fail("cannot open curve file " + path);
  std::vector<Curve> curves;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line)) {
    ++line_number;
    std::istringstream fields(line);
    std::vector<double> v;
    double x;
    while(fields >> x)
      v.push_back(x);
    if(v.empty())
      continue;
    const std::size_t n = static_cast<std::size_t>(v[0]);
    Curve c;
    if(v.size() == 1 + 3 * n) {
      for(std::size_t i = 0; i < n; ++i)
        c.points.push_back(Point_3(v[1 + 3 * i], v[2 + 3 * i], v[3 + 3 * i]));
    } else if(v.size() == 1 + 9 * n) {
      for(std::size_t i = 0; i < n; ++i) {
        const double* p = &v[1 + 9 * i];
        c.points.push_back(Point_3(p[0], p[1], p[2]));
        c.normals.push_back({{Vector_3(p[3], p[4], p[5]), Vector_3(p[6], p[7], p[8])}});
      }
    } else {
      fail(path + ":" + std::to_string(line_number) + ": expected a count n then 3n or 9n numbers");
    }
    curves.push_back(c);
  }
  return curves;
}

void write_curves(const std::string& path, const std::vector<Curve>& curves)
{
  std::ofstream out(path);
  out.precision(17);
  for(const Curve& c : curves) {
    out << c.points.size();
    for(std::size_t i = 0; i < c.points.size(); ++i) {
      out << ' ' << c.points[i];
      if(c.normals.size() == c.points.size())
        out << ' ' << c.normals[i][0] << ' ' << c.normals[i][1];
    }
    out << '\n';
  }
  if(!out)
    fail("cannot write " + path);
}

/// Progress on stderr: a bar for the stages that report a fraction, elapsed seconds for those
/// that cannot (Poisson, Mesh_3). Silent when stderr is not a terminal.
class Stage_display
{
public:
  explicit Stage_display(bool quiet) : m_bar("extracting curves"), m_quiet(quiet)
  {
#ifndef _WIN32
    m_terminal = isatty(fileno(stderr)) != 0;
#endif
  }

  sfe_utilities::Terminal_progress_bar& bar() { return m_bar; }

  void operator()(const std::string& stage, double fraction, double seconds)
  {
    if(m_quiet)
      return;
    if(stage != m_stage) {
      m_bar.finish();
      if(m_timer_line)
        std::fputc('\n', stderr);
      m_timer_line = false;
      m_stage = stage;
      m_bar.set_stage(stage);
    }
    if(fraction >= 0) {
      m_bar(fraction);
    } else if(m_terminal) {
      std::fprintf(stderr, "\r%s ... %.0f s\x1b[K", stage.c_str(), seconds);
      std::fflush(stderr);
      m_timer_line = true;
    }
  }

  void finish()
  {
    m_bar.finish();
    if(m_timer_line)
      std::fputc('\n', stderr);
    m_timer_line = false;
  }

private:
  sfe_utilities::Terminal_progress_bar m_bar;
  std::string m_stage;
  bool m_quiet = false, m_terminal = false, m_timer_line = false;
};

} // namespace

int main(int argc, char* argv[])
{
  sfe_meshing::Point_cloud_meshing_options options;
  options.limits.time_limit = 1800;
  bool features = true, quiet = false;
  std::string curves_path, curves_out, stats_path;
  std::vector<std::string> files;
  double facet_size = 0, facet_distance = 0, edge_size = 0;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        fail(arg + " expects a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") {
      std::cout << usage;
      return EXIT_SUCCESS;
    } else if(arg == "--no-features") features = false;
    else if(arg == "--curves") curves_path = value();
    else if(arg == "--no-protection") options.protect_curves = false;
    else if(arg == "--no-sharpening") options.sharpen_creases = false;
    else if(arg == "--no-normal-correction") options.correct_normals = false;
    else if(arg == "--spacing") options.spacing = parse_size(arg, value());
    else if(arg == "--facet-size") facet_size = parse_size(arg, value());
    else if(arg == "--facet-distance") facet_distance = parse_size(arg, value());
    else if(arg == "--edge-size") edge_size = parse_size(arg, value());
    else if(arg == "--facet-angle") options.facet_angle = parse_number(arg, value());
    else if(arg == "--time-limit") options.limits.time_limit = parse_number(arg, value());
    else if(arg == "--curves-out") curves_out = value();
    else if(arg == "--stats") stats_path = value();
    else if(arg == "--quiet") quiet = true;
    else if(!arg.empty() && arg[0] == '-' && arg.size() > 1) fail("unknown option " + arg + " (see --help)");
    else files.push_back(arg);
  }
  if(files.size() != 2)
    fail("expected an input point file and an output name (see --help)");
  if(options.spacing < 0)
    fail("--spacing must be a length, not a multiple of itself");
  // negative: a multiple of the spacing
  auto set_size = [](double parsed, double& relative, double& absolute) {
    if(parsed > 0) absolute = parsed;
    else if(parsed < 0) relative = -parsed;
  };
  set_size(facet_size, options.facet_size, options.absolute_facet_size);
  set_size(facet_distance, options.facet_distance, options.absolute_facet_distance);
  set_size(edge_size, options.edge_size, options.absolute_edge_size);
  if(!features)
    options.protect_curves = options.correct_normals = options.sharpen_creases = false;

  std::vector<Point_3> points;
  if(!std::ifstream(files[0]))
    fail("cannot open " + files[0]);
  if(!CGAL::IO::read_points(files[0], std::back_inserter(points)) || points.empty())
    fail("cannot read points from " + files[0] + " (XYZ, PLY, OFF, LAS)");

  const auto start = std::chrono::steady_clock::now();
  Stage_display display(quiet);
  std::vector<Curve> curves;
  std::vector<Point_3> corners;
  double seconds_extraction = 0;
  if(features) {
    if(!curves_path.empty()) {
      curves = read_curves(curves_path);
    } else {
#ifdef SFE_HAS_EXTRACTION
      CGAL::Sharp_features<K> extracted;
      const auto t0 = std::chrono::steady_clock::now();
      std::function<bool(double)> callback = [](double) { return true; };
      if(!quiet) {
        display("extracting curves", 0, 0);
        callback = display.bar();
      }
      CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, extracted,
                                                                   CGAL::parameters::callback(callback));
      curves = extracted.network.polylines;
      for(const auto& c : extracted.network.corners)
        corners.push_back(c.point);
      seconds_extraction = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
#else
      fail("this build has no extract_sharp_features(): pass --curves FILE or --no-features");
#endif
    }
  }

  const auto result = sfe_meshing::mesh_point_cloud<K, CGAL::Parallel_if_available_tag>(
    points, curves, options,
    [&](const std::string& stage, double fraction, double seconds) { display(stage, fraction, seconds); },
    corners);
  display.finish();
  if(!result.error.empty() && result.surface.triangles.empty())
    fail(result.error);

  const sfe_meshing::Surface_check check =
    sfe_meshing::check_triangle_soup(result.surface.points, result.surface.triangles);

  // the soup as a halfedge mesh, facing outward, for the writers
  namespace PMP = CGAL::Polygon_mesh_processing;
  CGAL::Surface_mesh<Point_3> mesh;
  std::vector<Point_3> soup_points = result.surface.points;
  std::vector<std::vector<std::size_t>> polygons;
  for(const auto& t : result.surface.triangles)
    polygons.push_back(std::vector<std::size_t>(t.begin(), t.end()));
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    PMP::orient_polygon_soup(soup_points, polygons);
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, mesh);
  if(check.closed() && check.manifold() && !PMP::is_outward_oriented(mesh))
    PMP::reverse_face_orientations(mesh);
  for(const std::string extension : {".off", ".ply"})
    if(!CGAL::IO::write_polygon_mesh(files[1] + extension, mesh, CGAL::parameters::stream_precision(17)))
      fail("cannot write " + files[1] + extension);
  if(!curves_out.empty())
    write_curves(curves_out, result.curves);
  const double seconds_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if(!quiet) {
    std::cout << points.size() << " points, spacing " << result.spacing << ", noise " << result.noise << "\n";
    if(features)
      std::cout << "curves: " << result.repair.summary() << "; " << result.protected_curves
                << " protected (" << result.protected_vertices << " protected vertices), "
                << result.projected_vertices << " curve vertices moved onto the fitted creases\n";
    for(const std::string& problem : result.curve_problems)
      std::cout << "  curve problem left: " << problem << "\n";
    std::cout << "normals: " << result.corrected_normals << " corrected near creases, "
              << result.unoriented_points << " left unoriented (dropped)\n"
              << "sizes: facet " << result.sizes.facet_size << ", distance " << result.sizes.facet_distance
              << ", edge " << result.sizes.edge_size << ", angle " << result.sizes.facet_angle << "\n"
              << "mesh: " << check.summary() << "\n"
              << "time: extraction " << seconds_extraction << " s, normals " << result.seconds_normals
              << " s, Poisson " << result.seconds_poisson << " s, Mesh_3 " << result.seconds_meshing
              << " s, total " << seconds_total << " s\n";
  }
  if(!stats_path.empty()) {
    std::ofstream stats(stats_path);
    stats << "points=" << points.size() << "\nspacing=" << result.spacing << "\nnoise=" << result.noise
          << "\nfacet_distance=" << result.sizes.facet_distance << "\nfar_field=" << result.far_field
          << "\nfeatures=" << (features ? 1 : 0) << "\ncurves_in=" << result.repair.input_curves
          << "\ncurves_protected=" << result.protected_curves
          << "\ncurves_cut_off_surface=" << result.repair.cut_off_surface
          << "\ncurve_vertices_moved_onto_surface=" << result.repair.moved_onto_surface
          << "\ncurve_problems=" << result.curve_problems.size()
          << "\ncorrected_normals=" << result.corrected_normals
          << "\ntriangles=" << check.triangles << "\nvertices=" << check.vertices
          << "\nclosed=" << check.closed() << "\nmanifold=" << check.manifold()
          << "\nself_intersecting=" << check.self_intersecting()
          << "\nstopped=" << result.stopped
          << "\nseconds_extraction=" << seconds_extraction << "\nseconds_normals=" << result.seconds_normals
          << "\nseconds_poisson=" << result.seconds_poisson << "\nseconds_meshing=" << result.seconds_meshing
          << "\nseconds_total=" << seconds_total << "\n";
  }
  // a stopped Mesh_3 leaves an incomplete mesh, valid or not: say why, in one line
  if(result.stopped)
    std::cerr << "mesh_with_sharp_features: incomplete mesh written: " << result.error << std::endl;
  else if(!check.valid())
    std::cerr << "mesh_with_sharp_features: mesh written but " << check.summary() << std::endl;
  return check.valid() && !result.stopped ? EXIT_SUCCESS : 3;
}
