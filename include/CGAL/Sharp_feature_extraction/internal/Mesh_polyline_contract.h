// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What Mesh_3 needs of the polylines it protects (Mesh_domain_with_polyline_features_3), in one
// place: the constants of the contract and the geometric tests that `find_mesh_3_polyline_problems()`
// checks and `repair_polylines_for_mesh_3()` repairs.
//
// Mesh_domain_with_polyline_features_3 trusts its input: two curves that meet must share the
// meeting point exactly, a closed curve must repeat its first point exactly, and curves must
// not touch anywhere else. Near-misses (an end 1e-6 away from a corner, a loop that stops
// short, two curves crossing between vertices) make the protecting-ball stage fail an
// assertion or refine forever; a sharp turn inside one polyline is rounded off by its
// protecting balls.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_POLYLINE_CONTRACT_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_POLYLINE_CONTRACT_H

#include <CGAL/Sharp_feature_extraction/Mesh_3_polyline_problem.h>
#include <CGAL/Sharp_feature_extraction/internal/Spatial_grid.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace mesh_polylines {

/// The numbers of the contract. Distances are multiples of the contract's tolerance (the
/// `threshold_distance` of the public functions: the distance below which two vertices of the
/// protected polylines must be one point).
struct Mesh_polyline_contract
{
  /// A polyline that turns by more than this angle (degrees) is split there: Mesh_3's
  /// protecting balls round a sharp turn inside one polyline off, while a corner shared by two
  /// polylines is kept. The same threshold as stage 5 of the extraction (completion), so that
  /// extracted curves already satisfy it.
  static constexpr double sharp_turn_angle = 60;
  /// A closed polyline has at least this many vertices: three distinct points, the first
  /// repeated last. Fewer is a degenerate loop.
  static constexpr std::size_t min_loop_vertices = 4;
  /// Near a point two curves share, their vertices are close because both curves start there;
  /// they are fine as long as the curves leave it at an angle (then the gap grows like the
  /// distance to the junction times the angle). Below this angle (degrees) the two run together:
  /// Mesh_3's protecting balls there must shrink to the gap, and the refinement around them runs
  /// away. Noisy extracted curves leaving one corner differ by more than that.
  static constexpr double minimum_departure_angle = 5;
  /// Consecutive vertices closer than this fraction of the tolerance are one point (a
  /// zero-length segment for Mesh_3).
  static constexpr double merge_fraction = 1e-3;
  /// Vertices are at most this fraction of the tolerance apart before the proximity tests, so
  /// that "near a vertex" is "near the polyline".
  static constexpr double densify_fraction = 0.5;
  /// Along one polyline, vertices closer than this many tolerances of arc length are
  /// neighbours, not a contact of the polyline with itself.
  static constexpr double same_curve_separation = 4;
  /// The vertices of a curve within this many tolerances of arc length from one of its ends
  /// belong to that end's junction: an end near them does not lie on the curve's interior.
  static constexpr double junction_arc = 2;
  /// Curves leaving a shared junction at an acute angle stay within the tolerance of each other
  /// for up to this many tolerances from it (10: down to about 6 degrees): not a contact.
  static constexpr double acute_departure_reach = 10;
  /// Contacts between two curves closer than this many tolerances of arc length apart belong
  /// to one close run.
  static constexpr double run_gap = 2;
  /// A close run longer than this many tolerances on both curves is one crease found twice; a
  /// shorter one is where two curves touch.
  static constexpr double duplicate_run_extent = 4;
  /// A curve with this share of its (densified) vertices within the tolerance of one longer
  /// curve is that curve found twice.
  static constexpr double covered_fraction = 0.7;
};

template <typename Point_3>
bool is_finite_point(const Point_3& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

template <typename Point_3>
double point_distance(const Point_3& a, const Point_3& b)
{
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
}

template <typename Curve>
double curve_length(const Curve& c)
{
  double l = 0;
  for(std::size_t i = 1; i < c.points.size(); ++i)
    l += point_distance(c.points[i - 1], c.points[i]);
  return l;
}

/// arc length from the front to every vertex.
template <typename Curve>
std::vector<double> arc_lengths(const Curve& c)
{
  std::vector<double> s(c.points.size(), 0.);
  for(std::size_t i = 1; i < c.points.size(); ++i)
    s[i] = s[i - 1] + point_distance(c.points[i - 1], c.points[i]);
  return s;
}

/// inserts vertices on the segments longer than `max_step`, so that "near a vertex" tests are
/// also "near the curve" tests. The polyline keeps its exact shape.
template <typename Curve>
void densify(Curve& c, double max_step)
{
  if(!(max_step > 0) || c.points.size() < 2)
    return;
  const bool with_normals = c.normals.size() == c.points.size();
  Curve out = c;
  out.points.assign(1, c.points.front());
  out.normals.clear();
  if(with_normals)
    out.normals.push_back(c.normals.front());
  for(std::size_t i = 1; i < c.points.size(); ++i) {
    const auto& a = c.points[i - 1];
    const auto& b = c.points[i];
    const std::size_t pieces = static_cast<std::size_t>(std::ceil(point_distance(a, b) / max_step));
    for(std::size_t j = 1; j < pieces; ++j) {
      const double t = double(j) / pieces;
      out.points.push_back(a + t * (b - a));
      if(with_normals) {
        auto n = c.normals[i - 1];
        for(int k = 0; k < 2; ++k) {
          const auto m = (1 - t) * c.normals[i - 1][k] + t * c.normals[i][k];
          const double l = std::sqrt(CGAL::to_double(m.squared_length()));
          n[k] = l > 0 ? m / l : c.normals[i - 1][k];
        }
        out.normals.push_back(n);
      }
    }
    out.points.push_back(b);
    if(with_normals)
      out.normals.push_back(c.normals[i]);
  }
  c = std::move(out);
}

/// Two vertices closer than the tolerance that are not the same point, on two curves (or far
/// apart along one curve), and not explained by a junction the curves share.
struct Unshared_contact
{
  std::size_t a = 0, i = 0, b = 0, j = 0; // curve and vertex index of each vertex
  double distance = 0;
};

/// lists the vertex pairs Mesh_3 cannot protect apart: closer than `tol`, not the same point,
/// and not two curves leaving a shared point at
/// `Mesh_polyline_contract::minimum_departure_angle` or more.
template <typename Curve, typename Point_3>
std::vector<Unshared_contact> find_unshared_contacts(const std::vector<Curve>& curves, double tol)
{
  const double sin_departure = std::sin(Mesh_polyline_contract::minimum_departure_angle * CGAL_PI / 180.);
  std::vector<std::pair<std::size_t, std::size_t>> vertices;
  Spatial_grid<Point_3> grid(tol);
  for(std::size_t c = 0; c < curves.size(); ++c)
    for(std::size_t i = 0; i < curves[c].points.size(); ++i) {
      grid.insert(curves[c].points[i], vertices.size());
      vertices.push_back(std::make_pair(c, i));
    }
  std::vector<std::vector<double>> arcs;
  for(const Curve& c : curves)
    arcs.push_back(arc_lengths(c));
  std::vector<Unshared_contact> contacts;
  for(std::size_t id = 0; id < vertices.size(); ++id) {
    const std::size_t a = vertices[id].first, i = vertices[id].second;
    const Point_3& pa = curves[a].points[i];
    grid.for_each_within(pa, tol, [&](std::size_t other, double d2) {
      const std::size_t b = vertices[other].first, j = vertices[other].second;
      if(other <= id || curves[b].points[j] == pa)
        return;
      const Point_3& pb = curves[b].points[j];
      const double d = std::sqrt(d2);
      // along one curve, neighbours are close: only far-apart stretches count (cyclically on
      // a loop)
      if(a == b) {
        const double along = std::abs(arcs[a][i] - arcs[a][j]);
        const bool closed = curves[a].points.front() == curves[a].points.back();
        if((std::min)(along, closed ? arcs[a].back() - along : along) < Mesh_polyline_contract::same_curve_separation * tol)
          return;
      }
      for(const Point_3* e : {&curves[a].points.front(), &curves[a].points.back()})
        if(*e == curves[b].points.front() || *e == curves[b].points.back()) {
          const double r = (std::max)(point_distance(pa, *e), point_distance(pb, *e));
          if(d >= sin_departure * r)
            return;
        }
      contacts.push_back(Unshared_contact{a, i, b, j, d});
    });
  }
  return contacts;
}

/// The vertices where a polyline turns by more than `angle_degrees`, measured between chords
/// reaching at least `reach` along the curve on each side (so that vertex noise does not count
/// as a turn): one vertex per run of sharp vertices, the sharpest. With `away_from_ends`, only
/// the vertices farther than `reach` from both ends count: closer, a turn is below the
/// resolution of the tolerance (a snapped end moves its first segment by up to one tolerance).
template <typename Curve>
std::vector<std::size_t> sharp_turn_vertices(const Curve& curve, double reach, double angle_degrees,
                                             bool away_from_ends = false)
{
  const double cos_limit = std::cos(angle_degrees * CGAL_PI / 180.);
  const std::vector<double> s = arc_lengths(curve);
  const std::size_t n = curve.points.size();
  std::vector<double> turn(n, 1.);
  for(std::size_t i = 1; i + 1 < n; ++i) {
    std::size_t a = i, b = i;
    while(a > 0 && s[i] - s[a] < reach)
      --a;
    while(b + 1 < n && s[b] - s[i] < reach)
      ++b;
    const auto u = curve.points[i] - curve.points[a];
    const auto v = curve.points[b] - curve.points[i];
    const double nu = std::sqrt(CGAL::to_double(u.squared_length()));
    const double nv = std::sqrt(CGAL::to_double(v.squared_length()));
    const bool measured = !away_from_ends || (s[i] >= reach && s.back() - s[i] >= reach);
    if(nu > 0 && nv > 0 && measured)
      turn[i] = CGAL::to_double(u * v) / (nu * nv);
  }
  std::vector<std::size_t> sharpest_of_runs;
  for(std::size_t i = 1; i + 1 < n;) {
    if(turn[i] >= cos_limit) {
      ++i;
      continue;
    }
    std::size_t sharpest = i;
    while(i + 1 < n && turn[i] < cos_limit) {
      if(turn[i] < turn[sharpest])
        sharpest = i;
      ++i;
    }
    sharpest_of_runs.push_back(sharpest);
  }
  return sharpest_of_runs;
}

/// The tolerance and the angle of the contract.
struct Contract_tolerances
{
  double distance = 0;
  double angle = Mesh_polyline_contract::sharp_turn_angle;
};

/// The default tolerance: a thousandth of the bounding-box diagonal of the polylines, far below
/// any mesh size Mesh_3 could be given for them, far above rounding errors.
constexpr double default_tolerance_fraction = 1e-3;

template <typename Curve>
double default_tolerance(const std::vector<Curve>& curves)
{
  CGAL::Bbox_3 box;
  for(const Curve& c : curves)
    for(const auto& p : c.points)
      if(is_finite_point(p))
        box += p.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  return std::isfinite(diagonal) && diagonal > 0 ? default_tolerance_fraction * diagonal : 1.;
}

/// The check itself, on anything with `points` (see `find_mesh_3_polyline_problems()`).
template <typename Curve>
std::vector<Mesh_3_polyline_problem> find_contract_violations(const std::vector<Curve>& input,
                                                              const Contract_tolerances& tolerances)
{
  typedef typename std::remove_const<typename std::remove_reference<decltype(input[0].points[0])>::type>::type Point_3;
  typedef Mesh_3_polyline_problem Problem;
  const double tolerance = tolerances.distance;
  std::vector<Problem> problems;
  auto say = [&](typename Problem::Kind kind, std::size_t c, std::size_t other, const std::string& what) {
    problems.push_back(Problem{kind, c, other, "polyline " + std::to_string(c) + ": " + what});
  };
  // the proximity tests look at vertices: on a copy whose segments are short against the
  // tolerance, they see the whole polylines
  std::vector<Curve> curves = input;
  for(Curve& c : curves)
    densify(c, Mesh_polyline_contract::densify_fraction * tolerance);
  Spatial_grid<Point_3> ends(tolerance), interiors(tolerance);
  std::vector<std::size_t> interior_owner;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const auto& pts = curves[c].points;
    if(pts.size() < 2) {
      say(Problem::TOO_FEW_POINTS, c, c, "fewer than two points");
      continue;
    }
    for(std::size_t i = 0; i < pts.size(); ++i) {
      if(!is_finite_point(pts[i]))
        say(Problem::NON_FINITE_POINT, c, c, "non-finite point");
      else if(i > 0 && pts[i] == pts[i - 1])
        say(Problem::ZERO_LENGTH_SEGMENT, c, c, "repeated consecutive point");
    }
    if(pts.front() == pts.back() && pts.size() < Mesh_polyline_contract::min_loop_vertices)
      say(Problem::DEGENERATE_LOOP, c, c, "closed with fewer than three distinct points");
    for(std::size_t i : sharp_turn_vertices(curves[c], tolerance, tolerances.angle, true))
      say(Problem::SHARP_TURN, c, c, "turns by more than the maximum angle at vertex " + std::to_string(i));
    ends.insert(pts.front(), 2 * c);
    ends.insert(pts.back(), 2 * c + 1);
    for(std::size_t i = 1; i + 1 < pts.size(); ++i) {
      interiors.insert(pts[i], interior_owner.size());
      interior_owner.push_back(c);
    }
  }
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const auto& pts = curves[c].points;
    if(pts.size() < 2)
      continue;
    for(const Point_3& q : {pts.front(), pts.back()}) {
      ends.for_each_within(q, tolerance, [&](std::size_t other, double) {
        const auto& o = curves[other / 2].points;
        const Point_3& r = other % 2 == 0 ? o.front() : o.back();
        if(r != q && other / 2 >= c)
          say(Problem::UNSHARED_END, c, other / 2,
              "end nearly meets an end of polyline " + std::to_string(other / 2) + " without sharing it");
      });
      interiors.for_each_within(q, tolerance * Mesh_polyline_contract::merge_fraction, [&](std::size_t id, double) {
        say(Problem::END_ON_INTERIOR, c, interior_owner[id],
            "end lies on the interior of polyline " + std::to_string(interior_owner[id]));
      });
    }
  }
  for(const Unshared_contact& contact : find_unshared_contacts<Curve, Point_3>(curves, tolerance)) {
    std::ostringstream what;
    what << "a vertex is " << contact.distance << " from a vertex of polyline " << contact.b
         << " without sharing a point";
    say(Problem::UNSHARED_CONTACT, contact.a, contact.b, what.str());
  }
  return problems;
}

} // namespace mesh_polylines
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_POLYLINE_CONTRACT_H
