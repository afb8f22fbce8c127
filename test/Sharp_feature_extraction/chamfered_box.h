// A box with one chamfered edge: a small CAD part whose creases we know exactly (test helper
// of test_meshing_with_features.cpp), and uniform sampling of triangles.
//
// Seven planar faces, ten corners of valence 3, fifteen straight creases: twelve at 90 degrees
// and three at 45 degrees (the chamfer's). The tests mesh samples of it with the exact creases
// standing in for extracted curves, so that the meshing code is checked independently of the
// extraction.

#ifndef SFE_TEST_CHAMFERED_BOX_H
#define SFE_TEST_CHAMFERED_BOX_H

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace sfe_test {

typedef std::array<std::size_t, 3> Triangle_indices;

/// `n` points uniformly distributed on the area of the triangles, each moved by a uniform
/// offset in a ball of radius `noise` times the diagonal of the bounding box of `corners`.
template <typename Point_3>
std::vector<Point_3> sample_triangles(const std::vector<Point_3>& corners, const std::vector<Triangle_indices>& triangles,
                                      std::size_t n, double noise, unsigned seed)
{
  std::vector<double> cumulative_area;
  double total = 0;
  for(const Triangle_indices& t : triangles) {
    total += std::sqrt(CGAL::to_double(CGAL::squared_area(corners[t[0]], corners[t[1]], corners[t[2]])));
    cumulative_area.push_back(total);
  }
  CGAL::Bbox_3 box;
  for(const Point_3& p : corners)
    box += p.bbox();
  const double radius = noise * std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                          CGAL::square(box.zmax() - box.zmin()));
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<Point_3> points;
  while(points.size() < n) {
    const double pick = uniform(generator) * total;
    const std::size_t i = std::lower_bound(cumulative_area.begin(), cumulative_area.end(), pick) - cumulative_area.begin();
    const Triangle_indices& t = triangles[(std::min)(i, triangles.size() - 1)];
    double u = uniform(generator), v = uniform(generator);
    if(u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    Point_3 p = corners[t[0]] + u * (corners[t[1]] - corners[t[0]]) + v * (corners[t[2]] - corners[t[0]]);
    if(radius > 0) {
      double x, y, z;
      do {
        x = 2 * uniform(generator) - 1;
        y = 2 * uniform(generator) - 1;
        z = 2 * uniform(generator) - 1;
      } while(x * x + y * y + z * z > 1);
      p = p + radius * typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3(x, y, z);
    }
    points.push_back(p);
  }
  return points;
}

/// The box [0, size_x] x [0, size_y] x [0, size_z] whose edge {y = size_y, z = size_z} is cut
/// by a 45-degree chamfer of width `chamfer` along y and z.
template <typename GeomTraits>
struct Chamfered_box
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  double size_x = 1, size_y = 0.8, size_z = 0.6, chamfer = 0.15;

  std::vector<Point_3> corners() const
  {
    const double x = size_x, y = size_y, z = size_z, w = chamfer;
    return {Point_3(0, 0, 0), Point_3(x, 0, 0), Point_3(x, y, 0), Point_3(0, y, 0),             // 0-3 bottom
            Point_3(0, 0, z), Point_3(x, 0, z), Point_3(x, y - w, z), Point_3(0, y - w, z),     // 4-7 top
            Point_3(x, y, z - w), Point_3(0, y, z - w)};                                        // 8-9 back
  }

  /// the faces as corner indices, counter-clockwise seen from outside.
  static std::vector<std::vector<std::size_t>> faces()
  {
    return {{0, 3, 2, 1},     // bottom, -z
            {0, 1, 5, 4},     // front, -y
            {4, 5, 6, 7},     // top, +z
            {7, 6, 8, 9},     // chamfer, (0, 1, 1)
            {2, 3, 9, 8},     // back, +y
            {0, 4, 7, 9, 3},  // left, -x
            {1, 2, 8, 6, 5}}; // right, +x
  }

  /// the surface as triangles (fans of the convex faces), outward.
  void triangulate(std::vector<Point_3>& points, std::vector<Triangle_indices>& triangles) const
  {
    points = corners();
    triangles.clear();
    for(const std::vector<std::size_t>& f : faces())
      for(std::size_t i = 1; i + 1 < f.size(); ++i)
        triangles.push_back(Triangle_indices{{f[0], f[i], f[i + 1]}});
  }

  /// `n` points sampled uniformly on the surface, with noise (see `sample_triangles()`).
  std::vector<Point_3> sample(std::size_t n, double noise, unsigned seed) const
  {
    std::vector<Point_3> points;
    std::vector<Triangle_indices> triangles;
    triangulate(points, triangles);
    return sample_triangles(points, triangles, n, noise, seed);
  }

  /// signed distance from `p` to the box, exact inside and near the faces (the box is convex:
  /// the largest signed distance to the planes of its faces).
  double signed_distance(const Point_3& p) const
  {
    const std::vector<Point_3> c = corners();
    const std::vector<Vector_3> normals = face_normals();
    const std::vector<std::vector<std::size_t>> f = faces();
    double d = -1e300;
    for(std::size_t i = 0; i < f.size(); ++i)
      d = (std::max)(d, CGAL::to_double((p - c[f[i][0]]) * normals[i]));
    return d;
  }

  std::vector<Vector_3> face_normals() const
  {
    const std::vector<Point_3> p = corners();
    std::vector<Vector_3> normals;
    for(const std::vector<std::size_t>& f : faces()) {
      const Vector_3 n = CGAL::cross_product(p[f[1]] - p[f[0]], p[f[2]] - p[f[1]]);
      normals.push_back(n / std::sqrt(CGAL::to_double(n.squared_length())));
    }
    return normals;
  }

  /// the 15 creases as curves the way the extraction reports them: vertices about `step`
  /// apart, curves meeting at corners share the corner point exactly, each vertex carries the
  /// outward normals of the two faces (the orientation of a convex crease).
  std::vector<CGAL::Feature_polyline<GeomTraits>> creases(double step) const
  {
    const std::vector<Point_3> p = corners();
    const std::vector<Vector_3> normals = face_normals();
    const std::vector<std::vector<std::size_t>> f = faces();
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> edge_faces;
    for(std::size_t i = 0; i < f.size(); ++i)
      for(std::size_t j = 0; j < f[i].size(); ++j) {
        const std::size_t a = f[i][j], b = f[i][(j + 1) % f[i].size()];
        edge_faces[std::make_pair((std::min)(a, b), (std::max)(a, b))].push_back(i);
      }
    std::vector<CGAL::Feature_polyline<GeomTraits>> curves;
    for(const auto& e : edge_faces) {
      CGAL::Feature_polyline<GeomTraits> c;
      const Point_3& a = p[e.first.first];
      const Point_3& b = p[e.first.second];
      const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
      const std::size_t n = (std::max)(std::size_t(1), static_cast<std::size_t>(std::ceil(length / step)));
      for(std::size_t i = 0; i <= n; ++i) {
        c.points.push_back(i == 0 ? a : (i == n ? b : a + (double(i) / n) * (b - a)));
        c.normals.push_back({{normals[e.second[0]], normals[e.second[1]]}});
      }
      curves.push_back(c);
    }
    return curves;
  }
};

} // namespace sfe_test

#endif // SFE_TEST_CHAMFERED_BOX_H
