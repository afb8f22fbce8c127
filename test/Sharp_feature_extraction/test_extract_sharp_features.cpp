// The default call of extract_sharp_features() on analytic shapes whose creases are known
// exactly, sampled uniformly (fixed seed) without noise and with uniform noise of 0.5% and 1% of
// the bounding-box diagonal dB. Every tolerance is relative to dB. On exact data the bounds are
// those of a correct implementation (the creases are intersections of exact planes, or of a plane
// and a cylinder or sphere); on noisy data they state what the library does today, so that any
// change shows (see `Expected`).

#include "analytic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>

#include <catch2/catch.hpp>

#include <iostream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
using namespace sfe_test;

/// Noise radii of the noisy runs, relative to dB (uniform in a ball).
constexpr double noisy = 0.005;
constexpr double very_noisy = 0.01;
/// Outliers added to the cloud, as a fraction of its points (the benchmark's heavier setting).
constexpr double outliers = 0.05;

/// Number of sample points of each shape (about the same density on every shape).
constexpr std::size_t number_of_points = 30000;
/// Coverage is measured at crease points this far apart (relative to dB).
constexpr double coverage_step = 0.001;
/// Curve normals are unit vectors up to rounding.
constexpr double normal_length_tolerance = 1e-6;

/// What one run gives: counts, and bounds on the errors (distances relative to dB, angles in
/// degrees). On exact data the bounds are those of a correct extraction (the creases are
/// intersections of exact planes, or of a plane and a cylinder or sphere): vertices within
/// 0.15% dB (the Laplacian passes move curved creases by about 0.1% dB), corners within 0.1%
/// dB. On noisy data they state what the library does today, measured on these fixed samples
/// with a margin; the targets it does not meet yet are in the benchmark (REPORT.md).
struct Expected
{
  std::size_t min_polylines, max_polylines;
  std::size_t min_closed, max_closed;
  std::size_t min_corners, max_corners;
  /// True creases followed by exactly one curve, and curves sharing a crease with another.
  std::size_t min_creases_with_one_curve, max_curves_on_shared_crease;
  double max_vertex_distance, mean_vertex_distance, min_coverage;
  /// Between true and found corners, both ways (only when the shape has corners).
  double max_corner_error;
  double max_normal_error;
};

/// The bounds of a correct extraction on exact data, for a shape with `creases` creases (of
/// which `closed` are loops) and `corners` corners.
Expected exact(std::size_t creases, std::size_t closed, std::size_t corners)
{
  return Expected{creases, creases, closed, closed, corners, corners, creases, 0, 0.0015, 0.0012, 0.95, 0.001, 2};
}

struct Extraction
{
  Shape shape;
  double noise;
  CGAL::Sharp_features<K> result;
  Network_errors errors;
  double diagonal;
};

Extraction extract(const Shape& shape, double noise, double vertex_tolerance, std::size_t n = number_of_points,
                   double outlier_fraction = 0)
{
  Extraction x{shape, noise, {}, {}, shape.bbox_diagonal()};
  const std::vector<K::Point_3> points =
    to_points<K::Point_3>(with_outliers(sample(shape, n, noise), shape, outlier_fraction));
  REQUIRE(CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, x.result));
  x.errors = measure(shape, x.result.network, vertex_tolerance * x.diagonal, coverage_step * x.diagonal);
  std::cout << x.errors.summary(shape.name + " at noise " + std::to_string(noise * 100) + "% dB", x.diagonal)
            << " [spacing " << 100 * x.result.network.scales.spacing / x.diagonal << "% dB, time "
            << x.result.timings.total() << " s]" << std::endl;
  return x;
}

/// Extracts the features of `shape` at `noise` and checks them against `expected`, with the
/// checks every run shares: finite results, the Mesh_3 contract, unit normals that do not flip
/// between consecutive vertices.
Extraction check(const Shape& shape, double noise, const Expected& expected, std::size_t n = number_of_points,
                 double outlier_fraction = 0)
{
  const Extraction x = extract(shape, noise, expected.max_vertex_distance, n, outlier_fraction);
  const Network_errors& e = x.errors;
  const double dB = x.diagonal;
  INFO(e.summary(x.shape.name + " at noise " + std::to_string(noise * 100) + "% dB", dB));
  CHECK(result_is_finite(x.result));
  CHECK(mesh_3_contract_violation(x.result.network) == "");
  CHECK(e.polylines >= expected.min_polylines);
  CHECK(e.polylines <= expected.max_polylines);
  CHECK(e.closed_polylines >= expected.min_closed);
  CHECK(e.closed_polylines <= expected.max_closed);
  CHECK(e.corners >= expected.min_corners);
  CHECK(e.corners <= expected.max_corners);
  CHECK(e.creases_with_one_curve >= expected.min_creases_with_one_curve);
  CHECK(e.curves_on_shared_crease <= expected.max_curves_on_shared_crease);
  CHECK(e.max_vertex_distance <= expected.max_vertex_distance * dB);
  CHECK(e.mean_vertex_distance <= expected.mean_vertex_distance * dB);
  CHECK(e.coverage >= expected.min_coverage);
  if(!x.shape.corners.empty() && e.corners > 0)
  {
    CHECK(e.max_true_corner_error <= expected.max_corner_error * dB);
    CHECK(e.max_found_corner_error <= expected.max_corner_error * dB);
  }
  CHECK(e.max_normal_error <= expected.max_normal_error);
  CHECK(e.max_normal_length_error <= normal_length_tolerance);
  CHECK(e.min_consecutive_normal_dot > 0);
  return x;
}

/// Every corner joins `valence` curves.
void check_corner_valences(const Extraction& x, std::size_t valence)
{
  for(const auto& corner : x.result.network.corners)
    CHECK(corner.incident_polylines.size() == valence);
}

/// `n` points of `shape`, a smooth surface, with `noise`: no curve, no corner.
void check_no_curve(const Shape& shape, double noise, std::size_t n)
{
  const Extraction x = extract(shape, noise, 0, n);
  CHECK(result_is_finite(x.result));
  CHECK(x.result.network.polylines.empty());
  CHECK(x.result.network.corners.empty());
}

} // namespace

// Exact shapes: the result of a correct extraction.

TEST_CASE("an exact unit cube yields 12 polylines within 0.15% dB of the true edges and 8 corners of valence 3",
          "[shapes][cube]")
{
  check_corner_valences(check(unit_cube(), 0, exact(12, 0, 8)), 3);
}

TEST_CASE("an exact box with a 45-degree chamfer yields 15 polylines and 10 corners of valence 3",
          "[shapes][chamfer]")
{
  check_corner_valences(check(chamfered_box(), 0, exact(15, 0, 10)), 3);
}

TEST_CASE("an exact box with a step yields 18 polylines, the concave one included, and 12 corners",
          "[shapes][step]")
{
  check_corner_valences(check(stepped_box(), 0, exact(18, 0, 12)), 3);
}

TEST_CASE("an exact capped cylinder yields 2 closed loops within 0.15% dB of the rims and no corner",
          "[shapes][cylinder]")
{
  check(capped_cylinder(), 0, exact(2, 2, 0));
}

TEST_CASE("two exact planes meeting at 90 degrees yield one open polyline on their common edge", "[shapes][planes]")
{
  check(two_planes(90), 0, exact(1, 0, 0), number_of_points * 2 / 3);
}

TEST_CASE("two exact planes whose normals are 30 degrees apart yield one open polyline", "[shapes][planes]")
{
  check(two_planes(30), 0, exact(1, 0, 0), number_of_points * 2 / 3);
}

TEST_CASE("two exact planes forming a 30-degree wedge yield one open polyline on its edge", "[shapes][planes]")
{
  check(two_planes(150), 0, exact(1, 0, 0), number_of_points * 2 / 3);
}

TEST_CASE("an exact sphere cut by a plane at 30, 35, 40 and 50 degrees yields one closed loop on the rim",
          "[shapes][shallow]")
{
  for(double degrees : {30., 35., 40., 50.})
  {
    INFO("crease of " << degrees << " degrees");
    check(truncated_sphere(degrees), 0, exact(1, 1, 0));
  }
}

TEST_CASE("exact shapes with 5% outliers uniform in their bounding box: the 30-degree crease and the stepped "
          "box's 18 creases and 12 corners are found",
          "[shapes][outliers]")
{
  // The candidate threshold is the mean residual over the fits that a surface can explain: with
  // the outliers' own residuals in the mean, the 30-degree crease fell below it (no curve).
  check(two_planes(30), 0, exact(1, 0, 0), number_of_points * 2 / 3, outliers);
  // Exact geometry, but the normals of a few vertices next to outliers tilt by up to 8 degrees.
  Expected step = exact(18, 0, 12);
  step.max_normal_error = 10;
  check_corner_valences(check(stepped_box(), 0, step, number_of_points, outliers), 3);
}

TEST_CASE("an exact sphere yields no curve and no corner", "[shapes][sphere]")
{
  check_no_curve(sphere(), 0, number_of_points * 2 / 3);
}

// Noisy shapes: what the library does today on these samples (see `Expected`).

TEST_CASE("a sphere with 0.5% noise yields no curve and no corner", "[shapes][sphere][noise]")
{
  check_no_curve(sphere(), noisy, number_of_points * 2 / 3);
}

TEST_CASE("an open cylinder of radius 6% dB with 0.5% noise yields no curve and no corner", "[shapes][cylinder][noise]")
{
  // Over a stage-2 neighbourhood two planes fit the cylinder about as well as a quadric: the
  // split of a plane across a crease made 11 curves on this sample until the twice wider split
  // had to confirm it.
  check_no_curve(open_cylinder(0.06), noisy, number_of_points);
}

// Expected{curves min, max; closed min, max; corners min, max; creases with one curve,
//          curves on a shared crease; vertex distance max, mean; coverage; corner error; normal error}

TEST_CASE("a unit cube yields its 12 creases and 8 corners at 0.5% and at 1% noise", "[shapes][cube][noise]")
{
  check(unit_cube(), noisy, Expected{12, 12, 0, 0, 8, 8, 12, 0, 0.012, 0.0017, 0.97, 0.006, 35});
  check(unit_cube(), very_noisy, Expected{12, 12, 0, 0, 8, 8, 12, 0, 0.009, 0.0033, 0.97, 0.008, 30});
}

TEST_CASE("a chamfered box yields 13 polylines (13 of its 15 creases as one curve) at 0.5% noise, 12 at 1%",
          "[shapes][chamfer][noise]")
{
  // Corners of the chamfer are missed: the nearest found corner is 41% (0.5%) and 15% (1%)
  // dB away. At 1% noise three of the chamfer's six short 45-degree creases are lost (all six
  // before the split off one plane took the points beyond its tolerance, 9 polylines).
  check(chamfered_box(), noisy, Expected{13, 13, 0, 0, 8, 8, 13, 2, 0.021, 0.0018, 0.9, 0.45, 90});
  check(chamfered_box(), very_noisy, Expected{12, 12, 0, 0, 8, 8, 12, 0, 0.009, 0.003, 0.9, 0.2, 90});
}

TEST_CASE("a stepped box yields its 18 creases and 12 corners at 0.5% and at 1% noise", "[shapes][step][noise]")
{
  check(stepped_box(), noisy, Expected{18, 18, 0, 0, 12, 12, 18, 0, 0.007, 0.0017, 0.95, 0.005, 35});
  // At 1% the vertical crease above the concave corner runs past it (the line of its two faces
  // goes on below): completion cuts it back to the corner (the overshoot was 2.56% dB).
  check(stepped_box(), very_noisy, Expected{18, 18, 0, 0, 12, 12, 18, 0, 0.013, 0.0035, 0.95, 0.015, 30});
}

TEST_CASE("a capped cylinder yields its 2 rims as loops at 0.5% and at 1% noise", "[shapes][cylinder][noise]")
{
  check(capped_cylinder(), noisy, Expected{2, 2, 2, 2, 0, 0, 2, 0, 0.011, 0.0018, 0.95, 0, 28});
  check(capped_cylinder(), very_noisy, Expected{2, 2, 2, 2, 0, 0, 2, 0, 0.008, 0.003, 0.9, 0, 22});
}

TEST_CASE("two planes with 0.5% noise: one polyline at 90 degrees, one along 80% of the crease at 30, none on the "
          "30-degree wedge",
          "[shapes][planes][noise]")
{
  const std::size_t n = number_of_points * 2 / 3;
  check(two_planes(90), noisy, Expected{1, 1, 0, 0, 0, 0, 1, 0, 0.0045, 0.002, 0.97, 0, 15}, n);
  // 19% of the 30-degree crease before its split took the points beyond the tolerance.
  check(two_planes(30), noisy, Expected{1, 1, 0, 0, 0, 0, 1, 0, 0.005, 0.002, 0.75, 0, 12}, n);
  check(two_planes(150), noisy, Expected{0, 0, 0, 0, 0, 0, 0, 0, 0.005, 0.002, 0, 0, 90}, n);
}

TEST_CASE("a sphere cut by a plane, with 0.5% noise: the 40- and 50-degree rims are loops, the 35-degree rim one "
          "open curve, the 30-degree rim a third covered",
          "[shapes][shallow][noise]")
{
  // Before the split off one plane took the points beyond its tolerance: no curve at 30
  // degrees, 55% at 35, and one open curve at 40. At 35 degrees the rim is one open piece,
  // without a corner: the spike where it turned sharply and back (an edge point from the noise
  // beside the rim) is dropped instead of splitting it there.
  check(truncated_sphere(30), noisy, Expected{1, 3, 0, 0, 0, 0, 0, 3, 0.014, 0.0035, 0.3, 0, 15});
  check(truncated_sphere(35), noisy, Expected{1, 1, 0, 0, 0, 0, 1, 0, 0.012, 0.003, 0.7, 0, 20});
  check(truncated_sphere(40), noisy, Expected{1, 1, 1, 1, 0, 0, 1, 0, 0.012, 0.003, 0.97, 0, 20});
  check(truncated_sphere(50), noisy, Expected{1, 1, 1, 1, 0, 0, 1, 0, 0.008, 0.002, 0.97, 0, 20});
}
