// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 3 (paper 3.4): covariance smoothing of the edge points over adaptively grown
// neighbourhoods that never reach past a corner nor into another crease.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SMOOTHING_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SMOOTHING_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Settings.h>

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
inline void same_crease_neighbors(const std::vector<Edge_sample>& edges, const Point_index& index,
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

/// Principal direction of the first `count` points of `set`; returns the share of the
/// largest eigenvalue.
inline double principal_line(const std::vector<Edge_sample>& edges, const std::vector<std::size_t>& set,
                             std::size_t count, Vec3& centroid, Vec3& direction)
{
  centroid = Vec3::Zero();
  for(std::size_t j = 0; j < count; ++j)
    centroid += edges[set[j]].point;
  centroid /= double(count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(std::size_t j = 0; j < count; ++j)
  {
    const Vec3 d = edges[set[j]].point - centroid;
    covariance.noalias() += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  direction = solver.eigenvectors().col(2).normalized();
  const double total = solver.eigenvalues().sum();
  return total > 0 ? solver.eigenvalues()[2] / total : 0;
}

/// Stage 3. Returns false if cancelled.
template <typename ConcurrencyTag>
bool smooth_edge_points(Feature_samples& features, const Settings& settings, Progress progress)
{
  typedef Smoothing_constants C;
  std::vector<Edge_sample>& edges = features.edges;
  std::vector<Vec3> corners;
  for(const Corner_sample& c : features.corners)
    corners.push_back(c.point);
  Point_index corner_index;
  corner_index.build<CGAL::Sequential_tag>(corners);
  const double cos_same = std::cos(radians(same_crease_normal_angle));

  for(unsigned int pass = 0; pass < settings.smoothing_passes; ++pass)
  {
    std::vector<Vec3> positions;
    for(const Edge_sample& e : edges)
      positions.push_back(e.point);
    Point_index index;
    index.build<ConcurrencyTag>(positions);
    std::vector<Edge_sample> next = edges;
    const bool last_pass = pass + 1 == settings.smoothing_passes;
    Progress pass_progress = progress.sub(double(pass) / settings.smoothing_passes,
                                          double(pass + 1) / settings.smoothing_passes);
    if(!parallel_blocks<ConcurrencyTag>(edges.size(), pass_progress, [&](std::size_t first, std::size_t last) {
         std::vector<std::size_t> scratch, neighbors;
         for(std::size_t i = first; i < last; ++i)
         {
           same_crease_neighbors(edges, index, corner_index, corners, i, scratch, neighbors);
           if(neighbors.size() < 3)
             continue;
           // Adaptive growth: the smallest neighbourhood that is clearly along a line.
           std::size_t count = (std::min)(C::initial_neighbors, neighbors.size());
           Vec3 centroid, direction;
           double linearity = principal_line(edges, neighbors, count, centroid, direction);
           while(linearity < C::linearity && count < (std::min)(C::max_neighbors, neighbors.size()))
           {
             count = (std::min)(count + C::neighbor_increment, (std::min)(C::max_neighbors, neighbors.size()));
             linearity = principal_line(edges, neighbors, count, centroid, direction);
           }
           const Vec3& p = edges[i].point;
           next[i].point = centroid + (p - centroid).dot(direction) * direction;
           if(last_pass)
           {
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
               next[i].normals = {{sum[0].normalized(), sum[1].normalized()}};
           }
         }
       }))
      return false;
    edges.swap(next);
  }
  return progress.report(1.);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
