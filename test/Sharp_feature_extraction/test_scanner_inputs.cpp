// Clouds as range scanners produce them, from the scan simulation that the benchmark also uses
// (benchmark/Sharp_feature_extraction/scan_simulation.h): rays from a few viewpoints against
// analytic shapes whose creases are known exactly, with occlusion, grazing returns lost, and
// the defects of real files: georeferenced coordinates, scan lines (dense along a line, sparse
// across), two overlapping scans misregistered by 0.1% dB, rays without return written as
// (0,0,0), exact duplicates, and a cloud that is one plane. Each test states what the default
// call of extract_sharp_features() gives on it; the full-size versions are benchmark rows
// (scripts/bench.sh, REPORT.md "Scanner-like inputs").

#include "analytic_shapes.h"
#include "../../benchmark/Sharp_feature_extraction/scan_simulation.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
using namespace sfe_test;

/// Returns of each scan, over all views: about the density of the other shape tests.
constexpr std::size_t number_of_returns = 30000;
/// Range noise of the noisy scans (half-width along the ray, relative to dB): the 0.5% dB of
/// the other noisy tests.
constexpr double range_noise = 0.005;
/// Without range noise a scan samples the exact planes of the shape, so curve vertices lie on
/// the creases up to the precision of the fits (relative to dB; measured: below 0.01%).
constexpr double vertex_tolerance_exact = 0.001;
/// With range noise, fits over the neighbourhoods average it out (measured: 0.27% on the cube).
constexpr double vertex_tolerance_noisy = 0.005;
/// Share of the true crease length within the vertex tolerance of a curve.
constexpr double minimum_coverage_exact = 0.99;
constexpr double minimum_coverage_noisy = 0.95;
/// Found corners lie within this distance of a true corner (relative to dB): at noise 0 a
/// corner is the intersection of three exact planes.
constexpr double corner_tolerance_exact = 0.001;
/// Coverage is measured at crease points this far apart (relative to dB).
constexpr double coverage_step = 0.001;

/// `shape` moved by `t`: its triangles, creases, corners and box.
Shape translated(Shape shape, const Vec& t)
{
  for(Shape::Triangle& tr : shape.triangles)
    tr = {tr.a + t, tr.b + t, tr.c + t};
  for(Crease& c : shape.creases)
  {
    c.a = c.a + t;
    c.b = c.b + t;
    c.center = c.center + t;
  }
  for(Vec& c : shape.corners)
    c = c + t;
  shape.bbox_min = shape.bbox_min + t;
  shape.bbox_max = shape.bbox_max + t;
  return shape;
}

sfe_scan::Mesh mesh_of(const Shape& shape)
{
  sfe_scan::Mesh mesh;
  for(const Shape::Triangle& t : shape.triangles)
  {
    const std::size_t first = mesh.vertices.size();
    for(const Vec& v : {t.a, t.b, t.c})
      mesh.vertices.push_back({{v.x, v.y, v.z}});
    mesh.triangles.push_back({{first, first + 1, first + 2}});
  }
  return mesh;
}

/// The scan every test starts from: 4 viewpoints, an even ray grid, no range noise.
sfe_scan::Scan_options scan_options(std::size_t returns = number_of_returns)
{
  sfe_scan::Scan_options options;
  options.returns = returns;
  return options;
}

std::vector<K::Point_3> to_kernel_points(const std::vector<sfe_scan::Xyz>& xyz)
{
  std::vector<K::Point_3> points;
  points.reserve(xyz.size());
  for(const sfe_scan::Xyz& p : xyz)
    points.emplace_back(p[0], p[1], p[2]);
  return points;
}

std::vector<K::Point_3> scan(const Shape& shape, const sfe_scan::Scan_options& options)
{
  return to_kernel_points(sfe_scan::scan_mesh(mesh_of(shape), options).points);
}

struct Extraction
{
  CGAL::Sharp_features<K> result;
  Network_errors errors;
  double diagonal = 0;
  std::string label;
};

/// The default call on `points`, measured against the creases of `truth` (coverage within
/// `vertex_tolerance`, relative to dB).
Extraction extract(const std::vector<K::Point_3>& points, const Shape& truth, double vertex_tolerance,
                   const std::string& label)
{
  Extraction x;
  x.diagonal = truth.bbox_diagonal();
  x.label = label + " (" + std::to_string(points.size()) + " points)";
  REQUIRE(CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, x.result));
  x.errors = measure(truth, x.result.network, vertex_tolerance * x.diagonal, coverage_step * x.diagonal);
  std::cout << x.errors.summary(x.label, x.diagonal) << " [spacing "
            << 100 * x.result.network.scales.spacing / x.diagonal << "% dB, noise "
            << 100 * x.result.network.scales.noise / x.diagonal << "% dB, time " << x.result.timings.total() << " s]"
            << std::endl;
  CHECK(result_is_finite(x.result));
  CHECK(mesh_3_contract_violation(x.result.network) == "");
  return x;
}

/// One curve per true crease, the true corners, vertices within `vertex_tolerance` (relative to
/// dB) of the creases and covering at least `minimum_coverage` of their length.
void check_all_creases(const Extraction& x, const Shape& truth, double vertex_tolerance, double minimum_coverage)
{
  const Network_errors& e = x.errors;
  INFO(e.summary(x.label, x.diagonal));
  CHECK(e.polylines == truth.creases.size());
  CHECK(e.creases_with_one_curve == truth.creases.size());
  CHECK(e.corners == truth.corners.size());
  CHECK(e.max_vertex_distance <= vertex_tolerance * x.diagonal);
  CHECK(e.coverage >= minimum_coverage);
}

void check_all_creases_exact(const Extraction& x, const Shape& truth)
{
  check_all_creases(x, truth, vertex_tolerance_exact, minimum_coverage_exact);
  CHECK(x.errors.max_true_corner_error <= corner_tolerance_exact * x.diagonal);
  CHECK(x.errors.max_found_corner_error <= corner_tolerance_exact * x.diagonal);
}

Extraction scan_and_extract_exact(const Shape& shape, const sfe_scan::Scan_options& options, const std::string& label)
{
  return extract(scan(shape, options), shape, vertex_tolerance_exact, label);
}

/// Distance from `p` to the nearest triangle of `shape`.
double distance_to_surface(const Shape& shape, const sfe_scan::Xyz& p)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 P;
  double best = std::numeric_limits<double>::infinity();
  for(const Shape::Triangle& t : shape.triangles)
  {
    const CGAL::Simple_cartesian<double>::Triangle_3 triangle(P(t.a.x, t.a.y, t.a.z), P(t.b.x, t.b.y, t.b.z),
                                                             P(t.c.x, t.c.y, t.c.z));
    best = (std::min)(best, std::sqrt(CGAL::squared_distance(P(p[0], p[1], p[2]), triangle)));
  }
  return best;
}

} // namespace

TEST_CASE("the scan simulation: returns on the surface, none on hidden faces, range noise along the ray, "
          "no return written as (0,0,0), deterministic",
          "[scanner][simulation]")
{
  const Shape cube = unit_cube();
  sfe_scan::Scan_options options = scan_options(5000);
  options.views = 1; // from (1, 1, 1): sees the faces x = 1, y = 1, z = 1 only
  const sfe_scan::Scan exact = sfe_scan::scan_mesh(mesh_of(cube), options);
  CHECK(exact.returns == exact.points.size());
  CHECK(exact.rays == exact.returns + exact.misses + exact.grazing);
  // The pilot scan sets the step: the count is within a few percent of the request.
  CHECK(std::abs(double(exact.returns) / double(options.returns) - 1) < 0.05);
  // Rounding of the ray-triangle intersection only (relative to the cube's size 1).
  constexpr double on_surface = 1e-12;
  std::size_t on_hidden_faces = 0;
  for(const sfe_scan::Xyz& p : exact.points)
  {
    CHECK(distance_to_surface(cube, p) <= on_surface);
    if((std::min)({p[0], p[1], p[2]}) < on_surface)
      ++on_hidden_faces;
  }
  CHECK(on_hidden_faces == 0);

  options.range_noise = range_noise;
  const sfe_scan::Scan noisy = sfe_scan::scan_mesh(mesh_of(cube), options);
  CHECK(noisy.returns == exact.returns);
  double largest = 0;
  for(const sfe_scan::Xyz& p : noisy.points)
    largest = (std::max)(largest, distance_to_surface(cube, p));
  CHECK(largest <= range_noise * cube.bbox_diagonal());
  CHECK(largest > 0.5 * range_noise * cube.bbox_diagonal());

  options.no_returns_as_origin = true;
  const sfe_scan::Scan with_origin = sfe_scan::scan_mesh(mesh_of(cube), options);
  CHECK(with_origin.points.size() == with_origin.rays);
  CHECK(std::size_t(std::count(with_origin.points.begin(), with_origin.points.end(), sfe_scan::Xyz{{0, 0, 0}}))
        == with_origin.misses + with_origin.grazing);
  CHECK(sfe_scan::scan_mesh(mesh_of(cube), options).points == with_origin.points);
}

TEST_CASE("a cube scanned from 4 viewpoints yields 12 polylines within 0.1% dB of its edges and 8 corners",
          "[scanner]")
{
  const Shape cube = unit_cube();
  check_all_creases_exact(scan_and_extract_exact(cube, scan_options(), "cube, 4 views"), cube);
}

TEST_CASE("boxes with a chamfer and with a concave step (occluded from some views), scanned from 4 viewpoints, "
          "yield every crease and corner",
          "[scanner]")
{
  for(const Shape& shape : {chamfered_box(), stepped_box()})
    check_all_creases_exact(scan_and_extract_exact(shape, scan_options(), shape.name + ", 4 views"), shape);
}

TEST_CASE("a cube scanned with 0.5% dB range noise yields 12 polylines within 0.5% dB of its edges and 8 corners",
          "[scanner][noise]")
{
  const Shape cube = unit_cube();
  sfe_scan::Scan_options options = scan_options();
  options.range_noise = range_noise;
  const Extraction x = extract(scan(cube, options), cube, vertex_tolerance_noisy, "cube, range noise");
  check_all_creases(x, cube, vertex_tolerance_noisy, minimum_coverage_noisy);
}

TEST_CASE("georeferenced coordinates (offsets 1e6 to 1e8) give the curves of the same scan at the origin",
          "[scanner][georeferenced]")
{
  const Shape cube = unit_cube();
  const Extraction at_origin = scan_and_extract_exact(cube, scan_options(), "cube at the origin");
  for(double offset : {1e6, 1e7, 1e8})
  {
    sfe_scan::Scan_options options = scan_options();
    options.offset = {{offset, offset, offset}};
    const Shape moved = translated(cube, Vec(offset, offset, offset));
    const Extraction x = extract(scan(cube, options), moved, vertex_tolerance_exact, "cube at " + std::to_string(offset));
    check_all_creases_exact(x, moved);
    CHECK(x.errors.vertices == at_origin.errors.vertices);
  }
}

TEST_CASE("scan lines 4 times farther apart than the points along them give the 12 edges and 8 corners of a cube",
          "[scanner][scan lines]")
{
  // 8 times farther apart (the benchmark's row) loses corners and part of the edges.
  const Shape cube = unit_cube();
  sfe_scan::Scan_options options = scan_options();
  options.line_spacing_ratio = 4;
  check_all_creases_exact(scan_and_extract_exact(cube, options, "cube, scan lines 1:4"), cube);
}

TEST_CASE("two overlapping scans misregistered by 0.02% dB give the 12 edges and 8 corners of a cube, and by 0.1% dB "
          "the curves still cover the edges",
          "[scanner][misregistration]")
{
  const Shape cube = unit_cube();
  sfe_scan::Scan_options options = scan_options();
  // The last view's points shifted along its viewing direction: every face it sees doubled.
  // At 0.02% dB the curves are those of the cube, but a corner lies 0.34% dB from the true one
  // (the vertices of the edges within 0.02% dB on average): within the bound of noisy data.
  options.misregistration = 0.0002;
  check_all_creases(scan_and_extract_exact(cube, options, "cube, one view shifted by 0.02% dB"), cube,
                    vertex_tolerance_noisy, minimum_coverage_exact);
  // At 0.1% dB the doubled faces give spurious curves (59 instead of 12: the benchmark's row
  // keeps that target); what holds is the coverage of the true edges.
  options.misregistration = 0.001;
  const Extraction x = extract(scan(cube, options), cube, vertex_tolerance_noisy, "cube, one view shifted by 0.1% dB");
  INFO(x.errors.summary(x.label, x.diagonal));
  CHECK(x.errors.coverage >= minimum_coverage_noisy);
}

TEST_CASE("rays without return written as (0,0,0), 100k of them, leave the curves of a cube unchanged",
          "[scanner][no return]")
{
  // The cube away from the origin, as a scan in a scanner's frame (whose origin is the scanner).
  const Vec away(1.5, 0, 0);
  const Shape cube = translated(unit_cube(), away);
  sfe_scan::Scan_options options = scan_options(20000);
  options.offset = {{away.x, away.y, away.z}};
  // A ray grid twice as wide as the object, as scanners sweep: most rays find nothing.
  options.window = 2;
  const sfe_scan::Scan without = sfe_scan::scan_mesh(mesh_of(unit_cube()), options);
  options.no_returns_as_origin = true;
  const std::vector<K::Point_3> points = scan(unit_cube(), options);
  const std::size_t zeros = std::size_t(std::count(points.begin(), points.end(), K::Point_3(0, 0, 0)));
  CHECK(zeros >= 100000);
  const Extraction x = extract(points, cube, vertex_tolerance_exact, "cube, rays without return at (0,0,0)");
  check_all_creases_exact(x, cube);
  const Extraction reference = extract(to_kernel_points(without.points), cube, vertex_tolerance_exact,
                                       "cube, rays without return dropped");
  CHECK(x.errors.vertices == reference.errors.vertices);
}

TEST_CASE("1e6 exact duplicates (each point of a scan 40 more times) leave the curves of a cube unchanged",
          "[scanner][duplicates]")
{
  constexpr std::size_t copies = 40;
  const Shape cube = unit_cube();
  const std::vector<K::Point_3> once = scan(cube, scan_options(25000));
  std::vector<K::Point_3> repeated;
  repeated.reserve(once.size() * (copies + 1));
  for(const K::Point_3& p : once)
    repeated.insert(repeated.end(), copies + 1, p);
  CHECK(repeated.size() - once.size() >= 1000000);
  const Extraction x = extract(repeated, cube, vertex_tolerance_exact, "cube, every point 41 times");
  check_all_creases_exact(x, cube);
}

TEST_CASE("an all-planar cloud (a scanned square, every z exactly 0) and a plane scanned with 0.5% dB range noise "
          "from 4 viewpoints yield no curve",
          "[scanner][plane]")
{
  const Shape plane = square_plane();
  sfe_scan::Scan_options options = scan_options();
  options.views = 1;
  std::vector<K::Point_3> planar;
  for(const K::Point_3& p : scan(plane, options))
    planar.emplace_back(p.x(), p.y(), 0);
  const Extraction x = extract(planar, plane, vertex_tolerance_exact, "plane, one view, z = 0");
  CHECK(x.result.network.polylines.empty());
  CHECK(x.result.network.corners.empty());
  // With range noise from one viewpoint, these 30k returns get 2 to 9 spurious curves in the
  // part nearest the scanner (seeds 1 to 3): that target stays in the benchmark's plane_noise
  // row (100k returns, met there). From 4 viewpoints there is none.
  options.views = 4;
  options.range_noise = range_noise;
  const Extraction noisy = extract(scan(plane, options), plane, vertex_tolerance_noisy, "plane, 4 views, range noise");
  CHECK(noisy.result.network.polylines.empty());
  CHECK(noisy.result.network.corners.empty());
}
