// Surface splats for feature_rendering.h: a small disc per point of a cloud, in the plane
// fitted to its neighbours (a principal component analysis), sized to cover the surface.

#ifndef SFE_UTILITIES_POINT_SPLATS_H
#define SFE_UTILITIES_POINT_SPLATS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sfe_utilities {
namespace rendering_internal {

using Point = std::array<double, 3>;
using Colour = std::array<unsigned char, 3>;

inline Point operator-(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point cross(const Point& a, const Point& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// ---------------------------------------------------------------------------------------------
// Splats: a disc per point, in the plane fitted to its neighbours.

struct Splat
{
  Point normal = {0, 0, 0}; // unit, or zero if the neighbourhood is too small to fit a plane
  double radius = 0;        // in model units
};

// Eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix given by its six entries
// (xx, yy, zz, xy, xz, yz). The eigenvalue has a closed form (trigonometric solution of the
// characteristic cubic); the eigenvector is the longest cross product of two rows of
// (matrix - eigenvalue x identity), which are all orthogonal to it.
inline Point smallest_eigenvector(const std::array<double, 6>& m)
{
  const double off_diagonal = m[3] * m[3] + m[4] * m[4] + m[5] * m[5];
  const double mean = (m[0] + m[1] + m[2]) / 3;
  const double spread = std::sqrt(((m[0] - mean) * (m[0] - mean) + (m[1] - mean) * (m[1] - mean) +
                                   (m[2] - mean) * (m[2] - mean) + 2 * off_diagonal) / 6);
  if(!(spread > 0))
    return {0, 0, 1}; // isotropic: every direction is an eigenvector
  // B = (M - mean I) / spread has eigenvalues 2 cos(angle + 2 pi k / 3), with det(B) = 2 cos(3 angle).
  const double b[6] = {(m[0] - mean) / spread, (m[1] - mean) / spread, (m[2] - mean) / spread,
                       m[3] / spread,          m[4] / spread,          m[5] / spread};
  const double det = b[0] * (b[1] * b[2] - b[5] * b[5]) - b[3] * (b[3] * b[2] - b[5] * b[4]) +
                     b[4] * (b[3] * b[5] - b[1] * b[4]);
  const double pi = 3.14159265358979323846;
  const double angle = std::acos(std::clamp(det / 2, -1., 1.)) / 3;
  const double smallest = mean + 2 * spread * std::cos(angle + 2 * pi / 3);

  const Point rows[3] = {{m[0] - smallest, m[3], m[4]}, {m[3], m[1] - smallest, m[5]}, {m[4], m[5], m[2] - smallest}};
  Point best = cross(rows[0], rows[1]);
  for(const Point& candidate : {cross(rows[0], rows[2]), cross(rows[1], rows[2])})
    if(dot(candidate, candidate) > dot(best, best))
      best = candidate;
  const double length = std::sqrt(dot(best, best));
  if(!(length > 0))
    return {0, 0, 1};
  return {best[0] / length, best[1] / length, best[2] / length};
}

// Points sorted into cubic cells, to find the neighbours of a point in the 27 cells around it.
class Point_grid
{
public:
  Point_grid(const std::vector<Point>& points, const Point& origin, double cell_size)
    : m_origin(origin), m_cell_size(cell_size)
  {
    for(std::size_t i = 0; i < points.size(); ++i)
      m_cells[key(cell_of(points[i]))].push_back(i);
  }

  // Calls `visit(index)` for every point within the 27 cells around `p`.
  template <typename Visitor>
  void for_each_near(const Point& p, Visitor visit) const
  {
    const std::array<std::int64_t, 3> c = cell_of(p);
    for(std::int64_t dz = -1; dz <= 1; ++dz)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dx = -1; dx <= 1; ++dx) {
          const auto found = m_cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if(found != m_cells.end())
            for(std::size_t i : found->second)
              visit(i);
        }
  }

private:
  std::array<std::int64_t, 3> cell_of(const Point& p) const
  {
    std::array<std::int64_t, 3> c;
    for(std::size_t i = 0; i < 3; ++i)
      c[i] = static_cast<std::int64_t>(std::floor((p[i] - m_origin[i]) / m_cell_size));
    return c;
  }

  // Cell coordinates are below 2^20 (see `estimate_splats`); the +1 keeps neighbours of cell 0
  // non-negative.
  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    const auto field = [](std::int64_t v) { return static_cast<std::uint64_t>(v + 1) & 0x1FFFFF; };
    return field(c[0]) | (field(c[1]) << 21) | (field(c[2]) << 42);
  }

  Point m_origin;
  double m_cell_size;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

inline double median_radius(const std::vector<Splat>& splats)
{
  if(splats.empty())
    return 0;
  std::vector<double> radii;
  radii.reserve(splats.size());
  for(const Splat& s : splats)
    radii.push_back(s.radius);
  std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
  return radii[radii.size() / 2];
}

// One splat per point. The neighbourhood radius is chosen so that about 20 points fall in it
// if the points were spread evenly over the faces of the bounding box; the disc radius then
// gives each point 6 times its share of the local area, so that discs around random samples
// leave about e^-6 = 0.25% of the surface uncovered (pinholes that `close_pinholes` fills).
inline std::vector<Splat> estimate_splats(const std::vector<Point>& points)
{
  std::vector<Splat> splats(points.size());
  if(points.empty())
    return splats;
  Point lo = points.front(), hi = points.front();
  for(const Point& p : points)
    for(std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  const Point extent = hi - lo;
  const double pi = 3.14159265358979323846;
  const double diagonal = std::sqrt(dot(extent, extent));
  const double box_area = 2 * (extent[0] * extent[1] + extent[1] * extent[2] + extent[2] * extent[0]);
  const double wanted_neighbours = 20, coverage = 6;
  double radius = std::sqrt(wanted_neighbours * box_area / (pi * double(points.size())));
  radius = std::max(radius, diagonal * 1e-6); // all points on a line: no box area
  radius = std::max(radius, std::max({extent[0], extent[1], extent[2]}) / 1e6); // grid keys fit 20 bits
  if(!(radius > 0))
    return splats; // all points equal: nothing to fit

  const double max_radius = 0.05 * diagonal;
  const Point_grid grid(points, lo, radius);
  for(std::size_t i = 0; i < points.size(); ++i) {
    // Covariance of the neighbours, accumulated relative to the point for accuracy.
    std::size_t count = 0;
    Point sum = {0, 0, 0};
    std::array<double, 6> products = {0, 0, 0, 0, 0, 0};
    grid.for_each_near(points[i], [&](std::size_t j) {
      const Point d = points[j] - points[i];
      if(dot(d, d) > radius * radius)
        return;
      ++count;
      for(std::size_t k = 0; k < 3; ++k)
        sum[k] += d[k];
      products[0] += d[0] * d[0]; products[1] += d[1] * d[1]; products[2] += d[2] * d[2];
      products[3] += d[0] * d[1]; products[4] += d[0] * d[2]; products[5] += d[1] * d[2];
    });
    const double n = double(count);
    // count >= 1 (the point itself); the cap keeps a handful of points from filling the picture.
    splats[i].radius = std::min(radius * std::sqrt(coverage / n), max_radius);
    if(count < 4)
      continue; // too few neighbours (an outlier): drawn as a disc facing the viewer
    const Point mean = {sum[0] / n, sum[1] / n, sum[2] / n};
    const std::array<double, 6> covariance = {
      products[0] / n - mean[0] * mean[0], products[1] / n - mean[1] * mean[1], products[2] / n - mean[2] * mean[2],
      products[3] / n - mean[0] * mean[1], products[4] / n - mean[0] * mean[2], products[5] / n - mean[1] * mean[2]};
    splats[i].normal = smallest_eigenvector(covariance);
  }
  // Isolated points (outliers) would get huge discs: they become dots of half the typical
  // size, and no disc is larger than twice that size.
  const double typical = median_radius(splats);
  for(Splat& splat : splats) {
    const bool isolated = (splat.normal == Point{0, 0, 0});
    splat.radius = isolated ? 0.5 * typical : std::min(splat.radius, 2 * typical);
  }
  return splats;
}

} // namespace rendering_internal
} // namespace sfe_utilities

#endif // SFE_UTILITIES_POINT_SPLATS_H
