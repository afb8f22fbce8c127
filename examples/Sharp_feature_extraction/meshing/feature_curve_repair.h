// Makes feature curves safe to hand to Mesh_3 as protected polylines.
//
// Mesh_domain_with_polyline_features_3 trusts its input: two curves that meet must share the
// meeting point exactly, a closed curve must repeat its first point exactly, and curves must
// not touch anywhere else. Near-misses (an end 1e-6 away from a corner, a loop that stops
// short, two curves crossing between vertices) make the protecting-ball stage fail an
// assertion or refine forever. Extracted curves are not guaranteed to be perfect, so the
// example repairs what it can and reports the rest, instead of letting Mesh_3 assert.

#ifndef SFE_MESHING_FEATURE_CURVE_REPAIR_H
#define SFE_MESHING_FEATURE_CURVE_REPAIR_H

#include "meshing/spatial_grid.h"

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sfe_meshing {

/// Tolerances of `repair_feature_curves_for_mesh_3()`, as absolute distances (the example
/// derives them from the sampling spacing).
struct Curve_repair_options
{
  /// Curve ends closer than this are one junction; an end this close to the interior of a
  /// curve splits that curve there; two curves this close elsewhere are made to meet.
  double snap_tolerance = 0;
  /// Open curves shorter than this are dropped (closed loops: three times this perimeter).
  double minimum_length = 0;
  /// A curve that turns by more than this (degrees, measured over one snap tolerance on each
  /// side) is split there, because Mesh_3 rounds off sharp turns inside a polyline.
  double sharp_turn_angle = 70;
};

/// What `repair_feature_curves_for_mesh_3()` changed.
struct Curve_repair_report
{
  std::size_t input_curves = 0;
  std::size_t output_curves = 0;
  std::size_t removed_points = 0;      ///< non-finite or duplicate consecutive points
  std::size_t snapped_ends = 0;        ///< ends moved onto a shared junction point
  std::size_t closed_loops = 0;        ///< curves whose two ends became one point
  std::size_t junction_splits = 0;     ///< splits where an end or another curve touches an interior vertex
  std::size_t sharp_turn_splits = 0;
  std::size_t dropped_short = 0;
  std::size_t dropped_parallel = 0;    ///< curves dropped because they ran along a longer one (duplicates)
  std::size_t dropped_close = 0;       ///< curves dropped because they came too close to another one
  std::size_t discarded_normals = 0;   ///< curves whose normals did not match their points
  std::size_t moved_onto_surface = 0;  ///< vertices moved onto the implicit surface
  std::size_t cut_off_surface = 0;     ///< curves cut where a vertex is too far from the implicit surface

  std::string summary() const
  {
    std::ostringstream out;
    out << input_curves << " curves in, " << output_curves << " out";
    const std::pair<const char*, std::size_t> items[] = {
      {"points removed", removed_points}, {"ends snapped", snapped_ends},
      {"loops closed", closed_loops}, {"junction splits", junction_splits},
      {"sharp-turn splits", sharp_turn_splits}, {"short curves dropped", dropped_short},
      {"parallel duplicates dropped", dropped_parallel}, {"too close curves dropped", dropped_close},
      {"normals discarded", discarded_normals}, {"vertices moved onto the surface", moved_onto_surface},
      {"curves cut off the surface", cut_off_surface}};
    for(const auto& item : items)
      if(item.second > 0)
        out << ", " << item.second << " " << item.first;
    return out.str();
  }
};

namespace repair_internal {

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

struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t i)
  {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

/// removes non-finite points and consecutive points closer than `merge_distance`, keeping the
/// two ends exact. Returns the number of points removed.
template <typename Curve>
std::size_t remove_bad_points(Curve& c, double merge_distance)
{
  const bool with_normals = c.normals.size() == c.points.size();
  Curve out = c;
  out.points.clear();
  out.normals.clear();
  for(std::size_t i = 0; i < c.points.size(); ++i) {
    if(!is_finite_point(c.points[i]))
      continue;
    const bool last = (i + 1 == c.points.size());
    if(!out.points.empty() && point_distance(out.points.back(), c.points[i]) <= merge_distance) {
      if(!last || out.points.size() == 1)
        continue;
      // keep the exact last point: drop the interior one before it instead
      out.points.pop_back();
      if(with_normals)
        out.normals.pop_back();
    }
    out.points.push_back(c.points[i]);
    if(with_normals)
      out.normals.push_back(c.normals[i]);
  }
  const std::size_t removed = c.points.size() - out.points.size();
  c = std::move(out);
  return removed;
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

/// splits `c` at the sorted interior vertex indices `at`; pieces share the split vertices.
template <typename Curve>
std::vector<Curve> split(const Curve& c, const std::vector<std::size_t>& at)
{
  std::vector<Curve> pieces;
  const bool with_normals = c.normals.size() == c.points.size();
  std::size_t begin = 0;
  std::vector<std::size_t> cuts = at;
  cuts.push_back(c.points.size() - 1);
  for(std::size_t end : cuts) {
    if(end <= begin)
      continue;
    Curve piece;
    piece.points.assign(c.points.begin() + begin, c.points.begin() + end + 1);
    if(with_normals)
      piece.normals.assign(c.normals.begin() + begin, c.normals.begin() + end + 1);
    pieces.push_back(std::move(piece));
    begin = end;
  }
  return pieces;
}

/// Applies the pending splits (curve index -> interior vertex indices) to all curves.
template <typename Curve>
void apply_splits(std::vector<Curve>& curves, std::map<std::size_t, std::vector<std::size_t>>& splits)
{
  std::vector<Curve> result;
  for(std::size_t i = 0; i < curves.size(); ++i) {
    auto it = splits.find(i);
    if(it == splits.end()) {
      result.push_back(std::move(curves[i]));
      continue;
    }
    std::vector<std::size_t>& at = it->second;
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    for(Curve& piece : split(curves[i], at))
      result.push_back(std::move(piece));
  }
  curves = std::move(result);
  splits.clear();
}

/// Ends within the tolerance become one junction point: an exactly shared end if there is one,
/// else a preferred point (a corner of the network) nearby, else the cluster's centroid.
template <typename Curve, typename Point_3>
void snap_ends(std::vector<Curve>& curves, const std::vector<Point_3>& preferred, double tol,
               Curve_repair_report& report)
{
  const std::size_t n = 2 * curves.size();
  auto end_point = [&](std::size_t e) -> Point_3& {
    Curve& c = curves[e / 2];
    return (e % 2 == 0) ? c.points.front() : c.points.back();
  };
  Spatial_grid<Point_3> grid(tol);
  for(std::size_t e = 0; e < n; ++e)
    grid.insert(end_point(e), e);
  Union_find clusters(n);
  for(std::size_t e = 0; e < n; ++e)
    grid.for_each_within(end_point(e), tol, [&](std::size_t f, double) { clusters.unite(e, f); });

  Spatial_grid<Point_3> preferred_grid(tol);
  for(std::size_t i = 0; i < preferred.size(); ++i)
    preferred_grid.insert(preferred[i], i);

  std::map<std::size_t, std::vector<std::size_t>> members;
  for(std::size_t e = 0; e < n; ++e)
    members[clusters.find(e)].push_back(e);
  for(auto& cluster : members) {
    const std::vector<std::size_t>& ends = cluster.second;
    Point_3 junction = end_point(ends.front());
    bool chosen = false;
    // an end already shared exactly by two curve ends is kept as is
    for(std::size_t i = 0; i < ends.size() && !chosen; ++i)
      for(std::size_t j = i + 1; j < ends.size() && !chosen; ++j)
        if(end_point(ends[i]) == end_point(ends[j])) {
          junction = end_point(ends[i]);
          chosen = true;
        }
    if(!chosen) {
      const std::size_t p = preferred_grid.nearest_within(junction, tol);
      if(p != Spatial_grid<Point_3>::none) {
        junction = preferred[p];
        chosen = true;
      }
    }
    if(!chosen && ends.size() > 1) {
      double x = 0, y = 0, z = 0;
      for(std::size_t e : ends) {
        x += CGAL::to_double(end_point(e).x());
        y += CGAL::to_double(end_point(e).y());
        z += CGAL::to_double(end_point(e).z());
      }
      const double k = static_cast<double>(ends.size());
      junction = Point_3(x / k, y / k, z / k);
    }
    for(std::size_t e : ends)
      if(end_point(e) != junction) {
        end_point(e) = junction;
        ++report.snapped_ends;
      }
  }
}

/// An end lying on the interior of a curve is a T-junction: split the curve there, at the
/// vertex nearest to the end, and move that vertex onto the end exactly.
template <typename Curve, typename Point_3>
void split_at_ends_touching_interiors(std::vector<Curve>& curves, double tol, Curve_repair_report& report)
{
  typedef std::pair<std::size_t, std::size_t> Vertex; // (curve, index)
  std::vector<Vertex> interior;
  Spatial_grid<Point_3> grid(tol);
  for(std::size_t c = 0; c < curves.size(); ++c)
    for(std::size_t i = 1; i + 1 < curves[c].points.size(); ++i) {
      grid.insert(curves[c].points[i], interior.size());
      interior.push_back(Vertex(c, i));
    }
  std::vector<std::vector<double>> arcs;
  for(const Curve& c : curves)
    arcs.push_back(arc_lengths(c));

  std::map<std::size_t, std::vector<std::size_t>> splits;
  std::map<Vertex, Point_3> moves;
  for(std::size_t c = 0; c < curves.size(); ++c)
    for(int end = 0; end < 2; ++end) {
      const Point_3 q = end == 0 ? curves[c].points.front() : curves[c].points.back();
      // nearest interior vertex per curve
      std::map<std::size_t, std::pair<double, std::size_t>> best;
      grid.for_each_within(q, tol, [&](std::size_t id, double d2) {
        const Vertex v = interior[id];
        const Curve& other = curves[v.first];
        const std::vector<double>& s = arcs[v.first];
        // skip vertices next to an end of the same curve that is this junction
        if(other.points.front() == q && s[v.second] < 2 * tol)
          return;
        if(other.points.back() == q && s.back() - s[v.second] < 2 * tol)
          return;
        auto it = best.find(v.first);
        if(it == best.end() || d2 < it->second.first)
          best[v.first] = std::make_pair(d2, v.second);
      });
      for(const auto& b : best) {
        splits[b.first].push_back(b.second.second);
        moves[Vertex(b.first, b.second.second)] = q;
      }
    }
  for(const auto& m : moves)
    curves[m.first.first].points[m.first.second] = m.second;
  report.junction_splits += moves.size();
  apply_splits(curves, splits);
}

/// A stretch where two curves (or one curve with itself, far apart along it) come closer than
/// the tolerance: the arc-length extents on both, and the closest vertex pair.
struct Close_run
{
  std::size_t a = 0, b = 0;                 // curves (a <= b)
  std::size_t closest_a = 0, closest_b = 0; // vertex indices
  double extent_a = 0, extent_b = 0;        // arc length covered on each curve
};

/// finds the close runs between curves; `with_ends` says whether curve ends take part.
template <typename Curve, typename Point_3>
std::vector<Close_run> find_close_runs(const std::vector<Curve>& curves, double tol, bool with_ends)
{
  typedef std::pair<std::size_t, std::size_t> Vertex;
  std::vector<Vertex> vertices;
  Spatial_grid<Point_3> grid(tol);
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const std::size_t n = curves[c].points.size();
    for(std::size_t i = with_ends ? 0 : 1; i < (with_ends ? n : n - 1); ++i) {
      grid.insert(curves[c].points[i], vertices.size());
      vertices.push_back(Vertex(c, i));
    }
  }
  std::vector<std::vector<double>> arcs;
  for(const Curve& c : curves)
    arcs.push_back(arc_lengths(c));

  struct Contact { double sa, sb, d; std::size_t ia, ib; };
  std::map<std::pair<std::size_t, std::size_t>, std::vector<Contact>> contacts;
  for(std::size_t id = 0; id < vertices.size(); ++id) {
    const Vertex a = vertices[id];
    const Point_3& pa = curves[a.first].points[a.second];
    grid.for_each_within(pa, tol, [&](std::size_t other, double d2) {
      const Vertex b = vertices[other];
      if(b.first < a.first || (b.first == a.first && b.second <= a.second))
        return;
      // vertices meeting exactly are already a junction
      if(curves[b.first].points[b.second] == pa)
        return;
      // curves leaving a shared junction are close to each other near it, for a while if
      // they leave at an acute angle (10 tolerances: down to about 6 degrees): not a contact
      const Point_3& pb = curves[b.first].points[b.second];
      for(const Point_3* j : {&curves[a.first].points.front(), &curves[a.first].points.back()})
        if((*j == curves[b.first].points.front() || *j == curves[b.first].points.back()) &&
           point_distance(pa, *j) < 10 * tol && point_distance(pb, *j) < 10 * tol)
          return;
      if(a.first == b.first && std::abs(arcs[a.first][a.second] - arcs[b.first][b.second]) < 4 * tol)
        return;
      contacts[std::make_pair(a.first, b.first)].push_back(
        Contact{arcs[a.first][a.second], arcs[b.first][b.second], std::sqrt(d2), a.second, b.second});
    });
  }
  std::vector<Close_run> runs;
  for(auto& group : contacts) {
    std::vector<Contact>& cs = group.second;
    std::sort(cs.begin(), cs.end(), [](const Contact& x, const Contact& y) { return x.sa < y.sa; });
    std::size_t begin = 0;
    while(begin < cs.size()) {
      std::size_t end = begin + 1;
      while(end < cs.size() && cs[end].sa - cs[end - 1].sa < 2 * tol)
        ++end;
      Close_run run;
      run.a = group.first.first;
      run.b = group.first.second;
      double lo_b = cs[begin].sb, hi_b = cs[begin].sb;
      std::size_t closest = begin;
      for(std::size_t k = begin; k < end; ++k) {
        lo_b = (std::min)(lo_b, cs[k].sb);
        hi_b = (std::max)(hi_b, cs[k].sb);
        if(cs[k].d < cs[closest].d)
          closest = k;
      }
      run.closest_a = cs[closest].ia;
      run.closest_b = cs[closest].ib;
      run.extent_a = cs[end - 1].sa - cs[begin].sa;
      run.extent_b = hi_b - lo_b;
      runs.push_back(run);
      begin = end;
    }
  }
  return runs;
}

/// Two curves running closer than the tolerance for more than a few tolerances are one crease
/// found twice: the shorter goes.
template <typename Curve, typename Point_3>
void drop_parallel_duplicates(std::vector<Curve>& curves, double tol, Curve_repair_report& report)
{
  std::vector<bool> dropped(curves.size(), false);
  for(const Close_run& run : find_close_runs<Curve, Point_3>(curves, tol, true)) {
    if(run.a == run.b || (run.extent_a <= 4 * tol && run.extent_b <= 4 * tol))
      continue;
    if(dropped[run.a] || dropped[run.b])
      continue;
    const std::size_t shorter = curve_length(curves[run.a]) < curve_length(curves[run.b]) ? run.a : run.b;
    dropped[shorter] = true;
    ++report.dropped_parallel;
  }
  std::vector<Curve> kept;
  for(std::size_t c = 0; c < curves.size(); ++c)
    if(!dropped[c])
      kept.push_back(std::move(curves[c]));
  curves = std::move(kept);
}

/// A curve lying mostly (70% of its vertices) within the tolerance of one longer curve is that
/// curve found twice, even when the two leave a shared junction at an acute angle (the
/// close-run test ignores junction neighbourhoods): it goes. Curves are densified, so vertex
/// counts measure length.
template <typename Curve, typename Point_3>
void drop_covered_curves(std::vector<Curve>& curves, double tol, Curve_repair_report& report)
{
  const double covered_fraction = 0.7;
  Spatial_grid<Point_3> grid(tol);
  std::vector<std::size_t> owner;
  for(std::size_t c = 0; c < curves.size(); ++c)
    for(const Point_3& p : curves[c].points) {
      grid.insert(p, owner.size());
      owner.push_back(c);
    }
  std::vector<std::size_t> order(curves.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return curve_length(curves[a]) < curve_length(curves[b]);
  });
  std::vector<bool> dropped(curves.size(), false);
  for(std::size_t a : order) {
    const double length_a = curve_length(curves[a]);
    std::map<std::size_t, std::size_t> near_count; // other curve -> vertices of a near it
    for(const Point_3& p : curves[a].points) {
      std::vector<std::size_t> seen;
      grid.for_each_within(p, tol, [&](std::size_t id, double) {
        const std::size_t b = owner[id];
        if(b != a && !dropped[b] && std::find(seen.begin(), seen.end(), b) == seen.end())
          seen.push_back(b);
      });
      for(std::size_t b : seen)
        ++near_count[b];
    }
    for(const auto& nc : near_count)
      if(curve_length(curves[nc.first]) >= length_a &&
         nc.second >= covered_fraction * curves[a].points.size()) {
        dropped[a] = true;
        ++report.dropped_parallel;
        break;
      }
  }
  std::vector<Curve> kept;
  for(std::size_t c = 0; c < curves.size(); ++c)
    if(!dropped[c])
      kept.push_back(std::move(curves[c]));
  curves = std::move(kept);
}

/// Interior vertices of two curves (or of one curve, far apart along it) closer than the
/// tolerance over a short stretch: the curves cross or touch; they meet at the midpoint of the
/// closest pair, and both are split there.
template <typename Curve, typename Point_3>
void resolve_interior_contacts(std::vector<Curve>& curves, double tol, Curve_repair_report& report)
{
  typedef std::pair<std::size_t, std::size_t> Vertex;
  std::map<std::size_t, std::vector<std::size_t>> splits;
  std::map<Vertex, Point_3> moves;
  for(const Close_run& run : find_close_runs<Curve, Point_3>(curves, tol, false)) {
    if(run.extent_a > 4 * tol || run.extent_b > 4 * tol)
      continue; // a self-parallel stretch: left alone (Mesh_3 copes with it, slowly)
    const Vertex va(run.a, run.closest_a), vb(run.b, run.closest_b);
    if(moves.count(va) || moves.count(vb))
      continue;
    const Point_3 m = CGAL::midpoint(curves[run.a].points[run.closest_a], curves[run.b].points[run.closest_b]);
    moves[va] = m;
    moves[vb] = m;
    splits[run.a].push_back(run.closest_a);
    splits[run.b].push_back(run.closest_b);
    report.junction_splits += 2;
  }
  for(const auto& m : moves)
    curves[m.first.first].points[m.first.second] = m.second;
  apply_splits(curves, splits);
}

/// Two vertices closer than the tolerance that are not the same point, on two curves (or far
/// apart along one curve), and not explained by a junction the curves share.
struct Unshared_contact
{
  std::size_t a = 0, i = 0, b = 0, j = 0; // curve and vertex index of each vertex
  double distance = 0;
};

/// Near a point two curves share, their vertices are close because both curves start there;
/// they are fine as long as the curves leave it at an angle (then the gap grows like the
/// distance to the junction times the angle). Below this angle (degrees) the two run together:
/// Mesh_3's protecting balls there must shrink to the gap, and the refinement around them runs
/// away. Noisy extracted curves leaving one corner differ by more than that.
constexpr double minimum_departure_angle = 5;

/// lists the vertex pairs Mesh_3 cannot protect apart: closer than `tol`, not the same point,
/// and not two curves leaving a shared point at `minimum_departure_angle` or more.
template <typename Curve, typename Point_3>
std::vector<Unshared_contact> find_unshared_contacts(const std::vector<Curve>& curves, double tol)
{
  const double sin_departure = std::sin(minimum_departure_angle * 3.14159265358979323846 / 180.);
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
        if((std::min)(along, closed ? arcs[a].back() - along : along) < 4 * tol)
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

/// Splits where the curve turns by more than the angle, measured between chords reaching at
/// least `reach` along the curve on each side (so that vertex noise does not count as a turn).
template <typename Curve>
void split_sharp_turns(std::vector<Curve>& curves, double reach, double angle_degrees,
                       Curve_repair_report& report)
{
  const double cos_limit = std::cos(angle_degrees * 3.14159265358979323846 / 180.);
  std::map<std::size_t, std::vector<std::size_t>> splits;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const Curve& curve = curves[c];
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
      if(nu > 0 && nv > 0)
        turn[i] = CGAL::to_double(u * v) / (nu * nv);
    }
    // one split per run of sharp vertices, at the sharpest
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
      splits[c].push_back(sharpest);
      ++report.sharp_turn_splits;
    }
  }
  apply_splits(curves, splits);
}

} // namespace repair_internal

/// The last resort of the repair, also for curves moved after it: of two curves that come
/// closer than `tolerance` without sharing a point there (an unshared contact, as listed by
/// `find_mesh_3_feature_problems()`), the shorter is dropped (a curve that comes back onto
/// itself is dropped too). Without it that crease is meshed from the implicit surface alone;
/// with it Mesh_3 would shrink its protecting balls to the gap and not finish.
template <typename GeomTraits>
void drop_feature_curves_in_contact(std::vector<CGAL::Feature_polyline<GeomTraits>>& curves,
                                    double tolerance, Curve_repair_report& report)
{
  typedef CGAL::Feature_polyline<GeomTraits> Curve;
  using namespace repair_internal;
  std::vector<bool> dropped(curves.size(), false);
  for(const Unshared_contact& contact :
      find_unshared_contacts<Curve, typename GeomTraits::Point_3>(curves, tolerance)) {
    if(dropped[contact.a] || dropped[contact.b])
      continue;
    dropped[curve_length(curves[contact.a]) < curve_length(curves[contact.b]) ? contact.a : contact.b] = true;
    ++report.dropped_close;
  }
  report.output_curves -= std::count(dropped.begin(), dropped.end(), true);
  std::vector<Curve> kept;
  for(std::size_t c = 0; c < curves.size(); ++c)
    if(!dropped[c])
      kept.push_back(std::move(curves[c]));
  curves = std::move(kept);
}

/// moves `p` onto the zero set of `function` (a signed distance, up to a factor near 1) by
/// Newton steps along its gradient, taken by central differences `gradient_step` apart. Returns
/// false, leaving `p`, when no zero within `max_move` is found.
template <typename Function, typename Point_3>
bool project_onto_zero_set(const Function& function, Point_3& p, double gradient_step, double max_move)
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector_3;
  // converged: a hundredth of the gradient step, far below any facet distance
  const double tolerance = 1e-2 * gradient_step;
  const int maximal_steps = 20;
  Point_3 x = p;
  for(int step = 0; step < maximal_steps; ++step) {
    const double value = function(x);
    if(std::abs(value) <= tolerance) {
      if(repair_internal::point_distance(x, p) > max_move)
        return false;
      p = x;
      return true;
    }
    const double h = gradient_step;
    const Vector_3 gradient(
      (function(x + Vector_3(h, 0, 0)) - function(x - Vector_3(h, 0, 0))) / (2 * h),
      (function(x + Vector_3(0, h, 0)) - function(x - Vector_3(0, h, 0))) / (2 * h),
      (function(x + Vector_3(0, 0, h)) - function(x - Vector_3(0, 0, h))) / (2 * h));
    const double squared_norm = CGAL::to_double(gradient.squared_length());
    if(!(squared_norm > 0))
      return false;
    x = x - (value / squared_norm) * gradient;
    if(repair_internal::point_distance(x, p) > max_move)
      return false;
  }
  return false;
}

/// Mesh_3 makes every protected vertex a mesh vertex and refines the surface around it until
/// the facets are within the facet distance of the surface: a protected vertex off the implicit
/// surface can never be reached, and the refinement shrinks towards it without end. So every
/// vertex of `curves` is moved onto the zero set of `function` (leaving the vertices within
/// half the facet distance where they were still let Mesh_3 converge onto a point: anchor,
/// 25k points, noise 0, seed 2). Where a vertex has no zero
/// within `max_move`, the curve does not lie on the surface (a spurious curve, or a corner the
/// surface rounds off): the curve is cut there, the pieces on either side shortened by
/// `cut_margin` (so that their new ends stay clear of the other curves meeting at that point),
/// and pieces shorter than `minimum_length` are dropped. Shared points stay shared: the
/// projection is a function of the point alone.
template <typename GeomTraits, typename Function>
void project_feature_curves_onto_surface(std::vector<CGAL::Feature_polyline<GeomTraits>>& curves,
                                         const Function& function, double gradient_step,
                                         double max_move, double cut_margin, double minimum_length,
                                         Curve_repair_report& report)
{
  typedef CGAL::Feature_polyline<GeomTraits> Curve;
  using namespace repair_internal;
  std::vector<Curve> kept;
  for(Curve& c : curves) {
    const std::size_t n = c.points.size();
    std::vector<bool> on_surface(n);
    for(std::size_t i = 0; i < n; ++i) {
      const auto before = c.points[i];
      on_surface[i] = project_onto_zero_set(function, c.points[i], gradient_step, max_move);
      report.moved_onto_surface += (on_surface[i] && c.points[i] != before) ? 1 : 0;
    }
    if(std::find(on_surface.begin(), on_surface.end(), false) == on_surface.end()) {
      kept.push_back(std::move(c));
      continue;
    }
    ++report.cut_off_surface;
    const std::vector<double> arc = arc_lengths(c);
    auto near_cut = [&](std::size_t i, std::size_t cut) {
      return point_distance(c.points[i], c.points[cut]) < cut_margin;
    };
    for(std::size_t begin = 0; begin < n;) {
      if(!on_surface[begin]) {
        ++begin;
        continue;
      }
      std::size_t end = begin;
      while(end < n && on_surface[end])
        ++end;
      // [first, last): the run [begin, end) without its vertices within `cut_margin` of a
      // vertex off the surface
      std::size_t first = begin, last = end;
      if(begin > 0)
        while(first < end && near_cut(first, begin - 1))
          ++first;
      if(end < n)
        while(last > first && near_cut(last - 1, end))
          --last;
      if(last >= first + 2 && arc[last - 1] - arc[first] >= minimum_length) {
        std::vector<std::size_t> cuts;
        if(first > 0)
          cuts.push_back(first);
        if(last < n)
          cuts.push_back(last - 1);
        // the piece between the cuts: the second of the split's pieces if it starts with a cut
        const std::vector<Curve> pieces = split(c, cuts);
        kept.push_back(pieces[first > 0 ? 1 : 0]);
      }
      begin = end;
    }
  }
  report.output_curves = report.output_curves + kept.size() - curves.size();
  curves = std::move(kept);
}

template <typename GeomTraits>
std::vector<std::string> find_mesh_3_feature_problems(
  const std::vector<CGAL::Feature_polyline<GeomTraits>>& curves, double tolerance);

/// Repairs `curves` in place so that Mesh_3 accepts them as protected features:
/// removes non-finite and duplicate points; snaps ends within the tolerance to one shared point
/// (preferring an exactly shared end, then a point of `junction_hints`, such as the corners of
/// the curve network); closes loops whose ends meet; splits curves where an end or another
/// curve touches them; splits sharp turns; drops curves too short to mesh and curves that
/// duplicate a longer one; last, drops the shorter of two curves that still come closer than
/// the tolerance without sharing a point there (see `find_mesh_3_feature_problems()`). Normals stay attached to their points (a curve whose normals do not
/// match its points loses them). Corner indices are reset: they refer to the input network.
template <typename GeomTraits>
Curve_repair_report repair_feature_curves_for_mesh_3(
  std::vector<CGAL::Feature_polyline<GeomTraits>>& curves, const Curve_repair_options& options,
  const std::vector<typename GeomTraits::Point_3>& junction_hints = {})
{
  typedef CGAL::Feature_polyline<GeomTraits> Curve;
  typedef typename GeomTraits::Point_3 Point_3;
  using namespace repair_internal;

  Curve_repair_report report;
  report.input_curves = curves.size();
  const double tol = options.snap_tolerance;
  // points closer than this are the same point (relative to the snapping tolerance)
  const double merge_distance = 1e-3 * tol;

  for(Curve& c : curves) {
    if(!c.normals.empty() && c.normals.size() != c.points.size()) {
      c.normals.clear();
      ++report.discarded_normals;
    }
    c.front_corner = c.back_corner = Curve::no_corner;
    report.removed_points += remove_bad_points(c, merge_distance);
    densify(c, 0.5 * tol);
  }
  curves.erase(std::remove_if(curves.begin(), curves.end(),
                              [](const Curve& c) { return c.points.size() < 2; }),
               curves.end());

  // snapping may create zero-length pieces or duplicated points, splitting may create pieces
  // too short to mesh
  auto clean_up = [&]() {
    for(Curve& c : curves)
      report.removed_points += remove_bad_points(c, merge_distance);
    std::vector<Curve> kept;
    for(Curve& c : curves) {
      const bool closed = c.points.size() > 2 && c.points.front() == c.points.back();
      const double min_length = closed ? 3 * options.minimum_length : options.minimum_length;
      const bool degenerate = c.points.size() < 2 || (c.points.size() < 4 && closed) ||
                              (c.points.front() == c.points.back() && !closed);
      if(degenerate || curve_length(c) < min_length || curve_length(c) == 0) {
        ++report.dropped_short;
        continue;
      }
      kept.push_back(std::move(c));
    }
    curves = std::move(kept);
  };
  auto count_closed = [&]() {
    std::size_t n = 0;
    for(const Curve& c : curves)
      n += (c.points.size() > 3 && c.points.front() == c.points.back()) ? 1 : 0;
    return n;
  };

  if(tol > 0) {
    const std::size_t closed_before = count_closed();
    // each pass can leave new ends near others (a split moves a vertex, a dropped piece frees
    // an end): repeat until nothing is left to fix
    for(int pass = 0; pass < 4; ++pass) {
      snap_ends<Curve, Point_3>(curves, junction_hints, tol, report);
      if(pass == 0) {
        drop_covered_curves<Curve, Point_3>(curves, tol, report);
        drop_parallel_duplicates<Curve, Point_3>(curves, tol, report);
        // sharp turns first: the two legs of an acute turn are close, but they are not a contact
        split_sharp_turns(curves, tol, options.sharp_turn_angle, report);
      }
      split_at_ends_touching_interiors<Curve, Point_3>(curves, tol, report);
      resolve_interior_contacts<Curve, Point_3>(curves, tol, report);
      clean_up();
      if(find_mesh_3_feature_problems(curves, tol).empty())
        break;
    }
    const std::size_t closed_after = count_closed();
    report.closed_loops = closed_after > closed_before ? closed_after - closed_before : 0;
  } else {
    clean_up();
  }
  report.output_curves = curves.size();
  if(tol > 0)
    drop_feature_curves_in_contact(curves, tol, report);
  return report;
}

/// lists, one line each, the reasons Mesh_3 could reject `curves` as features: non-finite or
/// repeated consecutive points, ends that nearly (but not exactly) meet, ends or vertices
/// touching the interior of a curve, and vertices of two curves (or of one curve, far apart
/// along it) closer than `tolerance` without being one point, unless the curves leave a point
/// they share at `repair_internal::minimum_departure_angle` or more. An empty list means the
/// curves are safe to protect.
template <typename GeomTraits>
std::vector<std::string> find_mesh_3_feature_problems(
  const std::vector<CGAL::Feature_polyline<GeomTraits>>& curves, double tolerance)
{
  typedef typename GeomTraits::Point_3 Point_3;
  using namespace repair_internal;
  std::vector<std::string> problems;
  auto say = [&](std::size_t c, const std::string& what) {
    std::ostringstream line;
    line << "curve " << c << ": " << what;
    problems.push_back(line.str());
  };
  Spatial_grid<Point_3> ends(tolerance), interiors(tolerance);
  std::vector<std::pair<std::size_t, std::size_t>> interior_ids;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const auto& pts = curves[c].points;
    if(pts.size() < 2) {
      say(c, "fewer than two points");
      continue;
    }
    for(std::size_t i = 0; i < pts.size(); ++i) {
      if(!is_finite_point(pts[i]))
        say(c, "non-finite point");
      if(i > 0 && pts[i] == pts[i - 1])
        say(c, "repeated consecutive point");
    }
    if(pts.front() == pts.back() && pts.size() < 4)
      say(c, "closed with fewer than three distinct points");
    ends.insert(pts.front(), 2 * c);
    ends.insert(pts.back(), 2 * c + 1);
    for(std::size_t i = 1; i + 1 < pts.size(); ++i) {
      interiors.insert(pts[i], interior_ids.size());
      interior_ids.push_back(std::make_pair(c, i));
    }
  }
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const auto& pts = curves[c].points;
    if(pts.size() < 2)
      continue;
    for(int e = 0; e < 2; ++e) {
      const Point_3& q = e == 0 ? pts.front() : pts.back();
      ends.for_each_within(q, tolerance, [&](std::size_t other, double) {
        const auto& o = curves[other / 2].points;
        const Point_3& r = other % 2 == 0 ? o.front() : o.back();
        if(r != q && other / 2 >= c)
          say(c, "end nearly meets an end of curve " + std::to_string(other / 2) + " without sharing it");
      });
      interiors.for_each_within(q, tolerance * 1e-3, [&](std::size_t id, double) {
        say(c, "end lies on the interior of curve " + std::to_string(interior_ids[id].first));
      });
    }
  }
  for(const Unshared_contact& contact :
      find_unshared_contacts<CGAL::Feature_polyline<GeomTraits>, Point_3>(curves, tolerance)) {
    std::ostringstream what;
    what << "vertex " << contact.i << " is " << contact.distance << " from vertex " << contact.j
         << " of curve " << contact.b << " without sharing a point";
    say(contact.a, what.str());
  }
  return problems;
}

} // namespace sfe_meshing

#endif // SFE_MESHING_FEATURE_CURVE_REPAIR_H
