// repair_polylines_for_mesh_3() and find_mesh_3_polyline_problems(): the Mesh_3 contract on a
// user's own polylines (no extraction, no Mesh_3: the contract is checked on its own).

#include <CGAL/Sharp_feature_extraction/find_mesh_3_polyline_problems.h>
#include <CGAL/Sharp_feature_extraction/repair_polylines_for_mesh_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef std::vector<Point_3> Polyline;

const double tolerance = 0.01;
// vertices closer than half the tolerance: the repair inserts none
const double step = 0.004;

Polyline segment(const Point_3& a, const Point_3& b)
{
  const double length = std::sqrt(CGAL::squared_distance(a, b));
  const int n = static_cast<int>(std::ceil(length / step));
  Polyline p;
  for(int i = 0; i <= n; ++i)
    p.push_back(i == 0 ? a : (i == n ? b : a + (double(i) / n) * (b - a)));
  return p;
}

/// the 12 edges of the unit cube, sharing its corners exactly
std::vector<Polyline> cube_edges()
{
  std::vector<Polyline> edges;
  for(int a = 0; a < 8; ++a)
    for(int axis = 0; axis < 3; ++axis) {
      const int b = a | (1 << axis);
      if(b == a)
        continue;
      auto corner = [](int i) { return Point_3(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
      edges.push_back(segment(corner(a), corner(b)));
    }
  return edges;
}

std::size_t ends_at(const std::vector<Polyline>& polylines, const Point_3& p)
{
  std::size_t n = 0;
  for(const Polyline& l : polylines)
    n += (l.front() == p) + (l.back() == p);
  return n;
}

} // namespace

TEST_CASE("polylines that already meet the Mesh_3 contract (the edges of a cube, sharing its corners) "
          "pass the check and come out of the repair unchanged, with a report of zeros",
          "[mesh_3_polylines]")
{
  std::vector<Polyline> polylines = cube_edges();
  const std::vector<Polyline> before = polylines;
  const auto np = CGAL::parameters::threshold_distance(tolerance);
  CHECK(CGAL::find_mesh_3_polyline_problems(polylines, np).empty());
  const CGAL::Mesh_3_polyline_repair_report report = CGAL::repair_polylines_for_mesh_3(polylines, np);
  INFO(report.summary());
  CHECK_FALSE(report.changed());
  CHECK(report.input_polylines == 12);
  CHECK(report.output_polylines == 12);
  CHECK(polylines == before);
  // the default tolerance (a thousandth of the diagonal) says the same
  CHECK(CGAL::find_mesh_3_polyline_problems(polylines).empty());
}

TEST_CASE("the repair of a cube's edges with a corner missed, a repeated point, a duplicate edge, an "
          "almost closed loop and a 90-degree turn gives polylines that pass the check, and counts each "
          "change once",
          "[mesh_3_polylines]")
{
  std::vector<Polyline> polylines = cube_edges();
  // an end 0.2 tolerance off its corner (the other two ends there share it exactly)
  const Point_3 corner = polylines[0].front();
  polylines[0].front() = corner + Vector_3(0, 0.2 * tolerance, 0);
  // a zero-length segment
  polylines[1].insert(polylines[1].begin() + 5, polylines[1][5]);
  // edge 2 found twice: a shorter copy 0.2 tolerance beside it
  Polyline twin(polylines[2].begin() + 10, polylines[2].end() - 10);
  for(Point_3& p : twin)
    p = p + Vector_3(0.2 * tolerance, 0.2 * tolerance, 0);
  polylines.push_back(twin);
  // a circle, far from the cube, whose end stops 0.5 tolerance short of its start
  Polyline loop;
  for(int i = 0; i < 400; ++i) {
    const double a = 2 * CGAL_PI * i / 400.;
    loop.push_back(Point_3(5 + 0.25 * std::cos(a), 5 + 0.25 * std::sin(a), 0));
  }
  loop.push_back(loop.front() + Vector_3(0, -0.5 * tolerance, 0));
  polylines.push_back(loop);
  // an L, far from the rest: one polyline turning by 90 degrees
  Polyline l = segment(Point_3(10, 0, 0), Point_3(10.5, 0, 0));
  const Polyline leg = segment(Point_3(10.5, 0, 0), Point_3(10.5, 0.5, 0));
  l.insert(l.end(), leg.begin() + 1, leg.end());
  polylines.push_back(l);

  const auto np = CGAL::parameters::threshold_distance(tolerance);
  const auto problems = CGAL::find_mesh_3_polyline_problems(polylines, np);
  auto has = [&](CGAL::Mesh_3_polyline_problem::Kind kind) {
    for(const auto& p : problems)
      if(p.kind == kind)
        return true;
    return false;
  };
  CHECK(has(CGAL::Mesh_3_polyline_problem::UNSHARED_END));
  CHECK(has(CGAL::Mesh_3_polyline_problem::ZERO_LENGTH_SEGMENT));
  CHECK(has(CGAL::Mesh_3_polyline_problem::UNSHARED_CONTACT));
  CHECK(has(CGAL::Mesh_3_polyline_problem::SHARP_TURN));

  const CGAL::Mesh_3_polyline_repair_report report = CGAL::repair_polylines_for_mesh_3(polylines, np);
  INFO(report.summary());
  for(const auto& p : CGAL::find_mesh_3_polyline_problems(polylines, np))
    UNSCOPED_INFO(p.description);
  CHECK(CGAL::find_mesh_3_polyline_problems(polylines, np).empty());
  CHECK(report.input_polylines == 15);
  CHECK(report.removed_points == 1);
  CHECK(report.inserted_points == 0);
  CHECK(report.snapped_ends == 3); // the corner's stray end, and both ends of the loop
  CHECK(report.closed_loops == 1);
  CHECK(report.dropped_duplicates == 1);
  CHECK(report.sharp_turn_splits == 1);
  CHECK(report.junction_splits == 0);
  CHECK(report.dropped_short == 0);
  CHECK(report.dropped_in_contact == 0);
  // 12 edges, the loop, the two legs of the L
  CHECK(report.output_polylines == 15);
  CHECK(polylines.size() == 15);
  CHECK(ends_at(polylines, corner) == 3);
  CHECK(ends_at(polylines, Point_3(10.5, 0, 0)) == 2);
}

TEST_CASE("two polylines crossing between their vertices are a problem, and the repair makes them meet "
          "at one shared point",
          "[mesh_3_polylines]")
{
  // vertices 0.3 apart: the crossing lies between vertices, found on the segments
  std::vector<Polyline> polylines = {{Point_3(0, 0, 0), Point_3(0.3, 0, 0), Point_3(0.6, 0, 0), Point_3(0.9, 0, 0)},
                                     {Point_3(0.45, -0.45, 0.001), Point_3(0.45, -0.15, 0.001),
                                      Point_3(0.45, 0.15, 0.001), Point_3(0.45, 0.45, 0.001)}};
  const auto np = CGAL::parameters::threshold_distance(tolerance);
  REQUIRE_FALSE(CGAL::find_mesh_3_polyline_problems(polylines, np).empty());
  const CGAL::Mesh_3_polyline_repair_report report = CGAL::repair_polylines_for_mesh_3(polylines, np);
  INFO(report.summary());
  CHECK(CGAL::find_mesh_3_polyline_problems(polylines, np).empty());
  CHECK(report.junction_splits == 2);
  CHECK(report.output_polylines == 4);
  CHECK(report.inserted_points > 0);
}

TEST_CASE("a polyline that goes on past a loop, along its own start, is cut where it touches itself, "
          "not dropped",
          "[mesh_3_polylines]")
{
  // One and a quarter turns of a spiral around a unit circle, drifting outwards by 0.6
  // tolerances a turn: the last quarter runs within the tolerance of the first.
  const double turns = 1.25, drift = 0.6 * tolerance;
  const int n = static_cast<int>(std::ceil(2 * CGAL_PI * turns / step));
  Polyline spiral;
  for(int i = 0; i <= n; ++i) {
    const double angle = 2 * CGAL_PI * turns * double(i) / n;
    const double radius = 1 + drift * angle / (2 * CGAL_PI);
    spiral.push_back(Point_3(radius * std::cos(angle), radius * std::sin(angle), 0));
  }
  std::vector<Polyline> polylines = {spiral};
  const auto np = CGAL::parameters::threshold_distance(tolerance);
  REQUIRE_FALSE(CGAL::find_mesh_3_polyline_problems(polylines, np).empty());
  const CGAL::Mesh_3_polyline_repair_report report = CGAL::repair_polylines_for_mesh_3(polylines, np);
  INFO(report.summary());
  CHECK(CGAL::find_mesh_3_polyline_problems(polylines, np).empty());
  CHECK(report.dropped_in_contact == 0);
  CHECK(report.removed_in_contact > 0);
  // Where the two passes overlap, one of them is cut (the ends that touch the other pass split
  // it first): the pieces left cover the spiral within the tolerance, going around once, plus
  // the short stretches of both passes that leave the points the pieces share (measured: 3%).
  double length = 0;
  for(const Polyline& p : polylines)
    for(std::size_t i = 1; i < p.size(); ++i)
      length += std::sqrt(CGAL::squared_distance(p[i - 1], p[i]));
  CHECK(length >= 2 * CGAL_PI);
  CHECK(length <= 1.05 * 2 * CGAL_PI);
  std::size_t uncovered = 0;
  for(const Point_3& q : spiral) {
    double nearest = std::numeric_limits<double>::infinity();
    for(const Polyline& p : polylines)
      for(const Point_3& r : p)
        nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(q, r)));
    uncovered += nearest > tolerance ? 1 : 0;
  }
  CHECK(uncovered == 0);
}
