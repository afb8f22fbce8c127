// Distances from points to a surface: to a triangle mesh (exact, an AABB tree), or to the
// surface a point cloud samples (the least-squares plane of the nearest input points). The
// distortion measure of compress_point_cloud and of the compression benchmark.

#ifndef SFE_UTILITIES_SURFACE_DISTANCE_H
#define SFE_UTILITIES_SURFACE_DISTANCE_H

#include "utilities/mesh_surface_sampling.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/linear_least_squares_fitting_3.h>

#include <cmath>
#include <string>
#include <vector>

namespace sfe_utilities {

typedef CGAL::Simple_cartesian<double> Distance_kernel;

/// Number of nearest input points whose plane stands for the sampled surface: two rings on a
/// uniform sample, enough to average the sampling irregularity.
constexpr unsigned int surface_plane_neighbors = 12;

/// The root-mean-square distance from `points` to the triangles of `mesh_path`.
template <typename Point>
double rms_distance_to_mesh(const std::vector<Point>& points, const std::string& mesh_path)
{
  typedef Distance_kernel::Triangle_3 Triangle;
  typedef std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Distance_kernel, CGAL::AABB_triangle_primitive<Distance_kernel, Iterator>>> Tree;
  const Triangle_soup soup = read_triangle_soup(mesh_path);
  auto vertex = [&](std::size_t v) {
    return Distance_kernel::Point_3(soup.vertices[v][0], soup.vertices[v][1], soup.vertices[v][2]);
  };
  std::vector<Triangle> triangles;
  for(const auto& t : soup.triangles)
    triangles.emplace_back(vertex(t[0]), vertex(t[1]), vertex(t[2]));
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  double sum = 0;
  for(const Point& p : points)
    sum += tree.squared_distance(Distance_kernel::Point_3(p.x(), p.y(), p.z()));
  return points.empty() ? 0. : std::sqrt(sum / double(points.size()));
}

/// The root-mean-square distance from `points` to the surface `samples` sample: for each
/// point, to the least-squares plane of its `surface_plane_neighbors` nearest samples.
template <typename Point>
double rms_distance_to_samples(const std::vector<Point>& points, const std::vector<Point>& samples)
{
  typedef CGAL::Search_traits_3<Distance_kernel> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  std::vector<Distance_kernel::Point_3> converted;
  for(const Point& p : samples)
    converted.emplace_back(p.x(), p.y(), p.z());
  Search::Tree tree(converted.begin(), converted.end());
  double sum = 0;
  std::vector<Distance_kernel::Point_3> near;
  for(const Point& p : points)
  {
    const Distance_kernel::Point_3 q(p.x(), p.y(), p.z());
    near.clear();
    for(const auto& entry : Search(tree, q, surface_plane_neighbors))
      near.push_back(entry.first);
    Distance_kernel::Plane_3 plane;
    CGAL::linear_least_squares_fitting_3(near.begin(), near.end(), plane, CGAL::Dimension_tag<0>());
    sum += CGAL::squared_distance(q, plane);
  }
  return points.empty() ? 0. : std::sqrt(sum / double(points.size()));
}

} // namespace sfe_utilities

#endif
