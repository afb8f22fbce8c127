// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The k nearest neighbours of every point of a set at once, by grid cells.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_ALL_NEAREST_NEIGHBORS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_ALL_NEAREST_NEIGHBORS_H

#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>

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

/// Cell coordinates in a grid of side `cell` with its origin at `low`, offset by 1 (so that
/// the cells around any cell have coordinates too), packed in one sortable key of 21 bits per
/// coordinate. Coordinates beyond 21 bits wrap around.
struct Grid_key
{
  static constexpr std::uint64_t mask = (std::uint64_t(1) << 21) - 1;

  static std::uint64_t pack(std::uint64_t x, std::uint64_t y, std::uint64_t z)
  {
    return ((x & mask) << 42) | ((y & mask) << 21) | (z & mask);
  }
  static std::uint64_t of(const Vec3& p, const Vec3& low, double cell)
  {
    const Vec3 g = (p - low) / cell;
    return pack(std::uint64_t(g[0]) + 1, std::uint64_t(g[1]) + 1, std::uint64_t(g[2]) + 1);
  }
  static std::uint64_t x(std::uint64_t key) { return key >> 42; }
  static std::uint64_t y(std::uint64_t key) { return (key >> 21) & mask; }
  static std::uint64_t z(std::uint64_t key) { return key & mask; }
};

/// Calls `body(i, neighbors)` for every point `i` of `points` with its `k` nearest points of
/// `points` (`i` included, in no particular order); `index` must index `points`. The points
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
        index.nearest(points[i], k, neighbors, false);
        body(i, neighbors);
      }
    });
  }

  // Points by cell (cell keys ascending, then positions).
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(n);
  for(std::size_t i = 0; i < n; ++i)
    keyed[i] = std::make_pair(Grid_key::of(points[i], low, cell), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint64_t> cell_key;
  std::vector<std::size_t> cell_start;
  for(std::size_t i = 0; i < n; ++i)
    if(i == 0 || keyed[i].first != keyed[i - 1].first)
    {
      cell_key.push_back(keyed[i].first);
      cell_start.push_back(i);
    }
  cell_start.push_back(n);

  return parallel_blocks<ConcurrencyTag>(cell_key.size(), progress, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> candidates, neighbors;
    std::vector<std::pair<double, std::size_t>> ranked;
    for(std::size_t c = first; c < last; ++c)
    {
      // The candidates: the points of the 27 cells around cell c.
      const std::uint64_t x = Grid_key::x(cell_key[c]), y = Grid_key::y(cell_key[c]), z = Grid_key::z(cell_key[c]);
      candidates.clear();
      for(std::uint64_t dx = x - 1; dx <= x + 1; ++dx)
        for(std::uint64_t dy = y - 1; dy <= y + 1; ++dy)
        {
          // The three cells along z are consecutive keys.
          const auto from = std::lower_bound(cell_key.begin(), cell_key.end(), Grid_key::pack(dx, dy, z - 1));
          for(auto it = from; it != cell_key.end() && *it <= Grid_key::pack(dx, dy, z + 1); ++it)
          {
            const std::size_t d = std::size_t(it - cell_key.begin());
            for(std::size_t j = cell_start[d]; j < cell_start[d + 1]; ++j)
              candidates.push_back(keyed[j].second);
          }
        }
      // The box of the 27 cells.
      const Vec3 box_low = low + cell * Vec3(double(x) - 2, double(y) - 2, double(z) - 2);
      const Vec3 box_high = box_low + Vec3::Constant(3 * cell);
      // The previous point's k-th distance: the next one's is about the same, and only the
      // candidates within a little more need ranking. Reset per cell, so that the result does
      // not depend on how cells are shared between threads.
      double previous = 0;
      for(std::size_t j = cell_start[c]; j < cell_start[c + 1]; ++j)
      {
        const std::size_t i = keyed[j].second;
        const Vec3& p = points[i];
        const double margin = (std::min)((p - box_low).minCoeff(), (box_high - p).minCoeff());
        // Neighbourhoods within `margin` are exact: no point outside the 27 cells is closer.
        const double margin2 = margin * margin;
        const double guess2 = previous > 0 ? (std::min)(margin2, neighborhood_guess_factor * previous) : margin2;
        bool exact = false;
        for(double bound2 : {guess2, margin2})
        {
          ranked.clear();
          for(std::size_t q : candidates)
          {
            const double d2 = (points[q] - p).squaredNorm();
            if(d2 <= bound2)
              ranked.emplace_back(d2, q);
          }
          exact = ranked.size() >= k;
          if(exact || bound2 == margin2)
            break;
        }
        if(exact)
        {
          std::nth_element(ranked.begin(), ranked.begin() + (k - 1), ranked.end());
          previous = ranked[k - 1].first;
          neighbors.clear();
          for(std::size_t r = 0; r < k; ++r)
            neighbors.push_back(ranked[r].second);
        }
        else
          index.nearest(p, k, neighbors, false);
        body(i, neighbors);
      }
    }
  });
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
