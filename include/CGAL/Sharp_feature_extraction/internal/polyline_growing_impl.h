// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 4 (paper 3.5): polylines grown through the smoothed edge points from seeds far from
// corners, stopping at corners, at their own seed (closed loops) or where nothing lies ahead.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_POLYLINE_GROWING_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_POLYLINE_GROWING_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

struct Growing_constants
{
  /// Half-angle (degrees) of the cone ahead in which the next vertex is chosen.
  static constexpr double cone_angle = 45;
  /// Polylines with fewer vertices are dropped (the paper's rule).
  static constexpr std::size_t min_vertices = 4;
  /// Seeds tried between two progress reports.
  static constexpr std::size_t seeds_per_progress_report = 1024;
};

class Polyline_grower
{
  typedef Growing_constants Constants;

public:
  Polyline_grower(const std::vector<Working_edge_point>& edges, const std::vector<Working_corner_point>& corners, double radius)
    : m_edges(edges), m_radius(radius), m_visited(edges.size(), false)
  {
    std::vector<Vec3> positions;
    for(const Working_edge_point& e : edges)
      positions.push_back(e.point);
    m_index.build<CGAL::Sequential_tag>(positions);
    for(const Working_corner_point& c : corners)
      m_corners.push_back(c.point);
    m_corner_index.build<CGAL::Sequential_tag>(m_corners);
    m_cos_same = std::cos(radians(same_crease_normal_angle));
    m_cos_cone = std::cos(radians(Constants::cone_angle));
  }

  /// Seeds in order: farthest from any corner first (ties by coordinates, for determinism).
  std::vector<std::size_t> seed_order() const
  {
    std::vector<double> distance(m_edges.size(), 0.);
    std::vector<std::size_t> nearest;
    for(std::size_t i = 0; i < m_edges.size(); ++i)
      if(!m_corners.empty())
      {
        m_corner_index.nearest(m_edges[i].point, 1, nearest);
        distance[i] = (m_corners[nearest.front()] - m_edges[i].point).norm();
      }
    std::vector<std::size_t> order(m_edges.size());
    std::iota(order.begin(), order.end(), 0);
    // Ties (every seed of a network without corners) broken by coordinates, not by the order of
    // the edge points: the stitcher of a tiled extraction (see `stitch_tile_features()`) then
    // starts from the same seeds as the whole cloud.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if(distance[a] != distance[b])
        return distance[a] > distance[b];
      const Vec3& p = m_edges[a].point;
      const Vec3& q = m_edges[b].point;
      return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3) || (p == q && a < b);
    });
    return order;
  }

  /// Grows one polyline from `seed`; returns false when the seed has no line around it.
  bool grow(std::size_t seed, Working_polyline& curve)
  {
    curve = Working_polyline();
    m_visited[seed] = true;
    Vec3 direction;
    if(!local_direction(seed, direction))
      return false;
    Working_polyline forward, backward;
    const bool closed = walk(seed, direction, seed, forward);
    if(!closed)
      walk(seed, -direction, seed, backward);

    // backward (reversed), seed, forward
    for(std::size_t i = backward.points.size(); i-- > 0;)
    {
      curve.points.push_back(backward.points[i]);
      curve.normals.push_back(backward.normals[i]);
    }
    curve.front_corner = backward.back_corner;
    curve.points.push_back(m_edges[seed].point);
    curve.normals.push_back(m_edges[seed].normals);
    curve.points.insert(curve.points.end(), forward.points.begin(), forward.points.end());
    curve.normals.insert(curve.normals.end(), forward.normals.begin(), forward.normals.end());
    curve.back_corner = forward.back_corner;
    if(closed)
    {
      curve.points.push_back(curve.points.front());
      curve.normals.push_back(curve.normals.front());
    }
    return true;
  }

  bool visited(std::size_t i) const { return m_visited[i]; }

private:
  const std::vector<Working_edge_point>& m_edges;
  double m_radius;
  std::vector<bool> m_visited;
  Point_index m_index, m_corner_index;
  std::vector<Vec3> m_corners;
  double m_cos_same, m_cos_cone;
  std::vector<std::size_t> m_near;

  void same_crease_within(std::size_t i, std::vector<std::size_t>& out)
  {
    m_index.within(m_edges[i].point, m_radius, out);
    std::sort(out.begin(), out.end());
    out.erase(std::remove_if(out.begin(), out.end(), [&](std::size_t j) {
                return match_normal_pairs(m_edges[i].normals, m_edges[j].normals, m_cos_same) == 0;
              }), out.end());
  }

  bool local_direction(std::size_t i, Vec3& direction)
  {
    same_crease_within(i, m_near);
    if(m_near.size() < 3)
      return false;
    Vec3 centroid;
    fit_principal_line(m_near.size(), [&](std::size_t j) -> const Vec3& { return m_edges[m_near[j]].point; },
                       centroid, direction);
    return direction.allFinite();
  }

  // Walks from `start` along `direction`; vertices are appended to `out`. Returns true when
  // the walk came back to `seed` (closed loop).
  bool walk(std::size_t start, Vec3 direction, std::size_t seed, Working_polyline& out)
  {
    std::size_t current = start;
    std::array<Vec3, 2> normals = m_edges[start].normals;
    std::vector<std::size_t> corner_hits;
    for(std::size_t step = 0; step < m_edges.size(); ++step)
    {
      const Vec3 p = m_edges[current].point;
      // A corner ahead ends the walk there.
      m_corner_index.within(p, m_radius, corner_hits);
      std::sort(corner_hits.begin(), corner_hits.end());
      double best_corner = std::numeric_limits<double>::infinity();
      for(std::size_t c : corner_hits)
      {
        const Vec3 d = m_corners[c] - p;
        if(d.dot(direction) > m_cos_cone * d.norm() && d.norm() < best_corner)
        {
          best_corner = d.norm();
          out.back_corner = c;
        }
      }
      if(out.back_corner != no_index)
      {
        out.points.push_back(m_corners[out.back_corner]);
        out.normals.push_back(normals);
        return false;
      }

      same_crease_within(current, m_near);
      std::size_t next = no_index;
      double farthest = 0;
      bool seed_ahead = false;
      for(std::size_t j : m_near)
      {
        const Vec3 d = m_edges[j].point - p;
        const double along = d.dot(direction);
        if(along <= 0)
          continue;
        if(j == seed && out.points.size() >= 2)
          seed_ahead = true;
        if(!m_visited[j] && along > m_cos_cone * d.norm() && along > farthest)
        {
          farthest = along;
          next = j;
        }
      }
      if(seed_ahead)
      {
        // Closing the loop consumes what is left around the seed.
        same_crease_within(seed, m_near);
        for(std::size_t j : m_near)
          m_visited[j] = true;
        return true;
      }
      if(next == no_index)
        return false;
      for(std::size_t j : m_near)
        if((m_edges[j].point - p).dot(direction) > 0)
          m_visited[j] = true;
      Vec3 new_direction;
      if(local_direction(next, new_direction))
        direction = new_direction.dot(direction) >= 0 ? new_direction : Vec3(-new_direction);
      normals = align_normal_pair(normals, m_edges[next].normals);
      out.points.push_back(m_edges[next].point);
      out.normals.push_back(normals);
      current = next;
    }
    return false;
  }
};

/// Stage 4: all polylines through the edge points, with the corners as fixed vertices, within
/// the growth radius of `features.scales`.
inline Working_network grow_polylines(const Working_feature_points& features, Progress progress)
{
  const double radius = features.scales.growth_radius;
  Working_network network;
  network.scales = features.scales;
  for(const Working_corner_point& c : features.corner_points)
    network.corners.push_back(Working_corner{c.point, {c.normals[0], c.normals[1], c.normals[2]}});
  if(features.edge_points.empty())
    return network;
  Polyline_grower grower(features.edge_points, features.corner_points, radius);
  const std::vector<std::size_t> order = grower.seed_order();
  for(std::size_t k = 0; k < order.size(); ++k)
  {
    if(grower.visited(order[k]))
      continue;
    Working_polyline curve;
    std::size_t vertices = 0;
    if(grower.grow(order[k], curve))
      vertices = curve.points.size();
    if(vertices >= Growing_constants::min_vertices)
      network.polylines.push_back(std::move(curve));
    if(k % Growing_constants::seeds_per_progress_report == 0 && !progress.report(double(k) / double(order.size())))
      return network;
  }
  index_incident_polylines(network);
  progress.report(1.);
  return network;
}

/// Stage 4 on the user's feature points (converted to the working traits and back), with the
/// scales given in `np` replacing those of `features`. Returns false if cancelled.
template <typename GT, typename NamedParameters>
bool grow_feature_curve_network(const Feature_point_set<GT>& features, Feature_curve_network<GT>& network,
                                const NamedParameters& np, const Progress_callback& callback)
{
  Working_feature_points working = convert_feature_points<Working_traits>(features);
  override_scales(np, working.scales);
  Progress progress(callback);
  const Working_network grown = grow_polylines(working, progress);
  if(progress.cancelled())
    return false;
  network = convert_network<GT>(grown);
  return true;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
