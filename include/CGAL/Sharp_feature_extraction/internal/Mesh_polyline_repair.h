// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The repair of `repair_polylines_for_mesh_3()`, on feature polylines (their normals follow
// their points): the steps that make polylines meet the contract of Mesh_polyline_contract.h.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_POLYLINE_REPAIR_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_POLYLINE_REPAIR_H

#include <CGAL/Sharp_feature_extraction/Mesh_3_polyline_repair_report.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_contract.h>
#include <CGAL/Sharp_feature_extraction/internal/Spatial_grid.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace mesh_polylines {

/// The repair's distances and angle.
struct Repair_settings
{
  /// Ends closer than this are one junction; an end this close to the interior of a curve
  /// splits that curve there; two curves this close elsewhere are made to meet.
  double tolerance = 0;
  /// Open curves shorter than this are dropped (closed loops: three times this perimeter).
  double minimum_length = 0;
  /// A curve that turns by more than this (degrees) is split there.
  double maximum_angle = Mesh_polyline_contract::sharp_turn_angle;
};

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
               Mesh_3_polyline_repair_report& report)
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
void split_at_ends_touching_interiors(std::vector<Curve>& curves, double tol, Mesh_3_polyline_repair_report& report)
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
        if(other.points.front() == q && s[v.second] < Mesh_polyline_contract::junction_arc * tol)
          return;
        if(other.points.back() == q && s.back() - s[v.second] < Mesh_polyline_contract::junction_arc * tol)
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
      // they leave at an acute angle (see `acute_departure_reach`): not a contact
      const Point_3& pb = curves[b.first].points[b.second];
      for(const Point_3* j : {&curves[a.first].points.front(), &curves[a.first].points.back()})
        if((*j == curves[b.first].points.front() || *j == curves[b.first].points.back()) &&
           point_distance(pa, *j) < Mesh_polyline_contract::acute_departure_reach * tol &&
           point_distance(pb, *j) < Mesh_polyline_contract::acute_departure_reach * tol)
          return;
      if(a.first == b.first && std::abs(arcs[a.first][a.second] - arcs[b.first][b.second]) < Mesh_polyline_contract::same_curve_separation * tol)
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
      while(end < cs.size() && cs[end].sa - cs[end - 1].sa < Mesh_polyline_contract::run_gap * tol)
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

/// removes the curves marked in `dropped`, keeping the others in order.
template <typename Curve>
void erase_marked(std::vector<Curve>& curves, const std::vector<bool>& dropped)
{
  std::vector<Curve> kept;
  for(std::size_t c = 0; c < curves.size(); ++c)
    if(!dropped[c])
      kept.push_back(std::move(curves[c]));
  curves = std::move(kept);
}

/// Two curves running closer than the tolerance for more than a few tolerances are one crease
/// found twice: the shorter goes.
template <typename Curve, typename Point_3>
void drop_parallel_duplicates(std::vector<Curve>& curves, double tol, Mesh_3_polyline_repair_report& report)
{
  std::vector<bool> dropped(curves.size(), false);
  for(const Close_run& run : find_close_runs<Curve, Point_3>(curves, tol, true)) {
    if(run.a == run.b || (run.extent_a <= Mesh_polyline_contract::duplicate_run_extent * tol &&
                          run.extent_b <= Mesh_polyline_contract::duplicate_run_extent * tol))
      continue;
    if(dropped[run.a] || dropped[run.b])
      continue;
    const std::size_t shorter = curve_length(curves[run.a]) < curve_length(curves[run.b]) ? run.a : run.b;
    dropped[shorter] = true;
    ++report.dropped_duplicates;
  }
  erase_marked(curves, dropped);
}

/// A curve lying mostly (see `covered_fraction`) within the tolerance of one longer curve is that
/// curve found twice, even when the two leave a shared junction at an acute angle (the
/// close-run test ignores junction neighbourhoods): it goes. Curves are densified, so vertex
/// counts measure length.
template <typename Curve, typename Point_3>
void drop_covered_curves(std::vector<Curve>& curves, double tol, Mesh_3_polyline_repair_report& report)
{
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
         nc.second >= Mesh_polyline_contract::covered_fraction * curves[a].points.size()) {
        dropped[a] = true;
        ++report.dropped_duplicates;
        break;
      }
  }
  erase_marked(curves, dropped);
}

/// Interior vertices of two curves (or of one curve, far apart along it) closer than the
/// tolerance over a short stretch: the curves cross or touch; they meet at the midpoint of the
/// closest pair, and both are split there.
template <typename Curve, typename Point_3>
void resolve_interior_contacts(std::vector<Curve>& curves, double tol, Mesh_3_polyline_repair_report& report)
{
  typedef std::pair<std::size_t, std::size_t> Vertex;
  std::map<std::size_t, std::vector<std::size_t>> splits;
  std::map<Vertex, Point_3> moves;
  for(const Close_run& run : find_close_runs<Curve, Point_3>(curves, tol, false)) {
    if(run.extent_a > Mesh_polyline_contract::duplicate_run_extent * tol ||
       run.extent_b > Mesh_polyline_contract::duplicate_run_extent * tol)
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

/// Splits where the curve turns by more than `angle_degrees` (see `sharp_turn_vertices()`).
template <typename Curve>
void split_sharp_turns(std::vector<Curve>& curves, double reach, double angle_degrees,
                       Mesh_3_polyline_repair_report& report)
{
  std::map<std::size_t, std::vector<std::size_t>> splits;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    splits[c] = sharp_turn_vertices(curves[c], reach, angle_degrees);
    report.sharp_turn_splits += splits[c].size();
  }
  apply_splits(curves, splits);
}

/// The curves a conflict names: two curves, or one curve twice (a curve in conflict with itself).
inline std::pair<std::size_t, std::size_t> conflicting_curves(const Unshared_contact& contact)
{
  return std::make_pair(contact.a, contact.b);
}

/// The curves a problem of `find_contract_violations()` names (see `conflicting_curves()`).
inline std::pair<std::size_t, std::size_t> conflicting_curves(const Mesh_3_polyline_problem& problem)
{
  return std::make_pair(problem.polyline, problem.other_polyline);
}

/// Before the last resort: where a curve still comes closer than the tolerance to another one
/// (or to itself, far along it) without sharing a point, the vertices in contact are cut out
/// of one of the two, which the other covers there within the tolerance: out of the shorter
/// curve, or of a curve touching itself, out of the pass nearer one of its ends (the tail
/// that went on past a loop). The rest stays, in pieces, where the last resort would drop the
/// whole curve. Counts the vertices removed in `report.removed_in_contact`.
template <typename Curve>
void cut_out_contacts(std::vector<Curve>& curves, const std::vector<Unshared_contact>& contacts,
                      Mesh_3_polyline_repair_report& report)
{
  std::vector<std::vector<double>> arcs;
  std::vector<std::vector<bool>> cut;
  for(const Curve& c : curves) {
    arcs.push_back(arc_lengths(c));
    cut.emplace_back(c.points.size(), false);
  }
  for(const Unshared_contact& contact : contacts) {
    bool in_a;
    if(contact.a == contact.b) {
      const std::vector<double>& s = arcs[contact.a];
      auto to_end = [&](std::size_t i) { return (std::min)(s[i], s.back() - s[i]); };
      in_a = to_end(contact.i) <= to_end(contact.j);
    }
    else
      in_a = arcs[contact.a].back() <= arcs[contact.b].back();
    if(in_a)
      cut[contact.a][contact.i] = true;
    else
      cut[contact.b][contact.j] = true;
  }
  std::vector<Curve> result;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const bool with_normals = curves[c].normals.size() == curves[c].points.size();
    Curve piece;
    auto end_piece = [&]() {
      if(piece.points.size() >= 2)
        result.push_back(std::move(piece));
      piece = Curve();
    };
    for(std::size_t i = 0; i < curves[c].points.size(); ++i) {
      if(cut[c][i]) {
        ++report.removed_in_contact;
        end_piece();
        continue;
      }
      piece.points.push_back(curves[c].points[i]);
      if(with_normals)
        piece.normals.push_back(curves[c].normals[i]);
    }
    end_piece();
  }
  curves = std::move(result);
}

/// The last resort against curves Mesh_3 cannot protect: of the two curves of each conflict
/// (an `Unshared_contact` or a `Mesh_3_polyline_problem`, see `conflicting_curves()`), the
/// shorter is dropped, unless one of them is dropped already; a curve in conflict with itself
/// is dropped. Without it that crease is meshed from the implicit surface alone; with it
/// Mesh_3 would shrink its protecting balls to the gap and not finish, or fail an assertion.
/// Counts the drops in `report.dropped_in_contact` and sets `report.output_polylines` to the
/// curves left.
template <typename Curve, typename Conflict>
void drop_shorter_of_conflicting_curves(std::vector<Curve>& curves, const std::vector<Conflict>& conflicts,
                                        Mesh_3_polyline_repair_report& report)
{
  std::vector<bool> dropped(curves.size(), false);
  for(const Conflict& conflict : conflicts) {
    const std::pair<std::size_t, std::size_t> c = conflicting_curves(conflict);
    if(dropped[c.first] || dropped[c.second])
      continue;
    dropped[curve_length(curves[c.first]) < curve_length(curves[c.second]) ? c.first : c.second] = true;
    ++report.dropped_in_contact;
  }
  erase_marked(curves, dropped);
  report.output_polylines = curves.size();
}

/// removes the non-finite and repeated points, and the normals that do not match the points;
/// inserts points so that no segment is longer than the densify fraction of the tolerance;
/// drops curves of fewer than two points. Corner indices are reset: they refer to the input.
template <typename Curve>
void prepare_points(std::vector<Curve>& curves, double tol, Mesh_3_polyline_repair_report& report)
{
  for(Curve& c : curves) {
    if(!c.normals.empty() && c.normals.size() != c.points.size()) {
      c.normals.clear();
      ++report.discarded_normals;
    }
    c.front_corner = c.back_corner = Curve::no_corner;
    report.removed_points += remove_bad_points(c, Mesh_polyline_contract::merge_fraction * tol);
    const std::size_t before = c.points.size();
    densify(c, Mesh_polyline_contract::densify_fraction * tol);
    report.inserted_points += c.points.size() - before;
  }
  curves.erase(std::remove_if(curves.begin(), curves.end(), [](const Curve& c) { return c.points.size() < 2; }),
               curves.end());
}

/// Snapping may create zero-length pieces or repeated points, splitting may create pieces too
/// short to mesh: removes the points, drops the curves (loops: below three times the length).
template <typename Curve>
void drop_degenerate_and_short(std::vector<Curve>& curves, const Repair_settings& settings,
                               Mesh_3_polyline_repair_report& report)
{
  for(Curve& c : curves)
    report.removed_points += remove_bad_points(c, Mesh_polyline_contract::merge_fraction * settings.tolerance);
  std::vector<Curve> kept;
  for(Curve& c : curves) {
    const bool closed = c.points.size() > 2 && c.points.front() == c.points.back();
    const double min_length = closed ? 3 * settings.minimum_length : settings.minimum_length;
    const bool degenerate = c.points.size() < 2 || (c.points.size() < Mesh_polyline_contract::min_loop_vertices && closed) ||
                            (c.points.front() == c.points.back() && !closed);
    if(degenerate || curve_length(c) < min_length || curve_length(c) == 0) {
      ++report.dropped_short;
      continue;
    }
    kept.push_back(std::move(c));
  }
  curves = std::move(kept);
}

template <typename Curve>
std::size_t count_closed_loops(const std::vector<Curve>& curves)
{
  std::size_t n = 0;
  for(const Curve& c : curves)
    n += (c.points.size() >= Mesh_polyline_contract::min_loop_vertices && c.points.front() == c.points.back()) ? 1 : 0;
  return n;
}

/// Repairs `curves` in place so that Mesh_3 accepts them as protected features:
/// removes non-finite and duplicate points; snaps ends within the tolerance to one shared point
/// (preferring an exactly shared end, then a point of `junction_hints`, such as the corners of
/// the curve network); closes loops whose ends meet; splits curves where an end or another
/// curve touches them; splits sharp turns; drops curves too short to mesh and curves that
/// duplicate a longer one; cuts the vertices where two curves still come closer than the
/// tolerance without sharing a point out of one of them (see `cut_out_contacts()`); last,
/// drops the shorter of two curves still in such contact (see
/// `find_mesh_3_polyline_problems()`).
/// Normals stay attached to their points (a curve whose normals do not match its points loses
/// them).
template <typename GeomTraits>
Mesh_3_polyline_repair_report repair_feature_polylines(std::vector<Feature_polyline<GeomTraits>>& curves,
                                                       const Repair_settings& settings,
                                                       const std::vector<typename GeomTraits::Point_3>& junction_hints = {})
{
  typedef Feature_polyline<GeomTraits> Curve;
  typedef typename GeomTraits::Point_3 Point_3;
  Mesh_3_polyline_repair_report report;
  report.input_polylines = curves.size();
  const double tol = settings.tolerance;
  prepare_points(curves, tol, report);
  if(!(tol > 0)) {
    drop_degenerate_and_short(curves, settings, report);
    report.output_polylines = curves.size();
    return report;
  }
  const std::size_t closed_before = count_closed_loops(curves);
  // each pass can leave new ends near others (a split moves a vertex, a dropped piece frees an
  // end): repeat until nothing is left to fix
  for(int pass = 0; pass < 4; ++pass) {
    snap_ends<Curve, Point_3>(curves, junction_hints, tol, report);
    if(pass == 0) {
      drop_covered_curves<Curve, Point_3>(curves, tol, report);
      drop_parallel_duplicates<Curve, Point_3>(curves, tol, report);
      // sharp turns first: the two legs of an acute turn are close, but they are not a contact
      split_sharp_turns(curves, tol, settings.maximum_angle, report);
    }
    split_at_ends_touching_interiors<Curve, Point_3>(curves, tol, report);
    resolve_interior_contacts<Curve, Point_3>(curves, tol, report);
    drop_degenerate_and_short(curves, settings, report);
    if(find_contract_violations(curves, Contract_tolerances{tol, settings.maximum_angle}).empty())
      break;
  }
  // Contacts left (a crossing at a shallow angle, a curve that overlaps itself): cut out, and
  // the new ends near the other curve join it as above. Each pass removes vertices; the passes
  // after the first only see the contacts that the joins of the one before made, and the rare
  // contact still left then is for the last resort below.
  constexpr int contact_cut_passes = 3;
  for(int pass = 0; pass < contact_cut_passes; ++pass) {
    const std::vector<Unshared_contact> contacts = find_unshared_contacts<Curve, Point_3>(curves, tol);
    if(contacts.empty())
      break;
    cut_out_contacts(curves, contacts, report);
    snap_ends<Curve, Point_3>(curves, junction_hints, tol, report);
    split_at_ends_touching_interiors<Curve, Point_3>(curves, tol, report);
    drop_degenerate_and_short(curves, settings, report);
  }
  const std::size_t closed_after = count_closed_loops(curves);
  report.closed_loops = closed_after > closed_before ? closed_after - closed_before : 0;
  // the last resort: two curves that still come closer than the tolerance without sharing a
  // point there (an unshared contact, as `find_mesh_3_polyline_problems()` lists them)
  drop_shorter_of_conflicting_curves(curves, find_unshared_contacts<Curve, Point_3>(curves, tol), report);
  return report;
}

} // namespace mesh_polylines
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_POLYLINE_REPAIR_H
