// Degenerate and invalid input: the documented exception (std::invalid_argument for non-finite
// coordinates and out-of-range parameters) or an empty result, never a crash, a hang or a NaN.

#include "analytic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/tile_halo_width.h>

#include <catch2/catch.hpp>

#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
namespace sfe_parameters = CGAL::Sharp_feature_extraction::parameters;
using namespace sfe_test;

/// Runs the whole pipeline; the result must be free of NaN whatever it contains.
CGAL::Sharp_features<K> extract(const std::vector<Point_3>& points)
{
  CGAL::Sharp_features<K> result;
  CHECK(CGAL::extract_sharp_features<CGAL::Sequential_tag>(points, result));
  CHECK(result_is_finite(result));
  return result;
}

void check_empty(const CGAL::Sharp_features<K>& result)
{
  CHECK(result.network.polylines.empty());
  CHECK(result.network.corners.empty());
}

std::vector<Point_3> random_points(std::size_t n, std::uint64_t seed)
{
  Random random(seed);
  std::vector<Point_3> points;
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(random.uniform(), random.uniform(), random.uniform());
  return points;
}

} // namespace

TEST_CASE("an empty cloud yields an empty result", "[bad input]")
{
  const CGAL::Sharp_features<K> result = extract({});
  check_empty(result);
  CHECK(result.candidates.residuals.empty());
  CHECK(result.candidates.indices.empty());
  CHECK(result.projected.edge_points.empty());
  CHECK(result.smoothed.edge_points.empty());

  std::vector<std::vector<Point_3>> polylines;
  CHECK(CGAL::extract_sharp_features<CGAL::Sequential_tag>(std::vector<Point_3>(), std::back_inserter(polylines)));
  CHECK(polylines.empty());
}

TEST_CASE("clouds of 1 to 10 points, and of up to 19 (the documented minimum is 20), yield no curve", "[bad input]")
{
  for(std::size_t n = 1; n < 20; ++n)
  {
    INFO(n << " points");
    const CGAL::Sharp_features<K> result = extract(random_points(n, n));
    check_empty(result);
    CHECK(result.candidates.residuals.size() == n);
  }
}

TEST_CASE("small random clouds just above the minimum are processed without failure", "[bad input]")
{
  for(std::size_t n : {20, 21, 25, 36, 50, 73, 100, 200})
  {
    INFO(n << " points");
    const CGAL::Sharp_features<K> result = extract(random_points(n, 1000 + n));
    CHECK(mesh_3_contract_violation(result.network) == "");
  }
}

TEST_CASE("a NaN or infinite coordinate is rejected with std::invalid_argument", "[bad input]")
{
  const double bad_values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()};
  for(double bad : bad_values)
    for(int coordinate = 0; coordinate < 3; ++coordinate)
    {
      INFO("bad value " << bad << " in coordinate " << coordinate);
      std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), 500, 0));
      points[250] = Point_3(coordinate == 0 ? bad : 0.5, coordinate == 1 ? bad : 0.5, coordinate == 2 ? bad : 0.5);
      CGAL::Sharp_features<K> result;
      CHECK_THROWS_AS(CGAL::extract_sharp_features<CGAL::Sequential_tag>(points, result), std::invalid_argument);
      CGAL::Candidate_points<K> candidates;
      CHECK_THROWS_AS(CGAL::compute_candidate_points<CGAL::Sequential_tag>(points, candidates), std::invalid_argument);
      std::vector<std::vector<Point_3>> polylines;
      CHECK_THROWS_AS(CGAL::extract_sharp_features<CGAL::Sequential_tag>(points, std::back_inserter(polylines)),
                      std::invalid_argument);
    }
  std::vector<Point_3> one_bad_point{Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0)};
  CGAL::Sharp_features<K> result;
  CHECK_THROWS_AS(CGAL::extract_sharp_features<CGAL::Sequential_tag>(one_bad_point, result), std::invalid_argument);
}

TEST_CASE("a cloud whose points are all identical yields no curve", "[bad input]")
{
  for(std::size_t n : {20, 100, 5000})
  {
    INFO(n << " identical points");
    check_empty(extract(std::vector<Point_3>(n, Point_3(0.25, -3, 7))));
  }
}

TEST_CASE("a cloud of a few distinct positions, each repeated many times, yields no NaN", "[bad input]")
{
  // Neighbourhoods made of one repeated point have no principal plane: the fits must give up cleanly.
  std::vector<Point_3> points;
  for(int k = 0; k < 4; ++k)
    for(int i = 0; i < 300; ++i)
      points.emplace_back(k, k * k, 0);
  extract(points);
  std::vector<Point_3> mostly_identical(2000, Point_3(1, 1, 1));
  const std::vector<Point_3> few = random_points(30, 7);
  mostly_identical.insert(mostly_identical.end(), few.begin(), few.end());
  extract(mostly_identical);
}

// Range scanners write (0,0,0) for every ray without a return, and concatenated files repeat
// points: the pipeline once crashed (stack overflow in the k-d tree construction) on 50,000
// copies of one point. Exact copies now count once.
TEST_CASE("copies of points, in any number, change nothing: a cube plus 60,000 copies of one of its points, "
          "and the cube with every point doubled, give the cube's curves", "[bad input][duplicates]")
{
  const std::vector<Point_3> cube = to_points<Point_3>(sample(unit_cube(), 20000, 0));
  const CGAL::Sharp_features<K> reference = extract(cube);
  REQUIRE(reference.network.polylines.size() == 12);
  const std::size_t copies = 60000;

  std::vector<Point_3> with_copies = cube;
  with_copies.insert(with_copies.end(), copies, cube[0]);
  std::vector<Point_3> doubled = cube;
  doubled.insert(doubled.end(), cube.begin(), cube.end());
  for(const std::vector<Point_3>* cloud : {&with_copies, &doubled})
  {
    INFO(cloud->size() << " points");
    const CGAL::Sharp_features<K> result = extract(*cloud);
    REQUIRE(result.network.polylines.size() == reference.network.polylines.size());
    for(std::size_t c = 0; c < result.network.polylines.size(); ++c)
      CHECK(result.network.polylines[c].points == reference.network.polylines[c].points);
    // Every copy has its first copy's residual, and is a candidate with it.
    REQUIRE(result.candidates.residuals.size() == cloud->size());
    CHECK(result.candidates.residuals.back() == result.candidates.residuals[cloud == &doubled ? cube.size() - 1 : 0]);
  }
  const CGAL::Sharp_features<K> twice = extract(doubled);
  CHECK(twice.candidates.indices.size() == 2 * reference.candidates.indices.size());
}

TEST_CASE("a cloud of 200,000 copies of (0,0,0) yields no curve, and so does a cube of 500 points beside them",
          "[bad input][duplicates]")
{
  check_empty(extract(std::vector<Point_3>(200000, Point_3(0, 0, 0))));
  std::vector<Point_3> few = to_points<Point_3>(sample(unit_cube(), 500, 0));
  few.insert(few.end(), 200000, Point_3(0, 0, 0));
  const CGAL::Sharp_features<K> result = extract(few);
  CHECK(mesh_3_contract_violation(result.network) == "");
}

TEST_CASE("two far outliers whose distances to a cube overflow (5e303 away) leave its 12 curves as they are",
          "[bad input][outliers]")
{
  const std::vector<Point_3> cube = to_points<Point_3>(sample(unit_cube(), 6000, 0));
  const CGAL::Sharp_features<K> reference = extract(cube);
  REQUIRE(reference.network.polylines.size() == 12);
  // Finite coordinates, but the square of their distance to the cube is beyond the doubles: a
  // mean spacing over them was infinite, and so were the grid cells of stage 2 (NaN cell keys).
  const double far = -5.3e303;
  std::vector<Point_3> with_far = cube;
  with_far.insert(with_far.end(), 2, Point_3(far, far, far));
  const CGAL::Sharp_features<K> result = extract(with_far);
  CHECK(std::isfinite(result.candidates.scales.spacing));
  // The two points shift the regular subsample that measures the spacing: equal within 1%.
  CHECK(result.candidates.scales.spacing == Approx(reference.candidates.scales.spacing).epsilon(0.01));
  CHECK(result.network.polylines.size() == reference.network.polylines.size());
}

TEST_CASE("an exact plane has no sharp feature", "[bad input]")
{
  check_empty(extract(to_points<Point_3>(sample(square_plane(), 10000, 0))));
}

TEST_CASE("a plane with 0.5% noise has no sharp feature", "[bad input][noise]")
{
  check_empty(extract(to_points<Point_3>(sample(square_plane(), 10000, 0.005))));
}

TEST_CASE("points on a line (no surface) yield no curve", "[bad input]")
{
  std::vector<Point_3> exact, noisy;
  Random random(3);
  for(int i = 0; i < 2000; ++i)
  {
    const double t = random.uniform();
    exact.emplace_back(t, 2 * t, -t);
    const Vec n = random.in_ball(0.001);
    noisy.emplace_back(t + n.x, 2 * t + n.y, -t + n.z);
  }
  check_empty(extract(exact));
  check_empty(extract(noisy));
  // Evenly spaced points on a line: every neighbourhood is exactly collinear.
  std::vector<Point_3> regular;
  for(int i = 0; i < 500; ++i)
    regular.emplace_back(i * 0.01, 0, 0);
  check_empty(extract(regular));
}

TEST_CASE("out-of-range parameters are rejected with std::invalid_argument", "[bad input]")
{
  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), 500, 0));
  CGAL::Sharp_features<K> result;
  auto run = [&](const auto& np) { return CGAL::extract_sharp_features<CGAL::Sequential_tag>(points, result, np); };
  CHECK_THROWS_AS(run(sfe_parameters::rmls_tolerance(-1.)), std::invalid_argument);
  CHECK_THROWS_AS(run(sfe_parameters::growth_radius(std::numeric_limits<double>::quiet_NaN())), std::invalid_argument);
  CHECK_THROWS_AS(run(sfe_parameters::completion_distance(std::numeric_limits<double>::infinity())), std::invalid_argument);
  CHECK_THROWS_AS(run(sfe_parameters::corner_radius(-0.1)), std::invalid_argument);
  CHECK_THROWS_AS(run(CGAL::parameters::degree_fitting(3)), std::invalid_argument);
  CHECK_THROWS_AS(run(CGAL::parameters::sharpness_angle(0.)), std::invalid_argument);
  CHECK_THROWS_AS(run(CGAL::parameters::sharpness_angle(90.)), std::invalid_argument);
  CHECK_THROWS_AS(run(CGAL::parameters::maximum_angle(-5.)), std::invalid_argument);
}

TEST_CASE("scales given to a context, to stages 2, 4 and 5 or to the tile halo are checked", "[bad input]")
{
  typedef CGAL::Sharp_feature_scales<K::FT> Scales;
  typedef CGAL::Sharp_feature_extraction_context<K, CGAL::Sequential_tag> Context;
  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), 500, 0));
  const Scales estimated = CGAL::estimate_sharp_feature_scales<CGAL::Sequential_tag>(points);
  CHECK_NOTHROW(Context(points, estimated));
  CHECK_NOTHROW(Context(points, Scales())); // the all-zero scales of a cloud without extent
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<std::function<void(Scales&)>> breakages = {
    [&](Scales& s) { s.spacing = nan; },          [&](Scales& s) { s.noise = -1; },
    [&](Scales& s) { s.candidate_radius = inf; }, [&](Scales& s) { s.residual_threshold = nan; },
    [&](Scales& s) { s.rmls_tolerance = -inf; },  [&](Scales& s) { s.corner_radius = nan; },
    [&](Scales& s) { s.growth_radius = -0.5; },   [&](Scales& s) { s.completion_distance = inf; },
    [&](Scales& s) { s.sampled_fraction = 0; },   [&](Scales& s) { s.sampled_fraction = 1.5; },
    [&](Scales& s) { s.sampled_fraction = nan; }, [&](Scales& s) { s.search_fraction = 0; },
    [&](Scales& s) { s.search_fraction = nan; },  [&](Scales& s) { s.search_fraction = 1.5; },
    [&](Scales& s) { s.sampled_fraction = 0.5; s.search_fraction = 0.6; }};
  for(std::size_t i = 0; i < breakages.size(); ++i)
  {
    INFO("breakage " << i);
    Scales bad = estimated;
    breakages[i](bad);
    CHECK_THROWS_AS(Context(points, bad), std::invalid_argument);
    CHECK_THROWS_AS(CGAL::tile_halo_width(bad), std::invalid_argument);
  }
  // Stage 2 reads the scales that come with the candidates.
  const Context context(points);
  CGAL::Candidate_points<K> candidates;
  REQUIRE(context.compute_candidate_points(candidates));
  candidates.scales.rmls_tolerance = nan;
  CGAL::Feature_point_set<K> features;
  CHECK_THROWS_AS(context.rmls_project_candidates(candidates, features), std::invalid_argument);
  // Stages 4 and 5 read the scales that come with the feature points and the network.
  features.scales = estimated;
  features.scales.growth_radius = -1;
  CGAL::Feature_curve_network<K> network;
  CHECK_THROWS_AS(CGAL::grow_feature_polylines(features, network), std::invalid_argument);
  network.scales = estimated;
  network.scales.completion_distance = inf;
  CHECK_THROWS_AS(CGAL::complete_feature_polylines(network), std::invalid_argument);
}

TEST_CASE("stage functions accept empty input and reject candidate indices beyond the points", "[bad input]")
{
  const std::vector<Point_3> none;
  CGAL::Candidate_points<K> candidates;
  CHECK(CGAL::compute_candidate_points<CGAL::Sequential_tag>(none, candidates));
  CHECK(candidates.indices.empty());
  CGAL::Feature_point_set<K> features;
  CHECK(CGAL::rmls_project_candidates<CGAL::Sequential_tag>(none, candidates, features));
  CHECK(features.edge_points.empty());
  CHECK(CGAL::smooth_feature_points<CGAL::Sequential_tag>(features));
  CGAL::Feature_curve_network<K> network;
  CHECK(CGAL::grow_feature_polylines(features, network));
  CGAL::complete_feature_polylines(network);
  CHECK(network.polylines.empty());
  CHECK(network.corners.empty());

  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), 500, 0));
  candidates.indices = {3, 500};
  CHECK_THROWS_AS(CGAL::rmls_project_candidates<CGAL::Sequential_tag>(points, candidates, features),
                  std::invalid_argument);
}
