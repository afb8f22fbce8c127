// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tiled extraction: the candidate threshold estimated once for the whole cloud, the halo a
// tile needs, which feature points a tile owns, and the canonical order in which the stitcher
// joins the tiles' feature points before growing the curves.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_TILING_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_TILING_IMPL_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Indexed_input.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/candidate_points_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/rmls_projection_impl.h>
#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// How far the feature points of a tile's core depend on the points around it, in terms of
/// the scales (see `tile_halo_width()`).
struct Tile_halo_constants
{
  /// The stage-1 and stage-2 neighbourhoods hold a fixed number of points: their radius is the
  /// median one (`candidate_radius`, `corner_radius`) where the sampling is even, up to about
  /// twice that where it thins out (surface borders, anisotropic scans).
  static constexpr double neighborhood_radius_margin = 2;
  /// Reach of one smoothing pass (the 60 nearest edge points along the crease, see
  /// `Smoothing_constants::search_neighbors`), in growth radii: at the 99th percentile of the
  /// edge points, 1.9 to 2.7 (median 1.4 to 1.5) on fandisk, anchor and pinion, 100k points, noise
  /// 0 and 0.2% of the diagonal. With it, 27 tiles give every edge point of the untiled run to
  /// the last bit on anchor, pinion and fandisk at noise 0 (a halo of 14 growth radii; at 12,
  /// 1 of 17,489 edge points moves), and all but 6 of 15,697 (by 4% of the spacing) on fandisk at
  /// 0.2%: isolated edge points, whose 60 nearest reach up to 12 growth radii.
  static constexpr double smoothing_reach_per_growth_radius = 2.2;
};

/// The halo width that `tile_halo_width()` documents.
inline double halo_width(const Scales& scales, unsigned int smoothing_passes)
{
  typedef Tile_halo_constants C;
  // A candidate's edge point lies within its stage-1 neighbourhood; the candidates of its
  // stage-2 grid cell (noise-free data) share the surfaces found around one of them.
  const double cell_diagonal = noise_dominates(scales) ? 0. : std::sqrt(3.) * candidate_cell_per_spacing * scales.spacing;
  const double projection_reach = cell_diagonal
    + C::neighborhood_radius_margin * (scales.candidate_radius + scales.corner_radius)
    // corner points are grouped over `corner_radius`
    + scales.corner_radius;
  const double smoothing_reach = double(smoothing_passes) * C::smoothing_reach_per_growth_radius * scales.growth_radius;
  return projection_reach + smoothing_reach;
}

/// The candidate threshold of stage 1 (see `automatic_residual_threshold()`) on the regular
/// subsample that the scale estimation measures, instead of every point: a value every tile
/// can share.
template <typename ConcurrencyTag>
bool sampled_residual_threshold(const Indexed_input& input, const Scales& scales, int degree, Progress progress,
                                double& threshold)
{
  const std::vector<Vec3>& points = input.points;
  threshold = 0;
  if(!(scales.spacing > 0) || scales.candidate_neighbors == 0)
    return progress.report(1.);
  const std::size_t stride = scale_sample_stride(points.size());
  std::vector<double> residuals((points.size() + stride - 1) / stride, 0.);
  if(!parallel_blocks<ConcurrencyTag>(residuals.size(), progress, [&](std::size_t first, std::size_t last) {
       std::vector<std::size_t> neighbors;
       for(std::size_t s = first; s < last; ++s)
       {
         input.index.nearest(points[s * stride], scales.candidate_neighbors, neighbors);
         residuals[s] = fit_residuals(points, neighbors, degree).max_residual;
       }
     }))
    return false;
  threshold = automatic_residual_threshold(residuals, scales);
  return true;
}

/// The scales of `estimate_sharp_feature_scales_for_tiles()`.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
Scales scales_for_tiles(const PointRange& points, const NamedParameters& np)
{
  const Scale_parameters scale_parameters = read_scale_parameters(np);
  const Candidate_parameters candidate_parameters = read_candidate_parameters(np);
  Indexed_input input;
  index_input_points<ConcurrencyTag>(points, np, input);
  Scales scales;
  estimate_scales<ConcurrencyTag>(input, scale_parameters, Progress(), scales);
  if(candidate_parameters.residual_threshold >= 0)
    scales.residual_threshold = candidate_parameters.residual_threshold;
  else
    sampled_residual_threshold<ConcurrencyTag>(input, scales, candidate_parameters.degree_fitting, Progress(),
                                               scales.residual_threshold);
  return scales;
}

/// `true` if `p` lies in the half-open box [min, max) of `box`: the boxes of a grid that
/// share faces own every point once.
inline bool in_core(const CGAL::Bbox_3& box, double x, double y, double z)
{
  return box.xmin() <= x && x < box.xmax() && box.ymin() <= y && y < box.ymax() && box.zmin() <= z && z < box.zmax();
}

inline void require_core_box(const CGAL::Bbox_3& box)
{
  for(int i = 0; i < 3; ++i)
    if(std::isnan(box.min(i)) || std::isnan(box.max(i)) || !(box.min(i) < box.max(i)))
      throw std::invalid_argument("Sharp feature extraction: a tile's core box must have min < max on every axis");
}

/// `true` if the interiors of the two boxes meet.
inline bool interiors_overlap(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b)
{
  for(int i = 0; i < 3; ++i)
    if(!(a.min(i) < b.max(i) && b.min(i) < a.max(i)))
      return false;
  return true;
}

inline bool box_before(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b)
{
  return std::make_tuple(a.xmin(), a.ymin(), a.zmin(), a.xmax(), a.ymax(), a.zmax())
       < std::make_tuple(b.xmin(), b.ymin(), b.zmin(), b.xmax(), b.ymax(), b.zmax());
}

template <typename GT>
bool point_before(const typename GT::Point_3& p, const typename GT::Point_3& q)
{
  return CGAL::compare_xyz(p, q) == CGAL::SMALLER;
}

template <typename GT>
bool vector_before(const typename GT::Vector_3& u, const typename GT::Vector_3& v)
{
  return std::make_tuple(u.x(), u.y(), u.z()) < std::make_tuple(v.x(), v.y(), v.z());
}

/// The stitcher's order of the edge points: by position, then by normals. It depends on the
/// points only, never on the tiles they came from.
template <typename GT>
bool edge_point_before(const Edge_point<GT>& a, const Edge_point<GT>& b)
{
  if(a.point != b.point)
    return point_before<GT>(a.point, b.point);
  for(int i = 0; i < 2; ++i)
    if(a.normals[i] != b.normals[i])
      return vector_before<GT>(a.normals[i], b.normals[i]);
  return false;
}

/// The stitcher's order of the corner points: by decreasing weight, as stage 2 keeps them,
/// then by position.
template <typename GT>
bool corner_point_before(const Corner_point<GT>& a, const Corner_point<GT>& b)
{
  if(a.weight != b.weight)
    return a.weight > b.weight;
  return point_before<GT>(a.point, b.point);
}

/// The grid of tiles over a box: at least `tiles` cells, each axis split in turn where the
/// cells are longest, so that the cells stay close to cubes.
inline std::array<std::size_t, 3> tile_grid(const CGAL::Bbox_3& box, std::size_t tiles)
{
  std::array<std::size_t, 3> counts = {{1, 1, 1}};
  while(counts[0] * counts[1] * counts[2] < tiles)
  {
    int longest = 0;
    for(int i = 1; i < 3; ++i)
      if((box.max(i) - box.min(i)) / double(counts[i]) > (box.max(longest) - box.min(longest)) / double(counts[longest]))
        longest = i;
    ++counts[longest];
  }
  return counts;
}

/// Core box `(i, j, k)` of the grid `counts` over `box`; the faces on the border of `box`
/// are pushed to infinity so that every point of the cloud has a tile.
inline CGAL::Bbox_3 tile_core(const CGAL::Bbox_3& box, const std::array<std::size_t, 3>& counts,
                              const std::array<std::size_t, 3>& cell)
{
  const double infinity = std::numeric_limits<double>::infinity();
  std::array<double, 3> low, high;
  for(int i = 0; i < 3; ++i)
  {
    const double side = (box.max(i) - box.min(i)) / double(counts[i]);
    low[i] = cell[i] == 0 ? -infinity : box.min(i) + double(cell[i]) * side;
    high[i] = cell[i] + 1 == counts[i] ? infinity : box.min(i) + double(cell[i] + 1) * side;
  }
  return CGAL::Bbox_3(low[0], low[1], low[2], high[0], high[1], high[2]);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
