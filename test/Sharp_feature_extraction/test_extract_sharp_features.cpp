// The default call of extract_sharp_features() on analytic shapes whose creases are known
// exactly, sampled uniformly (fixed seed) without noise and with uniform noise of 0.5% of the
// bounding-box diagonal dB. Every tolerance is relative to dB and chosen from what a correct
// implementation achieves: the creases are intersections of exact planes (or a plane and a
// cylinder), so at noise 0 the curves lie on them up to the fit precision, and with noise the
// fits average it out over their neighbourhoods.

#include "analytic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>

#include <catch2/catch.hpp>

#include <iostream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
using namespace sfe_test;

/// Noise radius of the noisy runs, relative to dB (the 0.5%).
constexpr double noisy = 0.005;

/// Curve vertices lie within this distance (relative to dB) of a true crease. At noise 0 the
/// only expected error is the shrinkage of curved creases by the final Laplacian passes (about
/// 0.1% dB on the cylinder); with noise, fits over 36+ points average the 0.5% dB noise down.
constexpr double vertex_tolerance_exact = 0.0015;
constexpr double vertex_tolerance_noisy = 0.005;
/// Mean vertex distance (relative to dB).
constexpr double mean_vertex_tolerance_exact = 0.0012;
constexpr double mean_vertex_tolerance_noisy = 0.002;
/// Share of the true crease length within the vertex tolerance of a curve.
constexpr double minimum_coverage = 0.95;
/// Coverage is measured at crease points this far apart (relative to dB).
constexpr double coverage_step = 0.001;
/// Found corners lie within this distance (relative to dB) of the true corner: at noise 0 a
/// corner is the intersection of three exact planes.
constexpr double corner_tolerance_exact = 0.001;
constexpr double corner_tolerance_noisy = 0.01;
/// Curve normals are within this angle (degrees) of the true face normals, up to sign and order.
constexpr double normal_tolerance_exact = 2;
constexpr double normal_tolerance_noisy = 8;
/// Curve normals are unit vectors up to rounding.
constexpr double normal_length_tolerance = 1e-6;
/// Number of sample points of each shape (about the same density on every shape).
constexpr std::size_t number_of_points = 30000;

struct Extraction
{
  Shape shape;
  double noise;
  CGAL::Sharp_features<K> result;
  Network_errors errors;
  double diagonal;
};

Extraction extract(const Shape& shape, double noise, std::size_t n = number_of_points)
{
  Extraction x{shape, noise, {}, {}, shape.bbox_diagonal()};
  const std::vector<K::Point_3> points = to_points<K::Point_3>(sample(shape, n, noise));
  REQUIRE(CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, x.result));
  const double tolerance = (noise > 0 ? vertex_tolerance_noisy : vertex_tolerance_exact) * x.diagonal;
  x.errors = measure(shape, x.result.network, tolerance, coverage_step * x.diagonal);
  std::cout << x.errors.summary(shape.name + " at noise " + std::to_string(noise * 100) + "% dB", x.diagonal)
            << " [spacing " << 100 * x.result.network.scales.spacing / x.diagonal << "% dB, time "
            << x.result.timings.total() << " s]" << std::endl;
  return x;
}

/// The checks every shape shares: accuracy of vertices, coverage, corners, normals, NaN, and the
/// Mesh_3 contract.
void check_geometry(const Extraction& x)
{
  const bool exact = x.noise == 0;
  const Network_errors& e = x.errors;
  INFO(e.summary(x.shape.name, x.diagonal));
  CHECK(result_is_finite(x.result));
  CHECK(mesh_3_contract_violation(x.result.network) == "");
  CHECK(e.max_vertex_distance <= (exact ? vertex_tolerance_exact : vertex_tolerance_noisy) * x.diagonal);
  CHECK(e.mean_vertex_distance <= (exact ? mean_vertex_tolerance_exact : mean_vertex_tolerance_noisy) * x.diagonal);
  CHECK(e.coverage >= minimum_coverage);
  if(!x.shape.corners.empty())
  {
    CHECK(e.max_true_corner_error <= (exact ? corner_tolerance_exact : corner_tolerance_noisy) * x.diagonal);
    CHECK(e.max_found_corner_error <= (exact ? corner_tolerance_exact : corner_tolerance_noisy) * x.diagonal);
  }
  CHECK(e.max_normal_error <= (exact ? normal_tolerance_exact : normal_tolerance_noisy));
  CHECK(e.max_normal_length_error <= normal_length_tolerance);
  CHECK(e.min_consecutive_normal_dot > 0);
  // One true crease, one curve.
  CHECK(e.creases_with_one_curve == x.shape.creases.size());
  CHECK(e.curves_on_shared_crease == 0);
}

void check_corner_valences(const Extraction& x, std::size_t valence)
{
  for(const auto& corner : x.result.network.corners)
    CHECK(corner.incident_polylines.size() == valence);
}

void check_cube(double noise)
{
  const Extraction x = extract(unit_cube(), noise);
  CHECK(x.errors.polylines == 12);
  CHECK(x.errors.corners == 8);
  CHECK(x.errors.closed_polylines == 0);
  check_corner_valences(x, 3);
  check_geometry(x);
}

void check_chamfered_box(double noise)
{
  const Extraction x = extract(chamfered_box(), noise);
  CHECK(x.errors.polylines == 15);
  CHECK(x.errors.corners == 10);
  check_corner_valences(x, 3);
  check_geometry(x);
}

void check_stepped_box(double noise)
{
  const Extraction x = extract(stepped_box(), noise);
  CHECK(x.errors.polylines == 18);
  CHECK(x.errors.corners == 12);
  check_corner_valences(x, 3);
  check_geometry(x);
}

void check_cylinder(double noise)
{
  const Extraction x = extract(capped_cylinder(), noise);
  CHECK(x.errors.polylines == 2);
  CHECK(x.errors.closed_polylines == 2);
  CHECK(x.errors.corners == 0);
  check_geometry(x);
}

void check_two_planes(double bend_degrees, double noise)
{
  const Extraction x = extract(two_planes(bend_degrees), noise, number_of_points * 2 / 3);
  CHECK(x.errors.polylines == 1);
  CHECK(x.errors.closed_polylines == 0);
  CHECK(x.errors.corners == 0);
  check_geometry(x);
}

void check_sphere(double noise)
{
  const Extraction x = extract(sphere(), noise, number_of_points * 2 / 3);
  CHECK(result_is_finite(x.result));
  CHECK(x.result.network.polylines.empty());
  CHECK(x.result.network.corners.empty());
}

} // namespace

// Tests tagged [!mayfail] fail because of library defects diagnosed in the test report
// (listed in the closing note of issue 2); they stay here, unweakened, so that a fix shows.

TEST_CASE("an exact unit cube yields 12 polylines within 0.15% dB of the true edges and 8 corners of valence 3",
          "[shapes][cube]")
{
  check_cube(0);
}

TEST_CASE("a unit cube with 0.5% noise yields 12 polylines within 0.5% dB of the true edges and 8 corners",
          "[shapes][cube][noise][!mayfail]")
{
  check_cube(noisy);
}

TEST_CASE("an exact box with a 45-degree chamfer yields 15 polylines and 10 corners of valence 3",
          "[shapes][chamfer]")
{
  check_chamfered_box(0);
}

TEST_CASE("a box with a 45-degree chamfer and 0.5% noise yields 15 polylines and 10 corners",
          "[shapes][chamfer][noise][!mayfail]")
{
  check_chamfered_box(noisy);
}

TEST_CASE("an exact box with a step yields 18 polylines, the concave one included, and 12 corners",
          "[shapes][step]")
{
  check_stepped_box(0);
}

TEST_CASE("a box with a step and 0.5% noise yields 18 polylines and 12 corners", "[shapes][step][noise][!mayfail]")
{
  check_stepped_box(noisy);
}

TEST_CASE("an exact capped cylinder yields 2 closed loops within 0.15% dB of the rims and no corner",
          "[shapes][cylinder]")
{
  check_cylinder(0);
}

TEST_CASE("a capped cylinder with 0.5% noise yields 2 closed loops within 0.5% dB of the rims and no corner",
          "[shapes][cylinder][noise][!mayfail]")
{
  check_cylinder(noisy);
}

TEST_CASE("two exact planes meeting at 90 degrees yield one open polyline on their common edge", "[shapes][planes]")
{
  check_two_planes(90, 0);
}

TEST_CASE("two planes meeting at 90 degrees with 0.5% noise yield one open polyline", "[shapes][planes][noise][!mayfail]")
{
  check_two_planes(90, noisy);
}

TEST_CASE("two exact planes whose normals are 30 degrees apart yield one open polyline", "[shapes][planes]")
{
  check_two_planes(30, 0);
}

TEST_CASE("two planes whose normals are 30 degrees apart, with 0.5% noise, yield one open polyline",
          "[shapes][planes][noise][!mayfail]")
{
  check_two_planes(30, noisy);
}

TEST_CASE("two exact planes forming a 30-degree wedge yield one open polyline on its edge",
          "[shapes][planes]")
{
  check_two_planes(150, 0);
}

TEST_CASE("two planes forming a 30-degree wedge, with 0.5% noise, yield one open polyline",
          "[shapes][planes][noise][!mayfail]")
{
  check_two_planes(150, noisy);
}

TEST_CASE("an exact sphere yields no curve and no corner", "[shapes][sphere]")
{
  check_sphere(0);
}

TEST_CASE("a sphere with 0.5% noise yields no curve and no corner", "[shapes][sphere][noise]")
{
  check_sphere(noisy);
}
