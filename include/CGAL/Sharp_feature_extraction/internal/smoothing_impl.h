// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 3 (paper 3.4): covariance smoothing of the edge points over adaptively grown
// neighbourhoods that never reach past a corner nor into another crease.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SMOOTHING_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SMOOTHING_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

struct Smoothing_constants
{
  static constexpr std::size_t initial_neighbors = 10;
  static constexpr std::size_t neighbor_increment = 5;
  static constexpr std::size_t max_neighbors = 30;
  /// The neighbourhood is "along a line" when the largest eigenvalue carries this share.
  static constexpr double linearity = 0.8;
  /// Feature points are searched among this many nearest ones before filtering.
  static constexpr std::size_t search_neighbors = 60;
};

/// Neighbours of edge point `i` that lie on the same crease and on the same side of the
/// nearest corner, nearest first.
inline void same_crease_neighbors(const std::vector<Working_edge_point>& edges, const Point_index& index,
                                  const Point_index& corner_index, const std::vector<Vec3>& corners,
                                  std::size_t i, std::vector<std::size_t>& scratch,
                                  std::vector<std::size_t>& out)
{
  const double cos_same = std::cos(radians(same_crease_normal_angle));
  const Vec3& p = edges[i].point;
  double corner_distance = std::numeric_limits<double>::infinity();
  if(!corners.empty())
  {
    corner_index.nearest(p, 1, scratch);
    corner_distance = (corners[scratch.front()] - p).norm();
  }
  index.nearest(p, Smoothing_constants::search_neighbors, scratch);
  out.clear();
  for(std::size_t j : scratch)
    if((edges[j].point - p).norm() < corner_distance
       && match_normal_pairs(edges[i].normals, edges[j].normals, cos_same) != 0)
      out.push_back(j);
}

/// Principal line of the first `count` points of `set`; returns the share of the largest
/// variance.
inline double principal_line(const std::vector<Working_edge_point>& edges, const std::vector<std::size_t>& set,
                             std::size_t count, Vec3& centroid, Vec3& direction)
{
  return fit_principal_line(count, [&](std::size_t j) -> const Vec3& { return edges[set[j]].point; }, centroid, direction);
}

/// Edge point `i` moved onto the principal line of `neighbors` (its same-crease neighbours,
/// nearest first): of the smallest prefix of them that is clearly along a line (see
/// `Smoothing_constants::linearity`). With `average_normals`, its normals become the average
/// of theirs, in its own order and orientation.
inline Working_edge_point smoothed_edge_point(const std::vector<Working_edge_point>& edges, std::size_t i,
                                              const std::vector<std::size_t>& neighbors, bool average_normals)
{
  typedef Smoothing_constants Constants;
  Working_edge_point out = edges[i];
  const std::size_t largest = (std::min)(Constants::max_neighbors, neighbors.size());
  std::size_t count = (std::min)(Constants::initial_neighbors, neighbors.size());
  Vec3 centroid, direction;
  double linearity = principal_line(edges, neighbors, count, centroid, direction);
  while(linearity < Constants::linearity && count < largest)
  {
    count = (std::min)(count + Constants::neighbor_increment, largest);
    linearity = principal_line(edges, neighbors, count, centroid, direction);
  }
  const Vec3& p = edges[i].point;
  out.point = centroid + (p - centroid).dot(direction) * direction;
  if(!average_normals)
    return out;
  const double cos_same = std::cos(radians(same_crease_normal_angle));
  std::array<Vec3, 2> sum = {{Vec3::Zero(), Vec3::Zero()}};
  for(std::size_t j = 0; j < count; ++j)
  {
    if(match_normal_pairs(edges[i].normals, edges[neighbors[j]].normals, cos_same) == 0)
      continue;
    const std::array<Vec3, 2> aligned = align_normal_pair(edges[i].normals, edges[neighbors[j]].normals);
    sum[0] += aligned[0];
    sum[1] += aligned[1];
  }
  if(sum[0].norm() > 0 && sum[1].norm() > 0)
    out.normals = {{sum[0].normalized(), sum[1].normalized()}};
  return out;
}

/// Stage 3. Returns false if cancelled.
template <typename ConcurrencyTag>
bool smooth_edge_points(Working_feature_points& features, const Smoothing_parameters& parameters, Progress progress)
{
  std::vector<Working_edge_point>& edges = features.edge_points;
  std::vector<Vec3> corners;
  for(const Working_corner_point& c : features.corner_points)
    corners.push_back(c.point);
  Point_index corner_index;
  corner_index.build<CGAL::Sequential_tag>(corners);

  for(unsigned int pass = 0; pass < parameters.passes; ++pass)
  {
    std::vector<Vec3> positions;
    for(const Working_edge_point& e : edges)
      positions.push_back(e.point);
    Point_index index;
    index.build<ConcurrencyTag>(positions);
    std::vector<Working_edge_point> next = edges;
    const bool last_pass = pass + 1 == parameters.passes;
    Progress pass_progress = progress.sub(double(pass) / parameters.passes, double(pass + 1) / parameters.passes);
    if(!parallel_blocks<ConcurrencyTag>(edges.size(), pass_progress, [&](std::size_t first, std::size_t last) {
         std::vector<std::size_t> scratch, neighbors;
         for(std::size_t i = first; i < last; ++i)
         {
           same_crease_neighbors(edges, index, corner_index, corners, i, scratch, neighbors);
           if(neighbors.size() >= 3)
             next[i] = smoothed_edge_point(edges, i, neighbors, last_pass);
         }
       }))
      return false;
    edges.swap(next);
  }
  return progress.report(1.);
}

/// Stage 3 on the user's feature points (converted to the working traits and back).
template <typename ConcurrencyTag, typename GT>
bool smooth_feature_point_set(Feature_point_set<GT>& features, const Smoothing_parameters& parameters,
                              const Progress_callback& callback)
{
  Working_feature_points working = convert_feature_points<Working_traits>(features);
  if(!smooth_edge_points<ConcurrencyTag>(working, parameters, Progress(callback)))
    return false;
  features = convert_feature_points<GT>(working);
  return true;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
