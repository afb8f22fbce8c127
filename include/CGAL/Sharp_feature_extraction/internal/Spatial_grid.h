// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A uniform hash grid over 3D points for fixed-radius queries.
//
// The meshing helpers ask two kinds of questions many times: "which points lie within r of x"
// (fits, curve repair) and "which curve sample is nearest to x, if any within r" (millions of
// implicit-function evaluations during Mesh_3). With the cell size equal to the query radius,
// both look at the 27 cells around x, which is faster than a kd-tree for these small radii.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Points stored by index in cubic cells of side `cell_size`.
template <typename Point_3>
class Spatial_grid
{
public:
  explicit Spatial_grid(double cell_size = 1.) : m_cell_size(cell_size > 0 ? cell_size : 1.) {}

  double cell_size() const { return m_cell_size; }

  void insert(const Point_3& p, std::size_t id)
  {
    m_cells[key(cell_of(p))].push_back(Entry{{p.x(), p.y(), p.z()}, id});
  }

  /// calls `visit(id, squared_distance)` for every stored point within `radius` of `q`.
  /// `radius` must not exceed the cell size.
  template <typename Visitor>
  void for_each_within(const Point_3& q, double radius, Visitor visit) const
  {
    const double r2 = radius * radius;
    const std::array<std::int64_t, 3> c = cell_of(q);
    for(std::int64_t dx = -1; dx <= 1; ++dx)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = m_cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if(it == m_cells.end())
            continue;
          for(const Entry& e : it->second) {
            const double ex = e.xyz[0] - q.x(), ey = e.xyz[1] - q.y(), ez = e.xyz[2] - q.z();
            const double d2 = ex * ex + ey * ey + ez * ez;
            if(d2 <= r2)
              visit(e.id, d2);
          }
        }
  }

  /// returns the index of the stored point nearest to `q` among those within `radius`, or
  /// `none` if there is none.
  std::size_t nearest_within(const Point_3& q, double radius, double* squared_distance = nullptr) const
  {
    std::size_t best = none;
    double best_d2 = (std::numeric_limits<double>::max)();
    for_each_within(q, radius, [&](std::size_t id, double d2) {
      if(d2 < best_d2) {
        best_d2 = d2;
        best = id;
      }
    });
    if(squared_distance != nullptr)
      *squared_distance = best_d2;
    return best;
  }

  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

private:
  struct Entry
  {
    std::array<double, 3> xyz;
    std::size_t id;
  };

  std::array<std::int64_t, 3> cell_of(const Point_3& p) const
  {
    return {static_cast<std::int64_t>(std::floor(p.x() / m_cell_size)),
            static_cast<std::int64_t>(std::floor(p.y() / m_cell_size)),
            static_cast<std::int64_t>(std::floor(p.z() / m_cell_size))};
  }

  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    // 21 bits per axis: cells are a few sampling spacings wide, so any real model fits.
    const std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return ((std::uint64_t(c[0]) & mask) << 42) | ((std::uint64_t(c[1]) & mask) << 21) |
           (std::uint64_t(c[2]) & mask);
  }

  double m_cell_size;
  std::unordered_map<std::uint64_t, std::vector<Entry>> m_cells;
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H
