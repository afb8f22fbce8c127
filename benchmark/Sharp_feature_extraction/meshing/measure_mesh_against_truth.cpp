// Measures a reconstructed mesh against the true mesh it was sampled from (meshing benchmark).
//
//   measure_mesh_against_truth --truth fandisk.off --mesh out.off [--render out]
//       prints key=value lines: triangle count, validity checks, mean/max distance to the
//       truth, the same in the crease band, normal error in the band, crease dihedral angles;
//       --render writes out_full.png and out_closeup.png (same cameras for every mesh of the
//       same truth, so pictures of two meshes compare pixel for pixel).
//   measure_mesh_against_truth --truth fandisk.off --sample-to cloud.xyz --points 100000 --noise 0.005
//       samples the truth uniformly (noise: radius of a uniform ball, fraction of dB).
//   measure_mesh_against_truth --truth fandisk.off --true-curves-to curves.txt
//       writes the true creases as curves with their two normals (mesh_with_sharp_features --curves).

#include "mesh_measurement.h"
#include "mesh_rendering.h"
#include "utilities/surface_mesh_checks.h"
#include "utilities/mesh_surface_sampling.h"
#include "utilities/png_image.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;

namespace {

const char* usage =
  "usage: measure_mesh_against_truth --truth TRUE_MESH [mode and options]\n"
  "\n"
  "modes:\n"
  "  --mesh MESH             measure MESH against the truth (key=value lines on stdout)\n"
  "  --render PREFIX         write PREFIX_full.png and PREFIX_closeup.png of MESH (or of the\n"
  "                          truth without --mesh); the close-up looks at a long true crease\n"
  "  --sample-to FILE        write a sampled point cloud of the truth (XYZ)\n"
  "  --true-curves-to FILE   write the true creases as curves with normals\n"
  "options:\n"
  "  --crease-angle DEG      facet normals differing by more make a true crease (default 30)\n"
  "  --band F                crease band half-width, fraction of the diagonal dB (0.02)\n"
  "  --offset F              step into each face for dihedral angles, fraction of dB (0.005)\n"
  "  --samples N             samples of MESH for the distances (200000)\n"
  "  --points N --noise F --seed S   sampling: count, noise ball radius (fraction of dB), seed\n"
  "  --width PIXELS          picture width (800; height 600)\n"
  "  --worst N               also list the N vertices of MESH farthest from the truth\n"
  "  --help\n";

[[noreturn]] void fail(const std::string& message)
{
  std::cerr << "measure_mesh_against_truth: " << message << std::endl;
  std::exit(EXIT_FAILURE);
}

double parse_number(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !(value >= 0) || !std::isfinite(value))
    fail(option + " expects a non-negative number, not '" + text + "'");
  return value;
}

void read_mesh(const std::string& path, std::vector<Point_3>& points,
               std::vector<sfe_meshing::Triangle_indices>& triangles)
{
  if(!std::ifstream(path))
    fail("cannot open " + path);
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons) || polygons.empty())
    fail("cannot read a polygon mesh from " + path);
  for(const auto& p : polygons) {
    if(p.size() < 3)
      continue;
    for(std::size_t v : p)
      if(v >= points.size())
        fail(path + " refers to a missing vertex");
    for(std::size_t i = 1; i + 1 < p.size(); ++i)
      triangles.push_back(sfe_meshing::Triangle_indices{{p[0], p[i], p[i + 1]}});
  }
}

sfe_meshing::Orthographic_camera full_view(const std::vector<Point_3>& points)
{
  CGAL::Bbox_3 box;
  for(const Point_3& p : points)
    box += p.bbox();
  sfe_meshing::Orthographic_camera camera;
  camera.center = {{(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2}};
  camera.direction = {{-0.55, -1, -0.7}};
  camera.up = {{0, 0, 1}};
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  camera.half_width = 0.6 * diagonal;
  return camera;
}

/// looks at the middle of the true crease farthest from any corner, from the side between its
/// two faces, with the crease vertical.
sfe_meshing::Orthographic_camera close_up_view(const sfe_meshing::True_surface<K>& truth)
{
  sfe_meshing::Orthographic_camera camera;
  double best = -1;
  for(const auto& e : truth.creases()) {
    if(e.angle < 45)
      continue;
    const Point_3 m = CGAL::midpoint(e.a, e.b);
    double nearest = truth.diagonal();
    for(const Point_3& j : truth.crease_junctions())
      nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(m, j)));
    if(nearest <= best)
      continue;
    best = nearest;
    const Vector_3 along = sfe_meshing::True_surface<K>::unit(e.b - e.a);
    const Vector_3 out = sfe_meshing::True_surface<K>::unit(e.normals[0] + e.normals[1]);
    const Vector_3 direction = -out - 0.35 * along;
    camera.center = {{m.x(), m.y(), m.z()}};
    camera.direction = {{direction.x(), direction.y(), direction.z()}};
    camera.up = {{along.x(), along.y(), along.z()}};
  }
  camera.half_width = 0.05 * truth.diagonal();
  return camera;
}

void write_png(const std::string& path, const std::vector<Point_3>& points,
               const std::vector<sfe_meshing::Triangle_indices>& triangles,
               const sfe_meshing::Orthographic_camera& camera, int width)
{
  sfe_utilities::Png_image image(width, width * 3 / 4);
  sfe_meshing::render_triangles(points, triangles, camera, image);
  if(!image.write(path))
    fail("cannot write " + path);
}

/// chains the true crease edges into curves: through vertices with two crease edges, breaking
/// at the others; the normal pairs are ordered consistently along each curve.
void write_true_curves(const std::string& path, const sfe_meshing::True_surface<K>& truth)
{
  typedef sfe_meshing::True_surface<K>::Crease_edge Edge;
  const std::vector<Edge>& edges = truth.creases();
  std::map<Point_3, std::vector<std::size_t>> incident;
  for(std::size_t i = 0; i < edges.size(); ++i) {
    incident[edges[i].a].push_back(i);
    incident[edges[i].b].push_back(i);
  }
  std::vector<bool> used(edges.size(), false);
  std::ofstream out(path);
  out.precision(17);
  auto walk = [&](std::size_t first, const Point_3& start) {
    std::vector<Point_3> pts{start};
    std::vector<std::array<Vector_3, 2>> normals;
    std::size_t e = first;
    Point_3 at = start;
    std::array<Vector_3, 2> previous = edges[e].normals;
    normals.push_back(previous);
    while(true) {
      used[e] = true;
      std::array<Vector_3, 2> n = edges[e].normals;
      if(n[0] * previous[0] + n[1] * previous[1] < n[1] * previous[0] + n[0] * previous[1])
        std::swap(n[0], n[1]);
      normals.back() = n; // the vertex we came from takes this edge's pair (exact for planar faces)
      at = (edges[e].a == at) ? edges[e].b : edges[e].a;
      pts.push_back(at);
      normals.push_back(n);
      previous = n;
      const std::vector<std::size_t>& next = incident[at];
      if(next.size() != 2 || at == start)
        break;
      e = (next[0] == e) ? next[1] : next[0];
      if(used[e])
        break;
    }
    out << pts.size();
    for(std::size_t i = 0; i < pts.size(); ++i)
      out << ' ' << pts[i] << ' ' << normals[i][0] << ' ' << normals[i][1];
    out << '\n';
  };
  for(const auto& v : incident)
    if(v.second.size() != 2)
      for(std::size_t e : v.second)
        if(!used[e])
          walk(e, v.first);
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(!used[e])
      walk(e, edges[e].a); // closed loops
  if(!out)
    fail("cannot write " + path);
}

} // namespace

int main(int argc, char* argv[])
{
  std::string truth_path, mesh_path, render_prefix, sample_path, curves_path;
  sfe_meshing::Measurement_options options;
  std::size_t points_count = 100000;
  double noise = 0;
  unsigned seed = 1;
  int width = 800;
  std::size_t worst = 0;
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
    } else if(arg == "--truth") truth_path = value();
    else if(arg == "--mesh") mesh_path = value();
    else if(arg == "--render") render_prefix = value();
    else if(arg == "--sample-to") sample_path = value();
    else if(arg == "--true-curves-to") curves_path = value();
    else if(arg == "--crease-angle") options.crease_angle = parse_number(arg, value());
    else if(arg == "--band") options.band = parse_number(arg, value());
    else if(arg == "--offset") options.dihedral_offset = parse_number(arg, value());
    else if(arg == "--samples") options.samples = static_cast<std::size_t>(parse_number(arg, value()));
    else if(arg == "--points") points_count = static_cast<std::size_t>(parse_number(arg, value()));
    else if(arg == "--noise") noise = parse_number(arg, value());
    else if(arg == "--seed") seed = static_cast<unsigned>(parse_number(arg, value()));
    else if(arg == "--width") width = static_cast<int>(parse_number(arg, value()));
    else if(arg == "--worst") worst = static_cast<std::size_t>(parse_number(arg, value()));
    else fail("unknown argument " + arg + " (see --help)");
  }
  if(truth_path.empty())
    fail("--truth is required (see --help)");
  if(mesh_path.empty() && render_prefix.empty() && sample_path.empty() && curves_path.empty())
    fail("nothing to do: give --mesh, --render, --sample-to or --true-curves-to (see --help)");
  if(width < 16 || width > 8000)
    fail("--width must be between 16 and 8000");
  if(options.samples == 0)
    fail("--samples must be positive");

  std::vector<Point_3> truth_points;
  std::vector<sfe_meshing::Triangle_indices> truth_triangles;
  read_mesh(truth_path, truth_points, truth_triangles);
  sfe_meshing::True_surface<K> truth(truth_points, truth_triangles, options.crease_angle);

  if(!sample_path.empty()) {
    sfe_utilities::Triangle_soup soup;
    for(const Point_3& p : truth_points)
      soup.vertices.push_back({{p.x(), p.y(), p.z()}});
    soup.triangles = truth_triangles;
    sfe_utilities::Sampling_options sampling;
    sampling.number_of_points = points_count;
    sampling.noise = noise;
    sampling.seed = seed;
    try {
      sfe_utilities::write_xyz(sample_path, sfe_utilities::sample_triangle_soup(soup, sampling));
    } catch(const std::exception& e) {
      fail(e.what());
    }
  }
  if(!curves_path.empty())
    write_true_curves(curves_path, truth);

  std::vector<Point_3> points = truth_points;
  std::vector<sfe_meshing::Triangle_indices> triangles = truth_triangles;
  if(!mesh_path.empty()) {
    points.clear();
    triangles.clear();
    read_mesh(mesh_path, points, triangles);
    const sfe_meshing::Surface_check check = sfe_meshing::check_triangle_soup(points, triangles);
    const sfe_meshing::Mesh_quality q = sfe_meshing::measure_against_truth(points, triangles, truth, options);
    std::cout << "triangles=" << q.triangles << "\nclosed=" << check.closed() << "\nmanifold=" << check.manifold()
              << "\nself_intersecting=" << check.self_intersecting() << "\nmean_distance=" << q.mean_distance
              << "\nmax_distance=" << q.max_distance << "\nband_mean_distance=" << q.band_mean_distance
              << "\nband_max_distance=" << q.band_max_distance << "\nband_normal_angle=" << q.band_mean_normal_angle
              << "\nband_fraction=" << q.band_fraction << "\ncrease_true_angle=" << q.crease_true_angle
              << "\ncrease_reached_angle=" << q.crease_reached_angle
              << "\ncrease_angle_error=" << q.crease_angle_error << "\ncrease_within_10=" << q.crease_within_10
              << "\ncrease_samples=" << q.crease_samples << "\ntrue_creases=" << truth.creases().size() << "\n";
    if(worst > 0) {
      std::vector<std::pair<double, std::size_t>> d;
      for(std::size_t v = 0; v < points.size(); ++v)
        d.push_back(std::make_pair(std::sqrt(truth.tree().squared_distance(points[v])) / truth.diagonal(), v));
      std::sort(d.rbegin(), d.rend());
      for(std::size_t i = 0; i < (std::min)(worst, d.size()); ++i)
        std::cout << "worst=" << points[d[i].second] << " " << d[i].first << "\n";
    }
  }
  if(!render_prefix.empty()) {
    write_png(render_prefix + "_full.png", points, triangles, full_view(truth_points), width);
    write_png(render_prefix + "_closeup.png", points, triangles, close_up_view(truth), width);
  }
  return EXIT_SUCCESS;
}
