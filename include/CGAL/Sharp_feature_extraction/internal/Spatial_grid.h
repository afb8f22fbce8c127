// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The package's one spatial grid: points in cubic cells, for fixed-radius queries (the Mesh_3
// helpers) and for sweeps over all the points cell by cell (the neighbourhoods of stages 1 and
// 2, in All_nearest_neighbors.h). Cell coordinates are packed by `Grid_key`, which also keys
// the cells of stage 2's candidates.
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

/// Points stored by id in cubic cells of side `cell_size`, the cells of integer coordinates
/// floor((p - origin) / cell_size): radius queries (`for_each_within()`, `nearest_within()`)
/// and, for sweeps over all the points, the cells in the order of their first point with their
/// points in the order of insertion (`number_of_cells()`, `ids_around()`).
template <typename Point_3>
class Spatial_grid
{
public:
  explicit Spatial_grid(double cell_size = 1., const Vec3& origin = Vec3::Zero())
    : m_cell_size(cell_size > 0 ? cell_size : 1.), m_origin(origin)
  {}

  double cell_size() const { return m_cell_size; }

  void insert(const Point_3& p, std::size_t id)
  {
    const std::array<std::int64_t, 3> c = cell_of(p);
    const auto found = m_cell_of_key.emplace(key(c), m_cells.size());
    if(found.second)
      m_cells.push_back(Cell{c, {}});
    m_cells[found.first->second].entries.push_back(Entry{{double(p.x()), double(p.y()), double(p.z())}, id});
  }

  /// calls `visit(id, squared_distance)` for every stored point within `radius` of `q`.
  /// `radius` must not exceed the cell size.
  template <typename Visitor>
  void for_each_within(const Point_3& q, double radius, Visitor visit) const
  {
    const double r2 = radius * radius;
    for_each_entry_around(cell_of(q), [&](const Entry& e) {
      const double ex = e.xyz[0] - q.x(), ey = e.xyz[1] - q.y(), ez = e.xyz[2] - q.z();
      const double d2 = ex * ex + ey * ey + ez * ez;
      if(d2 <= r2)
        visit(e.id, d2);
    });
  }

  /// returns the id of the stored point nearest to `q` among those within `radius`, or
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

  /// The number of non-empty cells.
  std::size_t number_of_cells() const { return m_cells.size(); }
  /// The number of points of cell `c`, and the id of its `j`-th.
  std::size_t size(std::size_t c) const { return m_cells[c].entries.size(); }
  std::size_t id(std::size_t c, std::size_t j) const { return m_cells[c].entries[j].id; }

  /// The ids of the points of the 27 cells around cell `c` (itself included), appended to
  /// `out` (cleared first), cell by cell.
  void ids_around(std::size_t c, std::vector<std::size_t>& out) const
  {
    out.clear();
    for_each_entry_around(m_cells[c].coordinates, [&](const Entry& e) { out.push_back(e.id); });
  }

  /// The lowest corner of the box of the 27 cells around cell `c`.
  Vec3 low_corner_around(std::size_t c) const
  {
    const std::array<std::int64_t, 3>& k = m_cells[c].coordinates;
    return m_origin + m_cell_size * Vec3(double(k[0] - 1), double(k[1] - 1), double(k[2] - 1));
  }

  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

private:
  struct Entry
  {
    std::array<double, 3> xyz;
    std::size_t id;
  };

  struct Cell
  {
    std::array<std::int64_t, 3> coordinates;
    std::vector<Entry> entries;
  };

  std::array<std::int64_t, 3> cell_of(const Point_3& p) const
  {
    return {static_cast<std::int64_t>(std::floor((p.x() - m_origin.x()) / m_cell_size)),
            static_cast<std::int64_t>(std::floor((p.y() - m_origin.y()) / m_cell_size)),
            static_cast<std::int64_t>(std::floor((p.z() - m_origin.z()) / m_cell_size))};
  }

  // The entries of the 27 cells around `c`, by ascending x, then y, then z.
  template <typename Visitor>
  void for_each_entry_around(const std::array<std::int64_t, 3>& c, Visitor visit) const
  {
    for(std::int64_t dx = -1; dx <= 1; ++dx)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = m_cell_of_key.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if(it == m_cell_of_key.end())
            continue;
          for(const Entry& e : m_cells[it->second].entries)
            visit(e);
        }
  }

  // Cells wrap around every 2^21 cells: points that far apart share keys and are then told
  // apart by their distance, at the cost of a longer scan (never on a real model).
  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    return Grid_key::pack(std::uint64_t(c[0]), std::uint64_t(c[1]), std::uint64_t(c[2]));
  }

  double m_cell_size;
  Vec3 m_origin;
  std::unordered_map<std::uint64_t, std::size_t> m_cell_of_key;
  std::vector<Cell> m_cells;
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SPATIAL_GRID_H
