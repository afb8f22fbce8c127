// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The package's spatial grid: cubic cells keyed by `Grid_key`, the one packing of cell
// coordinates. Two structures use it: `Spatial_grid` below (a hash of the cells, for
// fixed-radius queries) and `Cell_grid` (All_nearest_neighbors.h: the cells of a fixed set in
// key order, for the all-points neighbourhood sweeps of stages 1 and 2).
//
// The meshing helpers ask two kinds of questions many times: "which points lie within r of x"
// (fits, curve repair) and "which curve sample is nearest to x, if any within r" (millions of
// implicit-function evaluations during Mesh_3). With the cell size equal to the query radius,
// both look at the 27 cells around x, which is faster than a kd-tree for these small radii.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H

#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>

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

  // Cells wrap around every 2^21 cells: points that far apart share keys and are then told
  // apart by their distance, at the cost of a longer scan (never on a real model).
  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    return Grid_key::pack(std::uint64_t(c[0]), std::uint64_t(c[1]), std::uint64_t(c[2]));
  }

  double m_cell_size;
  std::unordered_map<std::uint64_t, std::vector<Entry>> m_cells;
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H
