// The frame of feature_rendering.h: an orthographic projection of a view, z-buffered frame
// buffers, and the drawing of splats, segments and corners into them.

#ifndef SFE_UTILITIES_RENDER_FRAME_H
#define SFE_UTILITIES_RENDER_FRAME_H

#include "png_image.h"
#include "point_splats.h"

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
  std::vector<Colour> tint; // colour of the front splat's point (white: plain grey)
  std::vector<float> overlay_alpha;
  std::vector<Colour> overlay_colour;

  Frame(int w, int h)
    : width(w), height(h), depth(std::size_t(w) * std::size_t(h), std::numeric_limits<float>::infinity()),
      grey(depth.size(), 1.f), tint(depth.size(), Colour{255, 255, 255}), overlay_alpha(depth.size(), 0.f),
      overlay_colour(depth.size(), Colour{0, 0, 0})
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
                       double radius, const Colour& tint)
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
        frame.tint[i] = tint;
      }
    }
}

// Closes pinholes left between random discs: a pixel that is empty, or that sees a farther
// surface through the gap (deeper than `see_through` behind its neighbours), takes the mean
// depth and shade of its neighbours (and the tint of the last of them) if at least 7 of the 8
// are in front of it (pixels just outside a silhouette have at most 5).
inline void close_pinholes(Frame& frame, double see_through)
{
  const std::vector<float> depth = frame.depth, grey = frame.grey;
  const std::vector<Colour> tint = frame.tint;
  for(int y = 1; y + 1 < frame.height; ++y)
    for(int x = 1; x + 1 < frame.width; ++x) {
      const float centre = depth[frame.index(x, y)];
      int covering = 0;
      double depth_sum = 0, grey_sum = 0;
      Colour neighbour_tint = tint[frame.index(x, y)];
      for(int dy = -1; dy <= 1; ++dy)
        for(int dx = -1; dx <= 1; ++dx) {
          const std::size_t j = frame.index(x + dx, y + dy);
          if((dx != 0 || dy != 0) && double(depth[j]) < double(centre) - see_through) {
            ++covering;
            depth_sum += depth[j];
            grey_sum += grey[j];
            neighbour_tint = tint[j];
          }
        }
      if(covering >= 7) {
        frame.depth[frame.index(x, y)] = float(depth_sum / covering);
        frame.grey[frame.index(x, y)] = float(grey_sum / covering);
        frame.tint[frame.index(x, y)] = neighbour_tint;
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

} // namespace rendering_internal
} // namespace sfe_utilities

#endif // SFE_UTILITIES_RENDER_FRAME_H
