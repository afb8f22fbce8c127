// The searches behind the speed of stages 1 and 2 must not change what they find: the gridded
// neighbourhoods of stage 1 are exactly the k nearest points (as the k-d tree finds them), on
// clean, noisy, flat and duplicated clouds; and the candidate cells of stage 2 hold every
// candidate exactly once, within one cell of side the given size; the surfaces of a cell serve
// a candidate only where they explain its neighbourhood. The ranked neighbourhoods of stage 2
// are the k nearest points in a canonical order, and its forward search's moment sums agree
// with a direct covariance analysis.

#include "analytic_shapes.h"

#include <CGAL/Sharp_feature_extraction/internal/All_nearest_neighbors.h>
#include <CGAL/Sharp_feature_extraction/internal/rmls_projection_impl.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace sfe = CGAL::Sharp_feature_extraction::internal;
using namespace sfe_test;

std::vector<sfe::Vec3> to_vec3(const std::vector<Vec>& v)
{
  std::vector<sfe::Vec3> out;
  for(const Vec& p : v)
    out.emplace_back(p.x, p.y, p.z);
  return out;
}

/// Every neighbourhood of `for_each_neighborhood()` against the k-d tree's: same size, and
/// the same distance to the farthest member (the sets may differ only among points at exactly
/// that distance). Returns the number of points checked.
template <typename ConcurrencyTag>
std::size_t check_neighborhoods(const std::vector<sfe::Vec3>& points, std::size_t k)
{
  sfe::Point_index index;
  index.build<CGAL::Sequential_tag>(points);
  // The cell side the pipeline would use: from the median distance to the k-th neighbour.
  std::vector<double> radii;
  std::vector<std::size_t> sample;
  for(std::size_t i = 0; i < points.size(); i += 16)
  {
    index.nearest(points[i], k, sample);
    radii.push_back((points[sample.back()] - points[i]).norm());
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double cell = sfe::neighborhood_cell_per_radius * radii[radii.size() / 2];
  std::vector<std::vector<std::size_t>> found(points.size());
  sfe::Progress progress;
  REQUIRE(sfe::for_each_neighborhood<ConcurrencyTag>(points, index, k, cell, progress,
    [&](std::size_t i, const std::vector<std::size_t>& neighbors) { found[i] = neighbors; }));
  std::vector<std::size_t> expected;
  std::size_t mismatches = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    index.nearest(points[i], k, expected);
    std::vector<std::size_t> got = found[i];
    std::sort(got.begin(), got.end());
    const bool unique = std::adjacent_find(got.begin(), got.end()) == got.end();
    double farthest = 0;
    for(std::size_t j : got)
      farthest = (std::max)(farthest, (points[j] - points[i]).norm());
    const double expected_farthest = (points[expected.back()] - points[i]).norm();
    if(got.size() != expected.size() || !unique || farthest != expected_farthest)
      ++mismatches;
  }
  CHECK(mismatches == 0);
  return points.size();
}

/// Checks `nearest_ranked()` at every point of `points` in `order` (one workspace throughout,
/// as a block of stage 2 does), and at `extra` points, against the k smallest (squared
/// distance, index) pairs found by brute force. Returns the number of mismatched queries.
std::size_t ranked_mismatches(const std::vector<sfe::Vec3>& points, const std::vector<std::size_t>& order,
                              const std::vector<sfe::Vec3>& extra, std::size_t k)
{
  sfe::Point_index index;
  index.build<CGAL::Sequential_tag>(points);
  sfe::Point_index::Ranked_query query;
  std::vector<sfe::Vec3> queries;
  for(std::size_t i : order)
    queries.push_back(points[i]);
  queries.insert(queries.end(), extra.begin(), extra.end());
  std::size_t mismatches = 0;
  std::vector<std::size_t> got;
  std::vector<std::pair<double, std::size_t>> all;
  for(const sfe::Vec3& q : queries)
  {
    index.nearest_ranked(q, k, query, got);
    all.clear();
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const double dx = points[i].x() - q.x(), dy = points[i].y() - q.y(), dz = points[i].z() - q.z();
      all.emplace_back(dx * dx + dy * dy + dz * dz, i);
    }
    std::sort(all.begin(), all.end());
    std::vector<std::size_t> expected;
    for(std::size_t r = 0; r < (std::min)(k, all.size()); ++r)
      expected.push_back(all[r].second);
    if(got != expected)
      ++mismatches;
  }
  return mismatches;
}

} // namespace

TEST_CASE("ranked neighbourhoods of stage 2 are the k nearest points, ties by index, whatever the query before",
          "[neighbors]")
{
  // Stage 2 answers each candidate from the ball of the previous one's k-th distance when it
  // can: the result must not depend on which query came before (nor then on the threads).
  const std::vector<sfe::Vec3> noisy = to_vec3(sample(chamfered_box(), 6000, 0.01));
  std::vector<std::size_t> in_order(noisy.size()), scattered;
  std::iota(in_order.begin(), in_order.end(), std::size_t(0));
  for(std::size_t i = 0; i < noisy.size(); i += 7)
    scattered.push_back((i * 7919) % noisy.size());
  // Far from the cloud (no ball of the previous radius holds k points there), and a cloud of
  // fewer points than k.
  const std::vector<sfe::Vec3> far = {sfe::Vec3(5, 5, 5), sfe::Vec3(0.1, 0.2, 0.3), sfe::Vec3(-7, 0, 0)};
  CHECK(ranked_mismatches(noisy, in_order, far, 150) == 0);
  CHECK(ranked_mismatches(noisy, scattered, far, 150) == 0);
  CHECK(ranked_mismatches(std::vector<sfe::Vec3>(noisy.begin(), noisy.begin() + 40),
                          std::vector<std::size_t>(in_order.begin(), in_order.begin() + 40), far, 150) == 0);
  // A lattice: many points at exactly the same distance, told apart by their index.
  std::vector<sfe::Vec3> lattice;
  for(int i = 0; i < 40; ++i)
    for(int j = 0; j < 40; ++j)
      lattice.emplace_back(0.25 * i, 0.25 * j, 0);
  std::vector<std::size_t> lattice_order(lattice.size());
  std::iota(lattice_order.begin(), lattice_order.end(), std::size_t(0));
  CHECK(ranked_mismatches(lattice, lattice_order, far, 36) == 0);
  // Every point four times: copies are at distance 0 from each other.
  std::vector<sfe::Vec3> repeated;
  for(std::size_t i = 0; i < 1500; ++i)
    repeated.insert(repeated.end(), 4, noisy[i]);
  CHECK(ranked_mismatches(repeated, std::vector<std::size_t>(in_order.begin(), in_order.begin() + 1500), far, 60) == 0);
}

TEST_CASE("moment sums with points removed give the principal axes of the points left", "[neighbors]")
{
  // The forward search of stage 2 adds and removes members of a plane through these sums.
  const std::vector<sfe::Vec3> points = to_vec3(sample(chamfered_box(), 2000, 0.01));
  sfe::Moment_sums sums(points.front());
  std::vector<sfe::Vec3> left;
  for(std::size_t i = 0; i < points.size(); ++i)
    sums.add(points[i]);
  for(std::size_t i = 0; i < points.size(); ++i)
    if(i % 3 == 0)
      sums.remove(points[i]);
    else
      left.push_back(points[i]);
  sfe::Principal_axes incremental, direct;
  REQUIRE(sums.count() == left.size());
  REQUIRE(sums.principal_axes(incremental));
  REQUIRE(sfe::compute_principal_axes(left.size(), [&](std::size_t j) -> const sfe::Vec3& { return left[j]; }, direct));
  CHECK((incremental.centroid - direct.centroid).norm() < 1e-12);
  CHECK((incremental.variances - direct.variances).norm() < 1e-12);
  // The normals agree up to orientation.
  CHECK(std::abs(incremental.axes.col(0).dot(direct.axes.col(0))) > 1 - 1e-9);
  sfe::Moment_sums empty(points.front());
  CHECK_FALSE(empty.principal_axes(incremental));
}

TEST_CASE("gridded neighbourhoods are exactly the k nearest points", "[neighbors]")
{
  const std::vector<sfe::Vec3> clean = to_vec3(sample(chamfered_box(), 20000, 0));
  const std::vector<sfe::Vec3> noisy = to_vec3(sample(chamfered_box(), 20000, 0.01));
  SECTION("clean, k = 36") { check_neighborhoods<CGAL::Sequential_tag>(clean, 36); }
  SECTION("clean, k = 36, in parallel") { check_neighborhoods<CGAL::Parallel_if_available_tag>(clean, 36); }
  SECTION("noisy, k = 164") { check_neighborhoods<CGAL::Sequential_tag>(noisy, 164); }
  SECTION("flat") { check_neighborhoods<CGAL::Sequential_tag>(to_vec3(sample(square_plane(), 10000, 0)), 36); }
  SECTION("every point four times")
  {
    std::vector<sfe::Vec3> repeated;
    for(const sfe::Vec3& p : to_vec3(sample(unit_cube(), 5000, 0)))
      repeated.insert(repeated.end(), 4, p);
    check_neighborhoods<CGAL::Sequential_tag>(repeated, 36);
  }
  SECTION("fewer points than a neighbourhood") { check_neighborhoods<CGAL::Sequential_tag>(std::vector<sfe::Vec3>(clean.begin(), clean.begin() + 30), 36); }
}

TEST_CASE("candidate cells hold every candidate once, the best placed first", "[neighbors]")
{
  const std::vector<sfe::Vec3> points = to_vec3(sample(unit_cube(), 20000, 0));
  std::vector<std::size_t> candidates;
  std::vector<double> residuals(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    residuals[i] = double((i * 7919) % 1000); // arbitrary, with ties
    if(i % 3 == 0)
      candidates.push_back(i);
  }
  const double cell = 0.05;
  const sfe::Candidate_cells cells = sfe::group_candidates(points, candidates, residuals, cell);
  std::vector<std::size_t> members = cells.members;
  std::sort(members.begin(), members.end());
  CHECK(members == candidates);
  for(std::size_t c = 0; c < cells.size(); ++c)
  {
    REQUIRE(cells.size(c) > 0);
    sfe::Vec3 low = points[cells.member(c, 0)], high = low;
    for(std::size_t r = 0; r < cells.size(c); ++r)
    {
      low = low.cwiseMin(points[cells.member(c, r)]);
      high = high.cwiseMax(points[cells.member(c, r)]);
      if(r > 0)
        CHECK(residuals[cells.member(c, r - 1)] >= residuals[cells.member(c, r)]);
    }
    CHECK((high - low).maxCoeff() < cell);
  }
}

TEST_CASE("surfaces found around one candidate serve a neighbour only where they explain its neighbourhood",
          "[projection]")
{
  // The neighbourhood (radius 1 around the origin, the candidate) of a crease along y between
  // A = {z = 0, x >= 0} and B = {x = 0, z <= 0}, closed at y = -0.6 by a third face
  // C = {y = -0.6, x >= 0, z <= 0}: a cube corner. The search found A and B.
  const double step = 0.05, radius = 1, end = -0.6;
  std::vector<sfe::Vec3> points;
  for(int i = 0; i <= 20; ++i)
    for(int j = -12; j <= 20; ++j)
    {
      points.emplace_back(i * step, j * step, 0);     // A
      if(i > 0)
        points.emplace_back(0, j * step, -i * step);  // B
    }
  for(int i = 1; i <= 20; ++i)
    for(int k = 1; k <= 20; ++k)
      points.emplace_back(i * step, end, -k * step);  // C
  points.erase(std::remove_if(points.begin(), points.end(), [&](const sfe::Vec3& p) { return p.norm() > radius; }),
               points.end());
  std::stable_sort(points.begin(), points.end(), [](const sfe::Vec3& a, const sfe::Vec3& b) { return a.norm() < b.norm(); });
  REQUIRE(points.front().norm() == 0);

  sfe::Forward_search search;
  search.local = points;
  std::vector<sfe::Rmls_surface> found(2);
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(points[i].y() <= end + 1e-9)
      continue;
    if(std::abs(points[i].z()) < 1e-9)
      found[0].members.push_back(i);
    if(std::abs(points[i].x()) < 1e-9)
      found[1].members.push_back(i);
  }
  for(sfe::Rmls_surface& s : found)
  {
    sfe::Local_frame frame;
    sfe::Vec3 spread;
    REQUIRE(sfe::principal_frame(points, s.members, frame, spread));
    REQUIRE(s.height_field.fit(points, s.members, frame, 1));
  }
  const std::vector<const sfe::Rmls_surface*> surfaces = {&found[0], &found[1]};
  const double tolerance = 0.01;

  // Along the crease, away from C: A and B are all there is.
  CHECK(sfe::surfaces_explain(search, surfaces, sfe::Vec3(0.1, 0.2, 0), tolerance));
  CHECK(sfe::surfaces_explain(search, surfaces, sfe::Vec3(0, 0.1, -0.05), tolerance));
  // Near C: its points are a surface that a search there would find.
  CHECK_FALSE(sfe::surfaces_explain(search, surfaces, sfe::Vec3(0.1, -0.45, 0), tolerance));
  // Off both surfaces.
  CHECK_FALSE(sfe::surfaces_explain(search, surfaces, sfe::Vec3(0.1, 0.1, 0.1), tolerance));
  // At the rim of the neighbourhood, which covers no ball around it.
  CHECK_FALSE(sfe::surfaces_explain(search, surfaces, sfe::Vec3(0.99, 0, 0), tolerance));
}

TEST_CASE("a noisy plane tilted across a crease splits into the crease's sides, one over a cylinder does not",
          "[projection]")
{
  // 400 points of a unit square [-1, 1] x [-1, 1] folded along y (each half turned by 35
  // degrees: a 70-degree crease), then of a cylinder of radius 2 over the same square, with
  // noise uniform in a ball of radius 0.05 (2.5% of the half-width).
  const double noise = 0.05, half_turn = 35 * pi / 180, cylinder_radius = 2;
  const std::size_t min_size = 40;
  Random random(7);
  sfe::Forward_search fold, cylinder;
  for(int i = 0; i < 400; ++i)
  {
    const double x = random.uniform(-1, 1), y = random.uniform(-1, 1);
    const Vec e = random.in_ball(noise), f = random.in_ball(noise);
    fold.local.emplace_back(x * std::cos(half_turn) + e.x, y + e.y, std::abs(x) * std::sin(half_turn) + e.z);
    const double angle = x / cylinder_radius;
    cylinder.local.emplace_back(cylinder_radius * std::sin(angle) + f.x, y + f.y,
                                cylinder_radius * (1 - std::cos(angle)) + f.z);
  }
  sfe::Rmls_surface tilted, a, b;
  REQUIRE(fold.all_points(tilted));
  REQUIRE(fold.split_across_crease(tilted, min_size, a, b));
  // Each side holds the points of one half, but for those the noise puts across the fold.
  std::size_t misplaced = 0;
  for(const sfe::Rmls_surface* side : {&a, &b})
  {
    std::size_t negative = 0;
    for(std::size_t i : side->members)
      negative += fold.local[i].x() < 0 ? 1 : 0;
    misplaced += (std::min)(negative, side->members.size() - negative);
  }
  CHECK(a.members.size() + b.members.size() == fold.local.size());
  CHECK(misplaced <= fold.local.size() / 20);
  // The sides' planes are the halves' planes, 70 degrees apart.
  const double cosine = std::abs(a.height_field.normal(fold.local[0]).dot(b.height_field.normal(fold.local[0])));
  CHECK(std::acos(cosine) * 180 / pi == Approx(70).margin(3));

  sfe::Rmls_surface round;
  REQUIRE(cylinder.all_points(round));
  CHECK_FALSE(cylinder.split_across_crease(round, min_size, a, b));
}

TEST_CASE("an index over no points answers every query with nothing", "[neighbors]")
{
  // CGAL's Kd_tree has the precondition of a non-empty set (checked in builds without NDEBUG);
  // the stages build indices over feature points, of which there may be none.
  sfe::Point_index index;
  index.build<CGAL::Sequential_tag>(std::vector<sfe::Vec3>());
  std::vector<std::size_t> found{7};
  index.nearest(sfe::Vec3(0, 0, 0), 5, found);
  CHECK(found.empty());
  found = {7};
  index.within(sfe::Vec3(0, 0, 0), 1., found);
  CHECK(found.empty());
  CHECK(index.size() == 0);
}
