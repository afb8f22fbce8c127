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
#include "render_frame.h"

#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>

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

// Distinct, saturated colours that stand out on grey; curve i gets colour i modulo the size.
inline const std::vector<Colour>& curve_palette()
{
  static const std::vector<Colour> palette = {
    {228, 26, 28},  {31, 120, 220}, {40, 170, 60},  {255, 127, 0},  {150, 60, 180}, {0, 175, 175},
    {230, 50, 150}, {160, 90, 30},  {120, 170, 0},  {20, 40, 150},  {240, 190, 0},  {130, 0, 40}};
  return palette;
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
                               const std::vector<Colour>& tints, const std::vector<std::vector<Point>>& polylines,
                               const std::vector<Point>& corners, const Render_view& view)
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
    draw_splat(frame, projection, points[i], splats[i], view.splat_scale * splats[i].radius,
               tints.empty() ? Colour{255, 255, 255} : tints[i]);
  const double typical_radius = view.splat_scale * median_radius(splats);
  close_pinholes(frame, 2 * typical_radius);
  for(int y = 0; y < frame.height; ++y)
    for(int x = 0; x < frame.width; ++x) {
      const std::size_t i = frame.index(x, y);
      if(std::isfinite(frame.depth[i])) {
        auto level = [&](int channel) {
          return static_cast<unsigned char>(std::clamp(frame.grey[i] * float(frame.tint[i][channel]), 0.f, 255.f));
        };
        image.set_pixel(x0 + x, y0 + y, level(0), level(1), level(2));
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
  rendering_internal::render_with_splats(image, points, rendering_internal::estimate_splats(points), {}, polylines,
                                         corners, view);
}

/// An RGB colour.
using rendering_internal::Colour;

/// A light colour for patch `label` (the hue of `CGAL::IO::patch_colour()`, as in the PLY files
/// of the command-line program, half-way to white: shaded like the grey points, so the surface
/// still reads), dark grey for `unassigned`.
inline Colour patch_tint(std::size_t label, std::size_t unassigned)
{
  if(label == unassigned)
    return Colour{90, 90, 90};
  const std::array<unsigned char, 3> c = CGAL::IO::patch_colour(label);
  return Colour{static_cast<unsigned char>((c[0] + 255) / 2), static_cast<unsigned char>((c[1] + 255) / 2),
                static_cast<unsigned char>((c[2] + 255) / 2)};
}

/// splits `image` into as many equal columns as `views` (their viewports are ignored) and
/// renders the scene once per column, at one common scale so that sizes compare across views.
/// `tints`: one colour per point that its grey shade multiplies (empty: plain grey).
inline void render_side_by_side(Png_image& image, const std::vector<std::array<double, 3>>& points,
                                const std::vector<std::vector<std::array<double, 3>>>& polylines,
                                const std::vector<std::array<double, 3>>& corners, std::vector<Render_view> views,
                                const std::vector<Colour>& tints = {})
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
    rendering_internal::render_with_splats(image, points, splats, tints, polylines, corners, view);
  }
}

} // namespace sfe_utilities

#endif // SFE_UTILITIES_FEATURE_RENDERING_H
