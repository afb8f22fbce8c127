// Pictures of a point cloud with its feature curves, for the demo and the manual's figures.
//
// An orthographic software renderer with a z-buffer. Each point becomes a small disc in the
// tangent plane of the cloud (a "surface splat"; the normal comes from a principal component
// analysis of its neighbours), shaded grey by a light from the upper left and darker with
// depth. Discs, unlike screen-facing dots, cover the surface without gaps even where it is
// seen at a grazing angle, and give the z-buffer the depth of the surface itself.
// Feature polylines are drawn on top as thick coloured lines, one palette colour per curve,
// and corners as larger dark dots; the parts hidden behind the surface are drawn faded.

#ifndef SFE_UTILITIES_FEATURE_RENDERING_H
#define SFE_UTILITIES_FEATURE_RENDERING_H

#include "png_image.h"

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

/// How to look at the scene. The model is turned by `azimuth_degrees` about the z axis, then
/// by `elevation_degrees` about the x axis, and seen along the y axis with z up (so a positive
/// elevation shows the top of a z-up model). The scene is fitted into the viewport.
struct Render_view
{
  double azimuth_degrees = 35;
  double elevation_degrees = 25;
  /// empty border on each side, as a fraction of the viewport width and height.
  double margin = 0.05;
  /// pixels per model unit; 0: the largest scale that fits the scene into the viewport.
  double scale = 0;
  /// multiplies the splat radii, which are chosen from the local point spacing.
  double splat_scale = 1;
  /// width of feature lines and radius of corner dots, in pixels.
  double line_width = 3.5;
  double corner_radius = 5;
  /// opacity of the curve parts hidden behind the surface (0 hides them).
  double hidden_curve_opacity = 0.3;
  /// sub-rectangle of the image to draw into; a width or height of 0 means the whole image.
  int viewport_x = 0;
  int viewport_y = 0;
  int viewport_width = 0;
  int viewport_height = 0;
};

/// two 3/4 views from opposite sides, which together show most of a closed model.
inline std::vector<Render_view> front_and_back_views()
{
  Render_view front, back;
  back.azimuth_degrees = front.azimuth_degrees + 180;
  return {front, back};
}

namespace rendering_internal {

using Point = std::array<double, 3>;
using Colour = std::array<unsigned char, 3>;

inline Point operator-(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point cross(const Point& a, const Point& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Distinct, saturated colours that stand out on grey; curve i gets colour i modulo the size.
inline const std::vector<Colour>& curve_palette()
{
  static const std::vector<Colour> palette = {
    {228, 26, 28},  {31, 120, 220}, {40, 170, 60},  {255, 127, 0},  {150, 60, 180}, {0, 175, 175},
    {230, 50, 150}, {160, 90, 30},  {120, 170, 0},  {20, 40, 150},  {240, 190, 0},  {130, 0, 40}};
  return palette;
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

// ---------------------------------------------------------------------------------------------
// Projection and frame buffers.

// Orthographic projection to pixel coordinates: x to the right, y downwards, and the depth
// (distance from the viewer, in model units) for the z-buffer.
class Projection
{
public:
  Projection(const Render_view& view, int viewport_width, int viewport_height)
    : m_width(viewport_width), m_height(viewport_height)
  {
    const double pi = 3.14159265358979323846;
    const double a = view.azimuth_degrees * pi / 180, b = view.elevation_degrees * pi / 180;
    // Rows of Rx(b) * Rz(a), taken in the order (screen right, screen up, depth).
    m_rows[0] = {std::cos(a), -std::sin(a), 0};
    m_rows[1] = {std::sin(a) * std::sin(b), std::cos(a) * std::sin(b), std::cos(b)};
    m_rows[2] = {std::sin(a) * std::cos(b), std::cos(a) * std::cos(b), -std::sin(b)};
  }

  // Coordinates (right, up, depth) of a point or a direction, before scaling.
  Point rotate(const Point& p) const { return {dot(m_rows[0], p), dot(m_rows[1], p), dot(m_rows[2], p)}; }

  // Records the extent of the scene; call for every point before `fitting_scale()`.
  void include(const Point& p)
  {
    const Point r = rotate(p);
    for(std::size_t i = 0; i < 3; ++i) {
      m_lo[i] = std::min(m_lo[i], r[i]);
      m_hi[i] = std::max(m_hi[i], r[i]);
    }
  }

  bool empty() const { return !(m_lo[0] <= m_hi[0]); }

  // Largest scale that fits the recorded extent inside the viewport minus its margins.
  double fitting_scale(double margin) const
  {
    const double usable_width = m_width * (1 - 2 * margin), usable_height = m_height * (1 - 2 * margin);
    double scale = std::numeric_limits<double>::max();
    if(!empty() && m_hi[0] > m_lo[0])
      scale = std::min(scale, usable_width / (m_hi[0] - m_lo[0]));
    if(!empty() && m_hi[1] > m_lo[1])
      scale = std::min(scale, usable_height / (m_hi[1] - m_lo[1]));
    return scale == std::numeric_limits<double>::max() ? 1. : scale;
  }

  void set_scale(double scale) { m_scale = scale; }
  double scale() const { return m_scale; }
  double depth_min() const { return m_lo[2]; }
  double depth_range() const { return std::max(m_hi[2] - m_lo[2], std::numeric_limits<double>::min()); }

  // (pixel x, pixel y, depth) with the scene centred in the viewport.
  Point project(const Point& p) const
  {
    const Point r = rotate(p);
    return {0.5 * m_width + m_scale * (r[0] - 0.5 * (m_lo[0] + m_hi[0])),
            0.5 * m_height - m_scale * (r[1] - 0.5 * (m_lo[1] + m_hi[1])), r[2]};
  }

private:
  int m_width, m_height;
  std::array<Point, 3> m_rows;
  Point m_lo = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                std::numeric_limits<double>::max()};
  Point m_hi = {-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                -std::numeric_limits<double>::max()};
  double m_scale = 1;
};

// Viewport-sized buffers: the z-buffer with the shade of the front splat, and a layer for
// curves that is composited once, so overlapping anti-aliased segment ends do not blend twice.
struct Frame
{
  int width, height;
  std::vector<float> depth; // +infinity where no splat was drawn
  std::vector<float> grey;  // shade of the front splat, in [0,1]
  std::vector<float> overlay_alpha;
  std::vector<Colour> overlay_colour;

  Frame(int w, int h)
    : width(w), height(h), depth(std::size_t(w) * std::size_t(h), std::numeric_limits<float>::infinity()),
      grey(depth.size(), 1.f), overlay_alpha(depth.size(), 0.f), overlay_colour(depth.size(), Colour{0, 0, 0})
  {}

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }

  void paint_overlay(int x, int y, const Colour& colour, double alpha)
  {
    const std::size_t i = index(x, y);
    if(alpha > overlay_alpha[i]) {
      overlay_alpha[i] = float(alpha);
      overlay_colour[i] = colour;
    }
  }
};

// ---------------------------------------------------------------------------------------------
// Drawing.

// Grey of a surface with the given normal (in view coordinates, facing the viewer) at relative
// depth t in [0,1]: a light from the upper left in front, and 35% darker at the back.
inline double surface_grey(const Point& view_normal, double t)
{
  const Point light = {-0.45, 0.55, -0.70}; // (right, up, depth): depth < 0 is towards the viewer
  const double ambient = 0.32, diffuse = 0.6, far_darkening = 0.35;
  return (ambient + diffuse * std::max(0., dot(view_normal, light))) * (1 - far_darkening * t);
}

// Rasterises the disc of one splat: for each pixel, the depth where the pixel's line of sight
// meets the disc plane, kept if inside the disc and in front of what the pixel shows.
inline void draw_splat(Frame& frame, const Projection& projection, const Point& point, const Splat& splat,
                       double radius)
{
  const double min_facing = 0.2; // limits the depth slope of discs seen edge-on
  Point n = projection.rotate(splat.normal);
  if(n[2] > 0)
    n = {-n[0], -n[1], -n[2]}; // two-sided: the normal faces the viewer
  if(n[0] == 0 && n[1] == 0 && n[2] == 0)
    n = {0, 0, -1}; // no normal: a disc facing the viewer
  const double facing = std::min(n[2], -min_facing);
  const Point centre = projection.project(point);
  const double t = (centre[2] - projection.depth_min()) / projection.depth_range();
  const float grey = float(surface_grey(n, t));

  const double scale = projection.scale();
  const int reach = int(std::ceil(radius * scale));
  const int cx = int(std::floor(centre[0])), cy = int(std::floor(centre[1]));
  for(int y = std::max(cy - reach, 0); y <= std::min(cy + reach, frame.height - 1); ++y)
    for(int x = std::max(cx - reach, 0); x <= std::min(cx + reach, frame.width - 1); ++x) {
      const double right = (x + 0.5 - centre[0]) / scale, up = (centre[1] - y - 0.5) / scale;
      const double depth_offset = -(n[0] * right + n[1] * up) / facing;
      const bool own_pixel = (x == cx && y == cy); // tiny splats still cover their own pixel
      if(!own_pixel && right * right + up * up + depth_offset * depth_offset > radius * radius)
        continue;
      const std::size_t i = frame.index(x, y);
      const float depth = float(centre[2] + depth_offset);
      if(depth < frame.depth[i]) {
        frame.depth[i] = depth;
        frame.grey[i] = grey;
      }
    }
}

// Closes pinholes left between random discs: a pixel that is empty, or that sees a farther
// surface through the gap (deeper than `see_through` behind its neighbours), takes the mean
// depth and shade of its neighbours if at least 7 of the 8 are in front of it (pixels just
// outside a silhouette have at most 5).
inline void close_pinholes(Frame& frame, double see_through)
{
  const std::vector<float> depth = frame.depth, grey = frame.grey;
  for(int y = 1; y + 1 < frame.height; ++y)
    for(int x = 1; x + 1 < frame.width; ++x) {
      const float centre = depth[frame.index(x, y)];
      int covering = 0;
      double depth_sum = 0, grey_sum = 0;
      for(int dy = -1; dy <= 1; ++dy)
        for(int dx = -1; dx <= 1; ++dx) {
          const std::size_t j = frame.index(x + dx, y + dy);
          if((dx != 0 || dy != 0) && double(depth[j]) < double(centre) - see_through) {
            ++covering;
            depth_sum += depth[j];
            grey_sum += grey[j];
          }
        }
      if(covering >= 7) {
        frame.depth[frame.index(x, y)] = float(depth_sum / covering);
        frame.grey[frame.index(x, y)] = float(grey_sum / covering);
      }
    }
}

// The surface hides a curve point if splats are in front of it by more than `tolerance`
// (curves lie on the surface, so the splats around them must not hide them).
inline bool hidden(const Frame& frame, int x, int y, double depth, double tolerance)
{
  return double(frame.depth[frame.index(x, y)]) < depth - tolerance;
}

inline void draw_segment(Frame& frame, const Point& a, const Point& b, double width, const Colour& colour,
                         double hidden_opacity, double tolerance)
{
  const double half = 0.5 * width;
  const int x_min = int(std::floor(std::min(a[0], b[0]) - half - 1));
  const int x_max = int(std::ceil(std::max(a[0], b[0]) + half + 1));
  const int y_min = int(std::floor(std::min(a[1], b[1]) - half - 1));
  const int y_max = int(std::ceil(std::max(a[1], b[1]) + half + 1));
  const double ux = b[0] - a[0], uy = b[1] - a[1], length2 = ux * ux + uy * uy;
  for(int y = std::max(y_min, 0); y <= std::min(y_max, frame.height - 1); ++y)
    for(int x = std::max(x_min, 0); x <= std::min(x_max, frame.width - 1); ++x) {
      const double px = x + 0.5 - a[0], py = y + 0.5 - a[1];
      const double t = length2 > 0 ? std::clamp((px * ux + py * uy) / length2, 0., 1.) : 0.;
      const double distance = std::hypot(px - t * ux, py - t * uy);
      const double coverage = std::clamp(half + 0.5 - distance, 0., 1.); // anti-aliased edge
      if(coverage <= 0)
        continue;
      const double depth = a[2] + t * (b[2] - a[2]);
      frame.paint_overlay(x, y, colour, coverage * (hidden(frame, x, y, depth, tolerance) ? hidden_opacity : 1.));
    }
}

// A dark dot with a white rim, so that it shows on the curves it joins.
inline void draw_corner(Png_image& image, int x0, int y0, const Frame& frame, const Point& c, double radius,
                        double hidden_opacity, double tolerance)
{
  const double rim = std::max(1.5, 0.3 * radius);
  const int cx = int(std::floor(c[0])), cy = int(std::floor(c[1]));
  const double opacity = frame.contains(cx, cy) && hidden(frame, cx, cy, c[2], tolerance) ? hidden_opacity : 1.;
  const int reach = int(std::ceil(radius + rim)) + 1;
  for(int y = cy - reach; y <= cy + reach; ++y)
    for(int x = cx - reach; x <= cx + reach; ++x) {
      if(!frame.contains(x, y))
        continue;
      const double distance = std::hypot(x + 0.5 - c[0], y + 0.5 - c[1]);
      const double outer = std::clamp(radius + rim + 0.5 - distance, 0., 1.);
      const double inner = std::clamp(radius + 0.5 - distance, 0., 1.);
      image.blend_pixel(x0 + x, y0 + y, 255, 255, 255, opacity * outer);
      image.blend_pixel(x0 + x, y0 + y, 25, 25, 25, opacity * inner);
    }
}

inline Projection fitted_projection(const Render_view& view, int width, int height, const std::vector<Point>& points,
                                    const std::vector<std::vector<Point>>& polylines, const std::vector<Point>& corners)
{
  Projection projection(view, width, height);
  for(const Point& p : points)
    projection.include(p);
  for(const auto& polyline : polylines)
    for(const Point& p : polyline)
      projection.include(p);
  for(const Point& p : corners)
    projection.include(p);
  projection.set_scale(view.scale > 0 ? view.scale : projection.fitting_scale(view.margin));
  return projection;
}

inline std::array<int, 4> viewport(const Png_image& image, const Render_view& view)
{
  if(view.viewport_width <= 0 || view.viewport_height <= 0)
    return {0, 0, image.width(), image.height()};
  return {view.viewport_x, view.viewport_y, view.viewport_width, view.viewport_height};
}

inline void render_with_splats(Png_image& image, const std::vector<Point>& points, const std::vector<Splat>& splats,
                               const std::vector<std::vector<Point>>& polylines, const std::vector<Point>& corners,
                               const Render_view& view)
{
  const std::array<int, 4> port = viewport(image, view);
  const int x0 = port[0], y0 = port[1];
  if(port[2] <= 0 || port[3] <= 0)
    return;
  const Projection projection = fitted_projection(view, port[2], port[3], points, polylines, corners);
  if(projection.empty())
    return;

  Frame frame(port[2], port[3]);
  for(std::size_t i = 0; i < points.size(); ++i)
    draw_splat(frame, projection, points[i], splats[i], view.splat_scale * splats[i].radius);
  const double typical_radius = view.splat_scale * median_radius(splats);
  close_pinholes(frame, 2 * typical_radius);
  for(int y = 0; y < frame.height; ++y)
    for(int x = 0; x < frame.width; ++x) {
      const std::size_t i = frame.index(x, y);
      if(std::isfinite(frame.depth[i])) {
        const auto level = static_cast<unsigned char>(std::clamp(255.f * frame.grey[i], 0.f, 255.f));
        image.set_pixel(x0 + x, y0 + y, level, level, level);
      }
    }

  // A curve point counts as hidden only if the surface is in front of it by more than two
  // typical splat radii (discs near a convex crease stick out past it) or 0.5% of the depth range.
  const double tolerance =
    std::max(2 * typical_radius, 0.005 * projection.depth_range()) +
    1.5 / projection.scale(); // plus the depth change across a pixel or so
  const std::vector<Colour>& palette = curve_palette();
  for(std::size_t i = 0; i < polylines.size(); ++i)
    for(std::size_t k = 0; k + 1 < polylines[i].size(); ++k)
      draw_segment(frame, projection.project(polylines[i][k]), projection.project(polylines[i][k + 1]),
                   view.line_width, palette[i % palette.size()], view.hidden_curve_opacity, tolerance);
  for(int y = 0; y < frame.height; ++y)
    for(int x = 0; x < frame.width; ++x) {
      const std::size_t i = frame.index(x, y);
      const Colour& c = frame.overlay_colour[i];
      image.blend_pixel(x0 + x, y0 + y, c[0], c[1], c[2], frame.overlay_alpha[i]);
    }
  for(const Point& corner : corners)
    draw_corner(image, x0, y0, frame, projection.project(corner), view.corner_radius, view.hidden_curve_opacity,
                tolerance);
}

} // namespace rendering_internal

/// draws `points` as grey splats, `polylines` as coloured lines and `corners` as dots into the
/// viewport of `image` given by `view` (the rest of the image is left untouched).
inline void render_points_and_polylines(Png_image& image, const std::vector<std::array<double, 3>>& points,
                                        const std::vector<std::vector<std::array<double, 3>>>& polylines,
                                        const std::vector<std::array<double, 3>>& corners, const Render_view& view)
{
  rendering_internal::render_with_splats(image, points, rendering_internal::estimate_splats(points), polylines,
                                         corners, view);
}

/// splits `image` into as many equal columns as `views` (their viewports are ignored) and
/// renders the scene once per column, at one common scale so that sizes compare across views.
inline void render_side_by_side(Png_image& image, const std::vector<std::array<double, 3>>& points,
                                const std::vector<std::vector<std::array<double, 3>>>& polylines,
                                const std::vector<std::array<double, 3>>& corners, std::vector<Render_view> views)
{
  if(views.empty())
    return;
  const int columns = int(views.size());
  const int column_width = image.width() / columns;
  double common_scale = std::numeric_limits<double>::max();
  for(Render_view& view : views) {
    view.viewport_y = 0;
    view.viewport_width = column_width;
    view.viewport_height = image.height();
    if(view.scale <= 0)
      common_scale = std::min(common_scale, rendering_internal::fitted_projection(
                                              view, column_width, image.height(), points, polylines, corners).scale());
  }
  const std::vector<rendering_internal::Splat> splats = rendering_internal::estimate_splats(points);
  for(int c = 0; c < columns; ++c) {
    Render_view& view = views[std::size_t(c)];
    view.viewport_x = c * column_width;
    if(view.scale <= 0)
      view.scale = common_scale;
    rendering_internal::render_with_splats(image, points, splats, polylines, corners, view);
  }
}

} // namespace sfe_utilities

#endif // SFE_UTILITIES_FEATURE_RENDERING_H
