// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The k nearest neighbours of every point of a set at once, by grid cells.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_ALL_NEAREST_NEIGHBORS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_ALL_NEAREST_NEIGHBORS_H

#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Spatial_grid.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Cell side of `for_each_neighborhood()` relative to the median distance to the k-th neighbour.
constexpr double neighborhood_cell_per_radius = 1.2;
/// Ranked candidates of a point lie within this factor (squared) of the previous point's k-th
/// distance (squared), when that suffices.
constexpr double neighborhood_guess_factor = 1.5;
/// Below this many points, every query goes to the k-d tree.
constexpr std::size_t smallest_gridded_set = 4096;

/// The `k` nearest of `candidates` to `p` (in `neighbors`, nearest first), if they
/// all lie within `margin` of `p` (then no point outside the candidates' box is closer); false
/// otherwise. `previous` is the squared k-th distance of the point answered before (0 if
/// none): the candidates within `neighborhood_guess_factor` of it are ranked first, and it is
/// updated on success.
inline bool nearest_among(const std::vector<Vec3>& points, const Vec3& p, const std::vector<std::size_t>& candidates,
                          std::size_t k, double margin, double& previous,
                          std::vector<std::pair<double, std::size_t>>& ranked, std::vector<std::size_t>& neighbors)
{
  const double margin2 = margin * margin;
  const double guess2 = previous > 0 ? (std::min)(margin2, neighborhood_guess_factor * previous) : margin2;
  for(double bound2 : {guess2, margin2})
  {
    ranked.clear();
    for(std::size_t q : candidates)
    {
      const double d2 = (points[q] - p).squaredNorm();
      if(d2 <= bound2)
        ranked.emplace_back(d2, q);
    }
    if(ranked.size() >= k)
    {
      // Nearest first: the fits then sum the neighbours in an order that depends on the points
      // only, so that a tile of the cloud (see `extract_tile_features()`) gets the same residuals
      // to the last bit as the whole cloud, not an order that depends on the numbering.
      sort_smallest(ranked, k);
      previous = ranked[k - 1].first;
      neighbors.clear();
      for(std::size_t r = 0; r < k; ++r)
        neighbors.push_back(ranked[r].second);
      return true;
    }
    if(bound2 == margin2)
      break;
  }
  return false;
}

/// Calls `body(i, neighbors)` for every point `i` of `points` with its `k` nearest points of
/// `points` (`i` included, nearest first); `index` must index `points`. The points
/// are put in cubic cells of side `cell`, about as wide as a neighbourhood (see
/// `neighborhood_cell_per_radius`): the points of a cell share the candidates of the 27 cells
/// around it, and their neighbourhoods are selected from those. A point whose k-th neighbour
/// may lie outside them (closer to the border of the 27 cells than to its k-th candidate) is
/// answered by the k-d tree, so that every neighbourhood is exact, whatever `cell`. This does
/// the work of one tree query per point several times faster. Small sets, a `cell` of 0 and
/// grids too wide for `Grid_key` (far outliers) go to the k-d tree entirely.
///
/// `body` runs concurrently for different points when `ConcurrencyTag` allows it. Returns false
/// if `progress` was cancelled.
template <typename ConcurrencyTag, typename Body>
bool for_each_neighborhood(const std::vector<Vec3>& points, const Point_index& index, std::size_t k,
                           double cell, Progress& progress, const Body& body)
{
  const std::size_t n = points.size();
  k = (std::min)(k, n);
  Vec3 low = points.empty() ? Vec3::Zero() : points.front(), high = low;
  for(const Vec3& p : points)
  {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // Room for the offset and the cells around the last one.
  const double largest_cell_count = double(Grid_key::mask) - 2;
  if(n < smallest_gridded_set || k == 0 || !(cell > 0) || ((high - low) / cell).maxCoeff() >= largest_cell_count)
  {
    return parallel_blocks<ConcurrencyTag>(n, progress, [&](std::size_t first, std::size_t last) {
      std::vector<std::size_t> neighbors;
      for(std::size_t i = first; i < last; ++i)
      {
        index.nearest(points[i], k, neighbors);
        body(i, neighbors);
      }
    });
  }

  Spatial_grid<Vec3> grid(cell, low);
  for(std::size_t i = 0; i < n; ++i)
    grid.insert(points[i], i);
  return parallel_blocks<ConcurrencyTag>(grid.number_of_cells(), progress, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> candidates, neighbors;
    std::vector<std::pair<double, std::size_t>> ranked;
    for(std::size_t c = first; c < last; ++c)
    {
      grid.ids_around(c, candidates);
      const Vec3 box_low = grid.low_corner_around(c);
      const Vec3 box_high = box_low + Vec3::Constant(3 * cell);
      // The previous point's k-th distance: the next one's is about the same, and only the
      // candidates within a little more need ranking. Reset per cell, so that the result does
      // not depend on how cells are shared between threads.
      double previous = 0;
      for(std::size_t j = 0; j < grid.size(c); ++j)
      {
        const std::size_t i = grid.id(c, j);
        const Vec3& p = points[i];
        const double margin = (std::min)((p - box_low).minCoeff(), (box_high - p).minCoeff());
        if(!nearest_among(points, p, candidates, k, margin, previous, ranked, neighbors))
          index.nearest(p, k, neighbors);
        body(i, neighbors);
      }
    }
  });
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
