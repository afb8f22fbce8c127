// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 5 (paper 3.5, end-point analysis): gaps are bridged, missed corners created, loose ends
// attached to corners or left as dissipating features; then light Laplacian smoothing and the
// guarantees Mesh_3 needs (shared corner points, exactly closed loops, sharp turns split).

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_COMPLETION_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_COMPLETION_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_3_ready_network.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_contract.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

struct Completion_constants
{
  /// Vertices used to estimate the tangent at an end.
  static constexpr std::size_t tangent_vertices = 6;
  /// A curve turning by more than this angle (degrees) at a vertex is split there: the Mesh_3
  /// contract's (Mesh_3 rounds such a turn off).
  static constexpr double sharp_turn_angle = mesh_polylines::Mesh_polyline_contract::sharp_turn_angle;
  /// Laplacian step: the fraction of the way to the weighted average of the two neighbours.
  static constexpr double laplacian_step = 0.5;
  /// Second, inflating step of each pass (Taubin's lambda|mu smoothing, SIGGRAPH 1995): a
  /// plain Laplacian step moves a vertex of a curve of radius R sampled every s by
  /// laplacian_step * s^2 / (2 R) towards the centre, and under noise, where the vertices lie a
  /// growth radius apart, that shrinks a 0.2 dB circle by 0.5% dB in two passes. With the
  /// negative step, slightly larger in magnitude, smooth bends keep their size (pass-band
  /// 1/laplacian_step + 1/inflation_step = 0.11) while vertex-to-vertex zigzag is still damped.
  static constexpr double inflation_step = -0.53;
  /// Free-ended curves shorter than this, relative to the growth radius, are noise.
  static constexpr double min_length = 4;
  /// A short spur is dropped at a corner where the other two curves turn by less than this
  /// angle (degrees): one crease crossed by a fragment. Below the 45-degree turns where a
  /// chamfer's end meets the faces, whose short creases are real.
  static constexpr double spur_crossing_turn_angle = 30;
  /// Passes over all ends; each pass stops at the first change.
  static constexpr std::size_t max_rounds = 10000;
  /// An end looks for targets on its own curve only farther along it than this many completion
  /// distances: nearer vertices are the same stretch of crease, bending.
  static constexpr double own_curve_skip = 2;
  /// Vertices closer than this (relative to the growth radius) count as coincident in the
  /// inverse-distance weights of the Laplacian smoothing.
  static constexpr double coincident_vertex_distance = 1e-12;
  /// Smallest eigenvalue of the junction system (a sum of projectors): below it the tangents
  /// are too close to parallel to define where they cross.
  static constexpr double junction_conditioning = 0.05;
  /// A corner is re-placed where the lines of its curves meet. Each line goes through the
  /// vertices from `corner_fit_skip` to `corner_fit_skip + corner_fit_window` growth radii
  /// of arc length away from the corner: the nearest vertices are biased (their stage-2
  /// neighbourhoods hold the third surface, and the smoothing stops at the corner), and farther
  /// ones follow the bend of a curved crease. The window also ends `corner_fit_skip` before a
  /// corner at the curve's other end, whose nearest vertices are biased in the same way: a
  /// short curve between two corners (the top edge of a gear tooth, two corners 1.7% dB apart
  /// on CGAL's pinion) would otherwise tilt the line of one corner towards the other.
  static constexpr double corner_fit_skip = 0.5;
  static constexpr double corner_fit_window = 3;
  /// Corners with at most this many curves are placed on the crease lines of their curves'
  /// normals, those with more on the lines through their vertices (see `place_corners()`): a
  /// corner of three faces (a box's, a gear tooth's) has three creases.
  static constexpr std::size_t max_valence_on_normals = 3;
  /// A corner of valence 4 is two corners merged (see `split_merged_corners()`) only if the
  /// segment between the two corners it splits into runs along the crease line of the two
  /// surfaces that the segment separates within this angle (degrees). The angle between two
  /// normal pairs of one crease (`same_crease_normal_angle`): a direction fixed by two normals
  /// is as uncertain as they are.
  static constexpr double merged_corner_link_angle = same_crease_normal_angle;
  /// A curve ends where stage 4 lost its crease: the normals at a curve's end are those of a
  /// growth that failed. Where two strands of one crease overlap, measured on CGAL's rotor and
  /// spool at 0.5% noise, one normal of such a pair stays within a few degrees of the other
  /// strand's and the other is off by 30 to 43 degrees; at the valence-2 corners that cut the
  /// holes of CGAL's anchor into 2 to 5 curves at 0.5% noise, one within 18 and the other off by
  /// 17 to 56 (17 of 18 corners within this angle). Two curve ends belong to one crease when one
  /// normal matches within `same_crease_normal_angle` and the other within this angle (degrees).
  /// Parallel creases that share one surface differ more in the other: the two edges of a
  /// chamfer each turn by at least the sharpness angle (25 degrees by default), so their
  /// unshared normals are at least twice that apart, and the two sides of a thin wall face
  /// opposite ways.
  static constexpr double end_normal_angle = 2 * same_crease_normal_angle;
  /// An end goes to a corner in reach rather than to a curve vertex nearer to it by less than
  /// this many noise deviations (`Sharp_feature_scales::noise`): the two are as near as the
  /// noise can tell, and a vertex beside a corner would split its curve into a stub one
  /// segment long. On a cube at 0.5% noise, an end that stopped short of a corner reached the
  /// second vertex of another curve of that corner first, and the corner came out as two
  /// corners 0.4% dB apart joined by a stub.
  static constexpr double corner_preference_noise = 2;
  /// A closed curve has at least this many vertices (three distinct, the first repeated last):
  /// the Mesh_3 contract's.
  static constexpr std::size_t min_closed_curve_vertices = mesh_polylines::Mesh_polyline_contract::min_loop_vertices;
};

inline double curve_length(const Working_polyline& c)
{
  double length = 0;
  for(std::size_t i = 1; i < c.points.size(); ++i)
    length += (c.points[i] - c.points[i - 1]).norm();
  return length;
}

/// Whether curve `c` turns by more than `Completion_constants::sharp_turn_angle` at its interior
/// vertex `v`; a segment of length zero has no direction and makes no turn.
inline bool turns_sharply(const Working_polyline& c, std::size_t v)
{
  const Vec3 a = c.points[v] - c.points[v - 1], b = c.points[v + 1] - c.points[v];
  return a.norm() > 0 && b.norm() > 0
         && a.normalized().dot(b.normalized()) < std::cos(radians(Completion_constants::sharp_turn_angle));
}

/// Whether the sharp turn of curve `c` at its interior vertex `v` is a spike: the segments
/// before and after the turn, and the chord that skips `v`, all run the same way (within
/// `Completion_constants::sharp_turn_angle` of each other). The curve leaves its line at `v`
/// alone and returns to it: `v` is an edge point that stage 4 took from the noise beside the
/// crease, not a corner. A corner turns for good, and a short zigzag between two corners (the
/// top edge of a gear tooth) leaves in the opposite direction. Needs two vertices on each side.
inline bool is_spike(const Working_polyline& c, std::size_t v)
{
  if(v < 2 || v + 2 >= c.points.size())
    return false;
  const Vec3 before = c.points[v - 1] - c.points[v - 2], after = c.points[v + 2] - c.points[v + 1],
             chord = c.points[v + 1] - c.points[v - 1];
  const double cos_sharp = std::cos(radians(Completion_constants::sharp_turn_angle));
  auto same_way = [cos_sharp](const Vec3& a, const Vec3& b) {
    return a.norm() > 0 && b.norm() > 0 && a.normalized().dot(b.normalized()) > cos_sharp;
  };
  return same_way(before, after) && same_way(before, chord) && same_way(chord, after);
}

/// The least-squares line through `points` (at least two): their centroid and unit principal
/// direction; false if the direction is undefined (coincident points).
inline bool fit_line(const std::vector<Vec3>& points, Vec3& centroid, Vec3& direction)
{
  fit_principal_line(points.size(), [&](std::size_t j) -> const Vec3& { return points[j]; }, centroid, direction);
  return direction.allFinite();
}

/// Outward unit tangent at the front (`back == false`) or back end of an open curve.
inline Vec3 end_tangent(const Working_polyline& c, bool back)
{
  const std::size_t n = c.points.size();
  const std::size_t m = (std::min)(Completion_constants::tangent_vertices, n);
  auto at = [&](std::size_t k) -> const Vec3& { return back ? c.points[n - 1 - k] : c.points[k]; };
  std::vector<Vec3> last(m);
  for(std::size_t k = 0; k < m; ++k)
    last[k] = at(k);
  Vec3 centroid, t;
  if(!fit_line(last, centroid, t))
    t = (at(0) - at(m - 1)).normalized();
  return t.dot(at(0) - at(m - 1)) >= 0 ? t : Vec3(-t);
}

inline void reverse_curve(Working_polyline& c)
{
  std::reverse(c.points.begin(), c.points.end());
  std::reverse(c.normals.begin(), c.normals.end());
  std::swap(c.front_corner, c.back_corner);
}

/// Removes the vertices before the back end of `c` from which the curve turns sharply to reach
/// its next vertex, last first (the end itself stays).
inline void drop_sharp_turns_before_back(Working_polyline& c)
{
  while(c.points.size() > 2 && turns_sharply(c, c.points.size() - 2))
  {
    c.points.erase(c.points.end() - 2);
    c.normals.erase(c.normals.end() - 2);
  }
}

/// `a` followed by `b` (which must start where the joining segment ends).
inline void append_curve(Working_polyline& a, const Working_polyline& b)
{
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  a.back_corner = b.back_corner;
}

class Curve_completion
{
  typedef Completion_constants Constants;

public:
  Curve_completion(Working_network& network, const Completion_parameters& parameters)
    : m_net(network), m_scales(network.scales), m_parameters(parameters),
      m_cos_aperture(std::cos(radians(parameters.aperture)))
  {}

  void run()
  {
    drop_short_free_curves();
    // End analysis, one change at a time: every change renumbers curves and vertices.
    std::vector<std::pair<std::size_t, bool>> dissipating;
    for(std::size_t round = 0; round < Constants::max_rounds; ++round)
    {
      bool changed = false;
      for(std::size_t c = 0; c < m_net.polylines.size() && !changed; ++c)
        for(bool back : {false, true})
        {
          if(!is_free_end(c, back)
             || std::find(dissipating.begin(), dissipating.end(), std::make_pair(c, back)) != dissipating.end())
            continue;
          if(resolve_end(c, back))
          {
            changed = true;
            dissipating.clear();
            break;
          }
          dissipating.emplace_back(c, back);
        }
      if(!changed)
        break;
    }
    join_converging_ends();
    clean_corners();
    // Stage 4 attached curves to the corner points of stage 2, which the noise moves off the
    // crease lines: the vertex next to such a corner may turn sharply to reach it. As where
    // the end analysis attaches a curve to a corner (`attach_to_corner()`), that vertex is
    // dropped, not made a corner of its own: on the noisy stepped box of the tests (0.5% noise),
    // a corner 1% dB from the true one came out, joined to it by a curve of one segment.
    for(Working_polyline& c : m_net.polylines)
      drop_sharp_end_vertices(c);
    split_sharp_turns();
    for(unsigned int pass = 0; pass < m_parameters.laplacian_passes; ++pass)
      for(Working_polyline& c : m_net.polylines)
      {
        laplacian_step(c, Constants::laplacian_step);
        laplacian_step(c, Constants::inflation_step);
      }
    split_merged_corners();
    place_corners();
    finalize();
  }

private:
  Working_network& m_net;
  const Scales& m_scales;
  const Completion_parameters& m_parameters;
  double m_cos_aperture;

  bool is_free_end(std::size_t c, bool back) const
  {
    const Working_polyline& curve = m_net.polylines[c];
    return !is_loop_without_corner(curve) && (back ? curve.back_corner : curve.front_corner) == no_index;
  }

  void drop_short_free_curves()
  {
    std::vector<Working_polyline> kept;
    for(Working_polyline& c : m_net.polylines)
      if(is_loop_without_corner(c) || c.front_corner != no_index || c.back_corner != no_index
         || curve_length(c) >= Constants::min_length * m_scales.growth_radius)
        kept.push_back(std::move(c));
    m_net.polylines.swap(kept);
  }

  struct Target
  {
    std::size_t curve = no_index, vertex = no_index, corner = no_index;
    double distance = std::numeric_limits<double>::infinity();
  };

  // The closest curve vertex or corner inside the search cone of an end (paper Fig. 8); a corner
  // wins over a vertex nearer by less than the noise can tell (see `corner_preference_noise`).
  Target find_target(std::size_t c, bool back, const Vec3& end, const Vec3& tangent) const
  {
    Target best;
    const double reach = m_scales.completion_distance;
    auto in_cone = [&](const Vec3& q, double& d) {
      const Vec3 v = q - end;
      d = v.norm();
      return d > 0 && d <= reach && v.dot(tangent) >= m_cos_aperture * d;
    };
    // A corner within a growth radius is reached whatever the direction: the end stopped beside
    // it or overshot it (past a concave corner the crease line of two of its faces goes on, and
    // so do the edge points of the noise there), and its tangent no longer points at it.
    for(std::size_t k = 0; k < m_net.corners.size(); ++k)
    {
      double d;
      const bool ahead = in_cone(m_net.corners[k].point, d);
      if((ahead || d <= m_scales.growth_radius) && d < best.distance)
        best = Target{no_index, no_index, k, d};
    }
    const Target corner = best;
    for(std::size_t d_index = 0; d_index < m_net.polylines.size(); ++d_index)
    {
      const Working_polyline& other = m_net.polylines[d_index];
      const std::size_t n = other.points.size();
      for(std::size_t v = 0; v < n; ++v)
      {
        if(d_index == c)
        {
          // On its own curve, an end only sees the other end, or vertices far along the curve.
          const std::size_t from_end = back ? n - 1 - v : v;
          const bool other_end = from_end == n - 1;
          if(!other_end && arc_length_from_end(other, back, from_end) < Constants::own_curve_skip * reach)
            continue;
        }
        double d;
        if(in_cone(other.points[v], d) && d < best.distance)
          best = Target{d_index, v, no_index, d};
      }
    }
    if(corner.corner != no_index && corner.distance <= best.distance + Constants::corner_preference_noise * m_scales.noise)
      return corner;
    return best;
  }

  static double arc_length_from_end(const Working_polyline& c, bool back, std::size_t steps)
  {
    double length = 0;
    const std::size_t n = c.points.size();
    for(std::size_t k = 0; k < steps; ++k)
    {
      const std::size_t a = back ? n - 1 - k : k, b = back ? n - 2 - k : k + 1;
      length += (c.points[a] - c.points[b]).norm();
    }
    return length;
  }

  std::size_t add_corner(const Vec3& point, const std::array<Vec3, 2>& normals)
  {
    m_net.corners.push_back(Working_corner{point, {normals[0], normals[1]}});
    return m_net.corners.size() - 1;
  }

  void attach_to_corner(std::size_t c, bool back, std::size_t corner)
  {
    Working_polyline& curve = m_net.polylines[c];
    if(!back)
      reverse_curve(curve);
    // An end that overshot the corner (e.g. past a concave corner) is cut back to it, so that
    // the curve does not fold back on itself.
    const Vec3 point = m_net.corners[corner].point;
    while(curve.points.size() > 2)
    {
      const std::size_t n = curve.points.size();
      if((point - curve.points[n - 1]).dot(curve.points[n - 1] - curve.points[n - 2]) >= 0)
        break;
      curve.points.pop_back();
      curve.normals.pop_back();
    }
    curve.points.push_back(point);
    curve.normals.push_back(curve.normals.back());
    curve.back_corner = corner;
    drop_sharp_turns_before_back(curve);
    if(!back)
      reverse_curve(curve);
  }

  // Resolves one free end; returns true if the network changed.
  bool resolve_end(std::size_t c, bool back)
  {
    Working_polyline& curve = m_net.polylines[c];
    const Vec3 end = back ? curve.points.back() : curve.points.front();
    const Vec3 tangent = end_tangent(curve, back);
    const Target target = find_target(c, back, end, tangent);
    if(target.distance == std::numeric_limits<double>::infinity())
      return false; // (c) a dissipating feature end
    if(target.corner != no_index)
    {
      attach_to_corner(c, back, target.corner);
      return true;
    }
    Working_polyline& other = m_net.polylines[target.curve];
    const std::size_t n = other.points.size();
    const bool at_end = !is_loop_without_corner(other) && (target.vertex == 0 || target.vertex == n - 1);
    if(at_end)
    {
      const bool other_back = target.vertex == n - 1;
      if(!is_free_end(target.curve, other_back))
      {
        attach_to_corner(c, back, other_back ? other.back_corner : other.front_corner);
        return true;
      }
      const Vec3 other_tangent = end_tangent(other, other_back);
      if(other_tangent.dot(tangent) <= -m_cos_aperture)
      {
        // (a) a gap between two ends that face each other
        if(target.curve == c)
        {
          curve.points.push_back(curve.points.front());
          curve.normals.push_back(curve.normals.front());
        }
        else
          merge_ends(c, back, target.curve, other_back);
        return true;
      }
      // Two ends meeting at an angle: a corner the projection missed, where their tangents cross.
      if(create_junction(Free_end{c, back, end, tangent}, Free_end{target.curve, other_back, other.points[target.vertex], other_tangent}))
        return true;
      const std::size_t corner = add_corner(other.points[target.vertex], other.normals[target.vertex]);
      (other_back ? other.back_corner : other.front_corner) = corner;
      attach_to_corner(c, back, corner);
      return true;
    }
    // An end that runs along the curve it reached lies beside it (another strand of the same
    // crease, or a parallel crease), not across it: that is no junction, and a corner there
    // would cut the other curve in two.
    if(runs_along(other, target.vertex, tangent))
      return merge_overlapping_strands(c, back, target.curve, target.vertex, tangent);
    // (b) corner creation on an interior vertex
    const std::size_t corner = add_corner(other.points[target.vertex], other.normals[target.vertex]);
    split_at(target.curve, target.vertex, corner);
    attach_to_corner(c, back, corner);
    return true;
  }

  /// Direction of curve `c` at its vertex `v` (not normalized; zero where it is undefined).
  static Vec3 direction_at(const Working_polyline& c, std::size_t v)
  {
    const std::size_t n = c.points.size();
    return c.points[(std::min)(v + 1, n - 1)] - c.points[v > 0 ? v - 1 : 0];
  }

  /// Whether curve `c` runs along `tangent` at its vertex `v`, either way, within the aperture
  /// of the search cone.
  bool runs_along(const Working_polyline& c, std::size_t v, const Vec3& tangent) const
  {
    const Vec3 direction = direction_at(c, v);
    return direction.norm() > 0 && std::abs(direction.normalized().dot(tangent)) >= m_cos_aperture;
  }

  /// Whether a vertex at `point` with the normal pair `normals` lies on the crease of curve `c`:
  /// within a growth radius of it (stage 4 gathers the edge points of one crease within that
  /// radius, so two strands of it lie closer), with the normal pair of its nearest vertex, one
  /// normal closely and the other loosely (see `end_normal_angle`; two parallel creases
  /// that close, such as the two edges of a narrow chamfer or of a thin wall, share only one
  /// surface).
  bool on_crease_of(const Working_polyline& c, const Vec3& point, const std::array<Vec3, 2>& normals) const
  {
    double distance = std::numeric_limits<double>::infinity(), to_nearest_vertex = distance;
    std::size_t nearest = 0;
    for(std::size_t k = 0; k < c.points.size(); ++k)
    {
      const double to_vertex = (point - c.points[k]).norm();
      if(to_vertex < to_nearest_vertex)
      {
        to_nearest_vertex = to_vertex;
        nearest = k;
      }
      distance = (std::min)(distance, to_vertex);
      if(k + 1 < c.points.size())
      {
        const Vec3 segment = c.points[k + 1] - c.points[k];
        const double t = segment.squaredNorm() > 0 ? (point - c.points[k]).dot(segment) / segment.squaredNorm() : 0;
        if(t > 0 && t < 1)
          distance = (std::min)(distance, (point - c.points[k] - t * segment).norm());
      }
    }
    return distance <= m_scales.growth_radius
           && match_normal_pairs_unevenly(c.normals[nearest], normals, std::cos(radians(same_crease_normal_angle)),
                                          std::cos(radians(Constants::end_normal_angle)));
  }

  // The end (`c`, `back`) reached vertex `v` of curve `d` (possibly `c` itself), along which it
  // runs. On its own curve, the stretch behind `v` (on the end's side), up to the other end,
  // went once around a loop and on beside the curve's start: it is dropped and the loop closes
  // (or, if the other end is at a corner, the end joins that corner). On another curve, if that
  // stretch, up to a free end of `d` (or one at a corner that no other curve reaches), lies on
  // the crease of the end's curve, the two are strands of one crease that overlap like
  // shingles: it is dropped and the end joins the rest of `d`.
  // Otherwise nothing changes (the end is left as it is) and the result is false.
  bool merge_overlapping_strands(std::size_t c, bool back, std::size_t d, std::size_t v, const Vec3& tangent)
  {
    Working_polyline& strand = m_net.polylines[d];
    if(is_loop_without_corner(strand))
      return false;
    const std::size_t n = strand.points.size();
    // The vertices [0, v) lie behind v if the strand's order follows the end's tangent there.
    const bool behind_is_front = direction_at(strand, v).dot(tangent) > 0;
    if(d == c && behind_is_front != back)
      return false; // on its own curve, only its other end can lie behind
    std::size_t behind_corner = behind_is_front ? strand.front_corner : strand.back_corner;
    // A corner that only the strand reaches is none (`clean_corners()` drops it in the end): a
    // corner point that stage 2 found in the noise beside the crease, where stage 4 ended one
    // strand. It does not keep the strands apart.
    if(d != c && behind_corner != no_index && incidences()[behind_corner].size() == 1)
      behind_corner = no_index;
    if(d == c && behind_corner != no_index)
    {
      attach_to_corner(c, back, behind_corner);
      return true;
    }
    if(behind_corner != no_index || (behind_is_front ? v == 0 : v + 1 == n))
      return false;
    const std::size_t first = behind_is_front ? 0 : v + 1, last = behind_is_front ? v - 1 : n - 1;
    if(d != c)
      for(std::size_t k = first; k <= last; ++k)
        if(!on_crease_of(m_net.polylines[c], strand.points[k], strand.normals[k]))
          return false;
    (behind_is_front ? strand.front_corner : strand.back_corner) = no_index;
    strand.points.erase(strand.points.begin() + std::ptrdiff_t(first), strand.points.begin() + std::ptrdiff_t(last + 1));
    strand.normals.erase(strand.normals.begin() + std::ptrdiff_t(first), strand.normals.begin() + std::ptrdiff_t(last + 1));
    if(d == c)
    {
      strand.points.push_back(strand.points.front());
      strand.normals.push_back(strand.normals.front());
    }
    else
      merge_ends(c, back, d, !behind_is_front);
    return true;
  }

  struct Free_end
  {
    std::size_t curve;
    bool back;
    Vec3 point, tangent;
  };

  std::vector<Free_end> free_ends() const
  {
    std::vector<Free_end> ends;
    for(std::size_t c = 0; c < m_net.polylines.size(); ++c)
      for(bool back : {false, true})
        if(is_free_end(c, back))
        {
          const Working_polyline& curve = m_net.polylines[c];
          ends.push_back(Free_end{c, back, back ? curve.points.back() : curve.points.front(), end_tangent(curve, back)});
        }
    return ends;
  }

  // The point closest, in the least-squares sense, to the tangent lines of `ends`.
  static bool junction_point(const std::vector<Free_end>& ends, Vec3& x)
  {
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Vec3 b = Vec3::Zero();
    for(const Free_end& e : ends)
    {
      const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - e.tangent * e.tangent.transpose();
      a += projector;
      b += projector * e.point;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
    if(solver.eigenvalues()[0] < Constants::junction_conditioning)
      return false;
    x = a.ldlt().solve(b);
    return x.allFinite();
  }

  // Whether the ray of end `e` reaches `x`: ahead (or barely behind), within the completion
  // distance, and inside the search cone or a growth radius of the ray.
  bool ray_reaches(const Free_end& e, const Vec3& x) const
  {
    const Vec3 d = x - e.point;
    const double along = d.dot(e.tangent);
    if(along < -m_scales.growth_radius || along > m_scales.completion_distance)
      return false;
    const double off = (d - along * e.tangent).norm();
    return off <= (std::max)(m_scales.growth_radius, std::tan(radians(m_parameters.aperture)) * along);
  }

  // Creates a corner where the rays of `a`, `b` and every other free end reaching the same point
  // cross, and attaches all of them. Returns false if the rays of `a` and `b` do not meet.
  bool create_junction(const Free_end& a, const Free_end& b)
  {
    std::vector<Free_end> group = {a, b};
    Vec3 x;
    if(!junction_point(group, x) || !ray_reaches(a, x) || !ray_reaches(b, x))
      return false;
    for(const Free_end& e : free_ends())
      if(!(e.curve == a.curve && e.back == a.back) && !(e.curve == b.curve && e.back == b.back) && ray_reaches(e, x))
        group.push_back(e);
    if(group.size() > 2 && !junction_point(group, x))
      return false;
    Working_corner node{x, {}};
    for(const Free_end& e : group)
    {
      const std::array<Vec3, 2>& n = end_normals(m_net.polylines[e.curve], e.back);
      node.normals.push_back(n[0]);
      node.normals.push_back(n[1]);
    }
    m_net.corners.push_back(node);
    for(const Free_end& e : group)
      attach_to_corner(e.curve, e.back, m_net.corners.size() - 1);
    return true;
  }

  // Free ends left after the end analysis may still converge on a corner that none of them
  // sees inside its cone (e.g. each 45 degrees off the other's tangent): join the closest pairs.
  void join_converging_ends()
  {
    const double cos_aperture = m_cos_aperture;
    for(bool joined = true; joined;)
    {
      joined = false;
      const std::vector<Free_end> ends = free_ends();
      double best_cost = std::numeric_limits<double>::infinity();
      std::size_t best_i = 0, best_j = 0;
      for(std::size_t i = 0; i < ends.size(); ++i)
        for(std::size_t j = i + 1; j < ends.size(); ++j)
        {
          const double cos_between = ends[i].tangent.dot(ends[j].tangent);
          if(cos_between > cos_aperture || cos_between < -cos_aperture)
            continue; // same direction, or facing each other (a gap, not a corner)
          Vec3 x;
          if(!junction_point({ends[i], ends[j]}, x) || !ray_reaches(ends[i], x) || !ray_reaches(ends[j], x))
            continue;
          const double cost = (x - ends[i].point).norm() + (x - ends[j].point).norm();
          if(cost < best_cost)
          {
            best_cost = cost;
            best_i = i;
            best_j = j;
          }
        }
      if(best_cost < std::numeric_limits<double>::infinity())
        joined = create_junction(ends[best_i], ends[best_j]);
    }
  }

  void merge_ends(std::size_t c, bool back, std::size_t d, bool other_back)
  {
    Working_polyline a = m_net.polylines[c], b = m_net.polylines[d];
    if(!back)
      reverse_curve(a);
    if(other_back)
      reverse_curve(b);
    append_curve(a, b);
    m_net.polylines[c] = std::move(a);
    m_net.polylines.erase(m_net.polylines.begin() + d);
  }

  void split_at(std::size_t d, std::size_t vertex, std::size_t corner)
  {
    Working_polyline& curve = m_net.polylines[d];
    if(is_loop_without_corner(curve))
    {
      // Re-open the loop at the corner: it starts and ends there.
      Working_polyline open;
      const std::size_t m = curve.points.size() - 1;
      for(std::size_t k = 0; k <= m; ++k)
      {
        open.points.push_back(curve.points[(vertex + k) % m]);
        open.normals.push_back(curve.normals[(vertex + k) % m]);
      }
      open.front_corner = open.back_corner = corner;
      curve = std::move(open);
      return;
    }
    Working_polyline second;
    second.points.assign(curve.points.begin() + vertex, curve.points.end());
    second.normals.assign(curve.normals.begin() + vertex, curve.normals.end());
    second.front_corner = corner;
    second.back_corner = curve.back_corner;
    curve.points.resize(vertex + 1);
    curve.normals.resize(vertex + 1);
    curve.back_corner = corner;
    m_net.polylines.push_back(std::move(second));
  }

  std::vector<std::vector<std::pair<std::size_t, bool>>> incidences() const
  {
    std::vector<std::vector<std::pair<std::size_t, bool>>> at(m_net.corners.size());
    for(std::size_t c = 0; c < m_net.polylines.size(); ++c)
    {
      if(m_net.polylines[c].front_corner != no_index)
        at[m_net.polylines[c].front_corner].emplace_back(c, false);
      if(m_net.polylines[c].back_corner != no_index)
        at[m_net.polylines[c].back_corner].emplace_back(c, true);
    }
    return at;
  }

  // Corners with fewer than two curves are not corners; a corner with two curves that continue
  // each other (turning by less than the sharp-turn angle) is not one either: merge through it.
  void clean_corners()
  {
    for(bool changed = true; changed;)
    {
      changed = drop_short_corner_loops() || drop_short_spurs();
      const auto at = incidences();
      for(std::size_t k = 0; k < at.size() && !changed; ++k)
      {
        if(at[k].size() == 1)
        {
          Working_polyline& c = m_net.polylines[at[k][0].first];
          (at[k][0].second ? c.back_corner : c.front_corner) = no_index;
          changed = true;
        }
        else if(at[k].size() == 2)
        {
          const auto [c0, b0] = at[k][0];
          const auto [c1, b1] = at[k][1];
          // A valence-2 corner is kept only where the curve turns sharply (see split_sharp_turns),
          // and not where that turn is one crease bending.
          const bool straight = continue_each_other(at[k][0], at[k][1]);
          if(!straight && !bend_of_one_crease(at[k][0], at[k][1]))
            continue;
          // Through a bend, the corner point is dropped: the curve would turn sharply there. (It
          // lies where the ends' tangent lines cross, outside the bend, or where stage 2 fitted
          // two planes to the bent surface.)
          if(c0 == c1)
          {
            Working_polyline& c = m_net.polylines[c0];
            c.front_corner = c.back_corner = no_index;
            if(!straight && c.points.size() > Constants::min_closed_curve_vertices)
            {
              c.points.erase(c.points.begin());
              c.normals.erase(c.normals.begin());
              c.normals.back() = c.normals.front();
            }
            c.points.back() = c.points.front();
          }
          else
          {
            Working_polyline& a = m_net.polylines[c0];
            Working_polyline b = m_net.polylines[c1];
            if(!b0)
              reverse_curve(a);
            if(b1)
              reverse_curve(b);
            a.back_corner = no_index;
            if(!straight && a.points.size() > 2 && b.points.size() > 2)
            {
              a.points.pop_back();
              a.normals.pop_back();
            }
            b.points.erase(b.points.begin());
            b.normals.erase(b.normals.begin());
            append_curve(a, b);
            m_net.polylines.erase(m_net.polylines.begin() + c1);
          }
          changed = true;
        }
      }
    }
    remove_unused_corners();
  }

  // How far (degrees) the curves of two ends at a corner turn there: the angle between the
  // tangent into the corner along one and the tangent out of it along the other. Zero where a
  // curve is too short to have a tangent.
  double turn_at_corner(const std::pair<std::size_t, bool>& a, const std::pair<std::size_t, bool>& b) const
  {
    const Working_polyline& ca = m_net.polylines[a.first];
    const Working_polyline& cb = m_net.polylines[b.first];
    if(ca.points.size() < 2 || cb.points.size() < 2)
      return 0;
    return angle_between(end_tangent(ca, a.second), -end_tangent(cb, b.second));
  }

  // Whether the curves of two ends at a corner continue each other there: they turn by less
  // than `turn_angle` (degrees).
  bool continue_each_other(const std::pair<std::size_t, bool>& a, const std::pair<std::size_t, bool>& b,
                           double turn_angle = Constants::sharp_turn_angle) const
  {
    const Working_polyline& ca = m_net.polylines[a.first];
    const Working_polyline& cb = m_net.polylines[b.first];
    return ca.points.size() >= 2 && cb.points.size() >= 2 && turn_at_corner(a, b) <= turn_angle;
  }

  // Whether two curves that turn sharply at a valence-2 corner are one crease bending there (a
  // curved crease, such as the rim of a hole, that stage 4 left in pieces), not two creases
  // meeting where a third was lost. Their ends share one surface, their other normals match
  // loosely (`end_normal_angle`), and the turn is not the normals': where two creases of a
  // surface meet, the crease line (the cross product of the normals) turns about the shared
  // normal as far as the unshared normals do, whereas the tangents of a tight bend, fitted over
  // a few vertices on each side of a gap, turn more than the surfaces between its ends (at the
  // corners that cut the anchor's holes, 73 to 110 degrees against 17 to 56). A turn that
  // exceeds the normals' by more than `same_crease_normal_angle` is the bend's. Two chamfers
  // of 30 degrees meeting at a right angle turn as far as their normals do and keep their
  // corner.
  bool bend_of_one_crease(const std::pair<std::size_t, bool>& a, const std::pair<std::size_t, bool>& b) const
  {
    const std::array<Vec3, 2>& na = end_normals(m_net.polylines[a.first], a.second);
    const std::array<Vec3, 2>& nb_raw = end_normals(m_net.polylines[b.first], b.second);
    if(!match_normal_pairs_unevenly(na, nb_raw, std::cos(radians(same_crease_normal_angle)),
                                    std::cos(radians(Constants::end_normal_angle))))
      return false;
    const std::array<Vec3, 2> nb = align_normal_pair(na, nb_raw);
    const std::size_t shared = na[0].dot(nb[0]) >= na[1].dot(nb[1]) ? 0 : 1, other = 1 - shared;
    const Vec3 axis = (na[shared] + nb[shared]).normalized();
    const Vec3 across_a = na[other] - na[other].dot(axis) * axis, across_b = nb[other] - nb[other].dot(axis) * axis;
    if(across_a.norm() == 0 || across_b.norm() == 0)
      return false;
    return turn_at_corner(a, b) > angle_between(across_a, across_b) + same_crease_normal_angle;
  }

  // A curve that leaves a corner and returns to it within a growth radius follows no crease: a
  // fragment of stage 4 beside the corner, both of whose ends reached it in the end analysis
  // (`resolve_end()`). Kept, it adds two ends to the corner, and a corner between two pieces of
  // one crease looks like one of valence 4, which the pieces keep (measured on CGAL's rotor at
  // 100k points and 0.5% noise, seed 1: such curves of length 0 at 4 of its 5 corners, one of
  // which cut a circle of 0.5 dB into 2 curves). Returns whether one was dropped.
  bool drop_short_corner_loops()
  {
    const auto loop = std::find_if(m_net.polylines.begin(), m_net.polylines.end(), [&](const Working_polyline& c) {
      return c.front_corner != no_index && c.front_corner == c.back_corner
             && curve_length(c) < m_scales.growth_radius;
    });
    if(loop == m_net.polylines.end())
      return false;
    m_net.polylines.erase(loop);
    return true;
  }

  // A spur is a curve from a corner to a free end, shorter than the shortest free curve kept.
  // It is a fragment of noise, and is dropped, where
  // - the corner has valence 3 and the two other curves continue each other: a crease crossed
  //   by the fragment (under noise, around small holes and along thin walls), and the corner
  //   then merges through. A short crease that ends at a true corner is kept: there the other
  //   curves turn (see `spur_crossing_turn_angle`);
  // - or another curve leaves the corner along it (see `runs_alongside()`): a second strand of
  //   that curve's crease, which stage 4 started beside it. Kept, it would give a true corner of
  //   valence 3 a fourth curve that touches the third where the corner moves (measured on CGAL's
  //   fandisk at 0.5% noise: the two strands and the stretch of the crease between their contact
  //   and the corner became three curves of 2 and 3 vertices).
  bool drop_short_spurs()
  {
    const auto at = incidences();
    for(const auto& ends : at)
    {
      if(ends.size() < 3)
        continue;
      for(std::size_t k = 0; k < ends.size(); ++k)
      {
        const Working_polyline& spur = m_net.polylines[ends[k].first];
        if(is_loop_without_corner(spur) || (spur.front_corner == no_index) == (spur.back_corner == no_index)
           || curve_length(spur) >= Constants::min_length * m_scales.growth_radius)
          continue;
        const bool crossing = ends.size() == 3
                              && continue_each_other(ends[(k + 1) % 3], ends[(k + 2) % 3],
                                                     Constants::spur_crossing_turn_angle);
        const bool beside_another = std::any_of(ends.begin(), ends.end(), [&](const auto& other) {
          return other.first != ends[k].first && runs_alongside(ends[k], other);
        });
        if(!crossing && !beside_another)
          continue;
        m_net.polylines.erase(m_net.polylines.begin() + std::ptrdiff_t(ends[k].first));
        return true;
      }
    }
    return false;
  }

  // Whether the curves of two ends at one corner leave it along one crease: their ends' normal
  // pairs match and their tangents are as close (a crease's direction is the cross product of
  // its normals, so it is as uncertain as they are: `same_crease_normal_angle`).
  bool runs_alongside(const std::pair<std::size_t, bool>& a, const std::pair<std::size_t, bool>& b) const
  {
    return turn_at_corner(a, b) >= 180 - same_crease_normal_angle
           && match_normal_pairs(end_normals(m_net.polylines[a.first], a.second),
                                 end_normals(m_net.polylines[b.first], b.second),
                                 std::cos(radians(same_crease_normal_angle))) != 0;
  }

  void remove_unused_corners()
  {
    const auto at = incidences();
    std::vector<std::size_t> renumber(m_net.corners.size(), no_index);
    std::vector<Working_corner> kept;
    for(std::size_t k = 0; k < m_net.corners.size(); ++k)
      if(!at[k].empty())
      {
        renumber[k] = kept.size();
        kept.push_back(m_net.corners[k]);
      }
    m_net.corners.swap(kept);
    for(Working_polyline& c : m_net.polylines)
    {
      if(c.front_corner != no_index)
        c.front_corner = renumber[c.front_corner];
      if(c.back_corner != no_index)
        c.back_corner = renumber[c.back_corner];
    }
  }

  // Mesh_3 rounds off turns inside a polyline: split sharp turns into two curves at a corner,
  // except spikes (see `is_spike()`), whose vertex is dropped.
  void split_sharp_turns()
  {
    for(std::size_t c = 0; c < m_net.polylines.size();)
      if(!split_first_sharp_turn(c))
        ++c;
  }

  // Splits curve `c` at its first sharp turn, or drops the vertex of a spike there; the pieces
  // (or the curve) are examined again (the tail is appended to the list, a reopened loop keeps
  // its index).
  bool split_first_sharp_turn(std::size_t c)
  {
    Working_polyline& curve = m_net.polylines[c];
    for(std::size_t v = 1; v + 1 < curve.points.size(); ++v)
    {
      if(turns_sharply(curve, v))
      {
        // The turn towards a spike far off the line is sharp too, one vertex before it.
        for(std::size_t spike : {v, v + 1})
          if(is_spike(curve, spike) && turns_sharply(curve, spike))
          {
            curve.points.erase(curve.points.begin() + std::ptrdiff_t(spike));
            curve.normals.erase(curve.normals.begin() + std::ptrdiff_t(spike));
            return true;
          }
        const std::size_t corner = add_corner(curve.points[v], curve.normals[v]);
        split_at(c, v, corner);
        return true;
      }
    }
    return false;
  }

  // Moves every interior vertex of `c` by `step` times the way to the inverse-distance weighted
  // average of its two neighbours (ends fixed; a closed curve has no ends).
  void laplacian_step(Working_polyline& c, double step) const
  {
    const std::size_t n = c.points.size();
    if(n < 3)
      return;
    std::vector<Vec3> next = c.points;
    const bool loop = is_loop_without_corner(c);
    const std::size_t first = loop ? 0 : 1, last = n - 1;
    const double coincident = Constants::coincident_vertex_distance * m_scales.growth_radius;
    for(std::size_t v = first; v < last; ++v)
    {
      const Vec3& prev = c.points[v == 0 ? n - 2 : v - 1];
      const Vec3& succ = c.points[v + 1];
      const double wa = 1. / (std::max)((prev - c.points[v]).norm(), coincident);
      const double wb = 1. / (std::max)((succ - c.points[v]).norm(), coincident);
      const Vec3 target = (wa * prev + wb * succ) / (wa + wb);
      next[v] = c.points[v] + step * (target - c.points[v]);
    }
    if(loop)
      next[n - 1] = next[0];
    c.points.swap(next);
  }

  // Where the line of a curve's end takes its direction from (see `end_line()`).
  enum class Line_direction
  {
    of_vertices, // the principal direction of the window's vertices
    of_normals   // the crease line of the window's normal pairs (their cross products, summed)
  };

  // The line through the vertices of curve `c` at arc lengths from `corner_fit_skip` to
  // `corner_fit_skip + corner_fit_window` growth radii from its front (`back == false`) or back
  // end, and at least `corner_fit_skip` from a corner at its other end, as their centroid and a
  // unit direction; false if fewer than two vertices lie in the window.
  //
  // The direction of the vertices stays where the normals give none (all parallel). Where a
  // corner is placed the normals' is better: each normal pair was fitted by stage 2 to the
  // points around its vertex (150 to 200 on pinion at 0.5% and 1% noise), whereas the vertices
  // are few (2 to 6 on the curves between pinion's corners, 1.7% dB apart, at 0.5% noise) and
  // scatter across the crease by a good part of the noise, so that the line through them tilts.
  // Measured on the 9 benchmark parts (see `place_corners()` for where it is used): true
  // corners found within 0.5% dB, of 170, at 100k points, mean of seeds 1 and 2, 141 -> 149.5
  // at 0.5% noise and 65 -> 75.5 at 1%; at 50k points, seed 3, 120 -> 131 and 55 -> 67. The
  // line keeps the vertices' direction where the normals' is further from it than two normal
  // pairs of one crease can be (`same_crease_normal_angle`).
  bool end_line(const Working_polyline& c, bool back, Free_end& line,
                Line_direction direction = Line_direction::of_vertices) const
  {
    const std::size_t n = c.points.size();
    auto at = [&](std::size_t k) { return back ? n - 1 - k : k; };
    const double from = Constants::corner_fit_skip * m_scales.growth_radius;
    double to = from + Constants::corner_fit_window * m_scales.growth_radius;
    if((back ? c.front_corner : c.back_corner) != no_index)
      to = (std::min)(to, curve_length(c) - from);
    std::vector<std::size_t> window;
    double arc = 0;
    for(std::size_t k = 1; k < n && arc <= to; ++k)
    {
      arc += (c.points[at(k)] - c.points[at(k - 1)]).norm();
      if(arc >= from && arc <= to)
        window.push_back(at(k));
    }
    line = Free_end{no_index, back, Vec3::Zero(), Vec3::Zero()};
    if(window.size() < 2)
      return false;
    fit_principal_line(window.size(), [&](std::size_t j) -> const Vec3& { return c.points[window[j]]; }, line.point,
                       line.tangent);
    if(!line.tangent.allFinite())
      return false;
    if(direction == Line_direction::of_normals)
    {
      Vec3 crease = Vec3::Zero();
      for(std::size_t v : window)
      {
        const Vec3 t = c.normals[v][0].cross(c.normals[v][1]);
        crease += t.dot(line.tangent) >= 0 ? t : Vec3(-t);
      }
      if(crease.norm() > 0 && crease.allFinite() && angle_between(crease, line.tangent) <= same_crease_normal_angle)
        line.tangent = crease.normalized();
    }
    return true;
  }

  // Distance from `x` to the line of `line`.
  static double distance_to_line(const Vec3& x, const Free_end& line)
  {
    const Vec3 d = x - line.point;
    return (d - d.dot(line.tangent) * line.tangent).norm();
  }

  static const std::array<Vec3, 2>& end_normals(const Working_polyline& c, bool back)
  {
    return back ? c.normals.back() : c.normals.front();
  }

  // The corner of the curve ends `a` and `b`, which share one surface: the point closest to
  // both their lines, how far it lies from them (summed), and the normals of the three
  // surfaces, the shared one in the middle. False if the lines are too close to parallel.
  bool pair_junction(const std::pair<std::size_t, bool>& a, const std::pair<std::size_t, bool>& b,
                     const Free_end& line_a, const Free_end& line_b, Vec3& x, double& miss,
                     std::array<Vec3, 3>& surfaces) const
  {
    if(!junction_point({line_a, line_b}, x))
      return false;
    miss = distance_to_line(x, line_a) + distance_to_line(x, line_b);
    const std::array<Vec3, 2>& na = end_normals(m_net.polylines[a.first], a.second);
    const std::array<Vec3, 2>& nb = end_normals(m_net.polylines[b.first], b.second);
    int shared_a = 0, shared_b = 0;
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j)
        if(std::abs(na[i].dot(nb[j])) > std::abs(na[shared_a].dot(nb[shared_b])))
        {
          shared_a = i;
          shared_b = j;
        }
    surfaces = {{na[1 - shared_a], na[shared_a], nb[1 - shared_b]}};
    return true;
  }

  // Two corners closer than about a growth radius (the ends of the top edge of a gear tooth,
  // 1.7% dB apart on CGAL's pinion, the ends of a narrow chamfer) come out of stages 2 to 4 as
  // one corner where four curves meet: two creases of each true corner, the short crease
  // between them missing. Such a corner is split in two, joined by that crease: the four curves
  // pair up so that the lines of each pair meet at a point (see `end_line()`), the two points
  // stand farther apart than the lines of a pair miss each other, and the segment between them
  // runs along the crease line of the surfaces that the pairs do not share (see
  // `merged_corner_link_angle`). A true corner of valence 4, where the lines of all four curves
  // meet at one point, stays. On the pinion at 100k points and 0.5% noise this finds 13 and 14
  // more of its 80 corners within 0.5% dB (seeds 1 and 2: 49 -> 62, 38 -> 52); on the other
  // parts the corners found do not change, and at most 3 curves are added.
  void split_merged_corners()
  {
    static constexpr int pairings[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}};
    const double cos_link = std::cos(radians(Constants::merged_corner_link_angle));
    const auto at = incidences();
    for(std::size_t k = 0; k < at.size(); ++k)
    {
      const auto& ends = at[k];
      if(ends.size() != 4)
        continue;
      std::array<Free_end, 4> lines;
      bool fitted = true;
      for(std::size_t i = 0; i < 4 && fitted; ++i)
        fitted = end_line(m_net.polylines[ends[i].first], ends[i].second, lines[i])
                 && std::none_of(ends.begin(), ends.begin() + std::ptrdiff_t(i),
                                 [&](const auto& e) { return e.first == ends[i].first; });
      if(!fitted)
        continue;
      const int* best = nullptr;
      double best_miss = std::numeric_limits<double>::infinity();
      std::array<Vec3, 2> corners;
      std::array<std::array<Vec3, 3>, 2> surfaces;
      for(const auto& pairing : pairings)
      {
        std::array<Vec3, 2> x;
        std::array<std::array<Vec3, 3>, 2> s;
        std::array<double, 2> miss;
        bool met = true;
        for(int h = 0; h < 2 && met; ++h)
          met = pair_junction(ends[pairing[2 * h]], ends[pairing[2 * h + 1]], lines[pairing[2 * h]],
                              lines[pairing[2 * h + 1]], x[h], miss[h], s[h]);
        if(!met)
          continue;
        const Vec3 link = x[1] - x[0], crease = s[0][0].cross(s[0][2]);
        const double lengths = link.norm() * crease.norm();
        if(!(lengths > 0 && std::abs(link.dot(crease)) >= cos_link * lengths) || (std::max)(miss[0], miss[1]) >= best_miss)
          continue;
        best = pairing;
        best_miss = (std::max)(miss[0], miss[1]);
        corners = x;
        surfaces = s;
      }
      if(best == nullptr || (corners[1] - corners[0]).norm() <= best_miss)
        continue;
      m_net.corners[k] = Working_corner{corners[0], {surfaces[0].begin(), surfaces[0].end()}};
      const std::size_t second = m_net.corners.size();
      m_net.corners.push_back(Working_corner{corners[1], {surfaces[1].begin(), surfaces[1].end()}});
      for(int i = 2; i < 4; ++i)
      {
        Working_polyline& c = m_net.polylines[ends[best[i]].first];
        (ends[best[i]].second ? c.back_corner : c.front_corner) = second;
        (ends[best[i]].second ? c.points.back() : c.points.front()) = corners[1];
      }
      Working_polyline link;
      link.points = {corners[0], corners[1]};
      link.normals.assign(2, {{surfaces[0][0], surfaces[0][2]}});
      link.front_corner = k;
      link.back_corner = second;
      m_net.polylines.push_back(std::move(link));
    }
  }

  // Every corner moves to the point closest to the lines of its curves near it (see
  // `corner_fit_skip`), when at least two of them define one within a growth radius of where
  // it is. A corner point of stage 2 is one forward search's estimate; the lines average the
  // edge points of all the curves that meet there. The lines take the direction of the normals
  // (see `end_line()`) at corners of valence 2 and 3, and that of the vertices where more
  // curves meet: there noise made the corner, or strands of one crease repeat its faces, and
  // the normals lead no better than the vertices (measured on CGAL's rotor at 50k points and 1%
  // noise, seed 3: placed on the normals' lines, its corners of valence 4 to 6 moved by up to a
  // growth radius and left 14 more curves of one segment, 16 instead of 2).
  void place_corners()
  {
    const auto at = incidences();
    for(std::size_t k = 0; k < at.size(); ++k)
    {
      const Line_direction direction =
        at[k].size() <= Constants::max_valence_on_normals ? Line_direction::of_normals : Line_direction::of_vertices;
      std::vector<Free_end> lines;
      for(const auto& [c, back] : at[k])
      {
        Free_end line;
        if(end_line(m_net.polylines[c], back, line, direction))
          lines.push_back(line);
      }
      Vec3 x;
      if(lines.size() < 2 || !junction_point(lines, x)
         || (x - m_net.corners[k].point).norm() > m_scales.growth_radius)
        continue;
      m_net.corners[k].point = x;
    }
  }

  // A corner moved by `place_corners()` can leave the curve's last vertices turning sharply to
  // reach it (the vertex before the corner lay on the noisy side of the averaged lines): such a
  // vertex goes, so that the curve runs straight to its corner instead of making a sharp turn
  // that Mesh_3 would round off (and that the Mesh_3 step would split into a one-segment curve).
  void drop_sharp_end_vertices(Working_polyline& c) const
  {
    if(c.front_corner != no_index)
    {
      reverse_curve(c);
      drop_sharp_turns_before_back(c);
      reverse_curve(c);
    }
    if(c.back_corner != no_index)
      drop_sharp_turns_before_back(c);
  }

  // Exact shared points, consistent normals. (Loops without a corner are exact already: every
  // step that moves a vertex moves their first and last together.)
  void finalize()
  {
    for(Working_polyline& c : m_net.polylines)
    {
      if(c.front_corner != no_index)
        c.points.front() = m_net.corners[c.front_corner].point;
      if(c.back_corner != no_index)
        c.points.back() = m_net.corners[c.back_corner].point;
      drop_sharp_end_vertices(c);
      for(std::size_t v = 1; v < c.normals.size(); ++v)
        c.normals[v] = align_normal_pair(c.normals[v - 1], c.normals[v]);
    }
  }
};

/// Stage 5.
inline void complete_polylines(Working_network& network, const Completion_parameters& parameters)
{
  Curve_completion(network, parameters).run();
  make_network_mesh_3_ready(network);
  index_incident_polylines(network);
}

/// Stage 5 on the user's network (converted to the working traits and back), with the scales
/// given in `np` replacing those of `network`.
template <typename GT, typename NamedParameters>
void complete_feature_curve_network(Feature_curve_network<GT>& network, const NamedParameters& np,
                                    const Completion_parameters& parameters)
{
  Working_network working = convert_network<Working_traits>(network);
  override_scales(np, working.scales);
  complete_polylines(working, parameters);
  network = convert_network<GT>(working);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
