// Pictures of triangle meshes for side-by-side comparisons: flat-shaded facets with their
// edges drawn, orthographic camera, z-buffer. Two meshes rendered with the same camera can be
// compared pixel for pixel; the facet edges show how many triangles each one spends where.

#ifndef SFE_MESHING_MESH_RENDERING_H
#define SFE_MESHING_MESH_RENDERING_H

#include "utilities/surface_mesh_checks.h"
#include "utilities/png_image.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sfe_meshing {

/// An orthographic camera looking along `direction` at `center`; `half_width` is half the
/// width of the visible region, in model units; `up` is projected to the image's vertical.
struct Orthographic_camera
{
  std::array<double, 3> center{{0, 0, 0}};
  std::array<double, 3> direction{{-1, -0.8, -0.6}};
  std::array<double, 3> up{{0, 0, 1}};
  double half_width = 1;
};

namespace rendering_internal {

typedef std::array<double, 3> V3;
inline V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 cross(const V3& a, const V3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline V3 unit(const V3& a)
{
  const double l = std::sqrt(dot(a, a));
  return l > 0 ? V3{a[0] / l, a[1] / l, a[2] / l} : a;
}

} // namespace rendering_internal

/// draws `triangles` into `image` (cleared to white first) as seen by `camera`. Facets are grey,
/// lit from above-left of the viewer; both sides are lit, so an inverted mesh still shows. Facet edges are
/// drawn darker when `draw_edges` and the facet is more than a few pixels wide.
template <typename Point_3>
void render_triangles(const std::vector<Point_3>& points, const std::vector<Triangle_indices>& triangles,
                      const Orthographic_camera& camera, sfe_utilities::Png_image& image,
                      bool draw_edges = true)
{
  using namespace rendering_internal;
  const int W = image.width(), H = image.height();
  for(int y = 0; y < H; ++y)
    for(int x = 0; x < W; ++x)
      image.set_pixel(x, y, 255, 255, 255);
  const V3 forward = unit(camera.direction);
  const V3 right = unit(cross(forward, camera.up));
  const V3 up = cross(right, forward);
  // a light above-left of the viewer, so that the two faces of a crease seen head-on differ
  const V3 light = unit(V3{-forward[0] - 0.4 * right[0] + 0.6 * up[0], -forward[1] - 0.4 * right[1] + 0.6 * up[1],
                           -forward[2] - 0.4 * right[2] + 0.6 * up[2]});
  const double scale = 0.5 * W / camera.half_width; // pixels per model unit
  std::vector<double> depth(static_cast<std::size_t>(W) * H, (std::numeric_limits<double>::max)());

  auto project = [&](const Point_3& p) {
    const V3 d = sub(V3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}, camera.center);
    return V3{0.5 * W + scale * dot(d, right), 0.5 * H - scale * dot(d, up), dot(d, forward)};
  };
  for(const Triangle_indices& t : triangles) {
    const V3 a = project(points[t[0]]), b = project(points[t[1]]), c = project(points[t[2]]);
    // facet normal in camera space gives the shade
    const V3 pa{CGAL::to_double(points[t[0]].x()), CGAL::to_double(points[t[0]].y()), CGAL::to_double(points[t[0]].z())};
    const V3 pb{CGAL::to_double(points[t[1]].x()), CGAL::to_double(points[t[1]].y()), CGAL::to_double(points[t[1]].z())};
    const V3 pc{CGAL::to_double(points[t[2]].x()), CGAL::to_double(points[t[2]].y()), CGAL::to_double(points[t[2]].z())};
    const V3 n = unit(cross(sub(pb, pa), sub(pc, pa)));
    const double facing = dot(n, forward) > 0 ? -1. : 1.; // light both sides
    const double lambert = (std::max)(0., facing * dot(n, light));
    const double brightness = 0.35 + 0.62 * lambert;
    const unsigned char grey = static_cast<unsigned char>(std::min(255., 255 * brightness));
    const unsigned char dark = static_cast<unsigned char>(0.55 * grey);

    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if(std::abs(area) < 1e-12)
      continue;
    // distances to the edges in pixels: barycentric coordinate x (2 area / edge length)
    const double la = std::hypot(c[0] - b[0], c[1] - b[1]);
    const double lb = std::hypot(a[0] - c[0], a[1] - c[1]);
    const double lc = std::hypot(b[0] - a[0], b[1] - a[1]);
    const bool edges_visible = draw_edges && std::abs(area) / (std::max)({la, lb, lc}) > 3;
    const int x0 = (std::max)(0, static_cast<int>(std::floor((std::min)({a[0], b[0], c[0]}))));
    const int x1 = (std::min)(W - 1, static_cast<int>(std::ceil((std::max)({a[0], b[0], c[0]}))));
    const int y0 = (std::max)(0, static_cast<int>(std::floor((std::min)({a[1], b[1], c[1]}))));
    const int y1 = (std::min)(H - 1, static_cast<int>(std::ceil((std::max)({a[1], b[1], c[1]}))));
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
        const double w1 = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
        const double w2 = 1 - w0 - w1;
        if(w0 < 0 || w1 < 0 || w2 < 0)
          continue;
        const double z = w0 * a[2] + w1 * b[2] + w2 * c[2];
        double& zb = depth[static_cast<std::size_t>(y) * W + x];
        if(z >= zb)
          continue;
        zb = z;
        const double edge_pixels = (std::min)({w0 * std::abs(area) / la, w1 * std::abs(area) / lb,
                                               w2 * std::abs(area) / lc});
        const unsigned char v = (edges_visible && edge_pixels < 0.8) ? dark : grey;
        image.set_pixel(x, y, v, v, static_cast<unsigned char>(std::min(255, v + 12)));
      }
  }
}

} // namespace sfe_meshing

#endif // SFE_MESHING_MESH_RENDERING_H
