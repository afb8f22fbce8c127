// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Consistent orientation of unoriented normals that does not cross thin walls.
//
// CGAL::mst_orient_normals() propagates an orientation along the minimum spanning tree of the
// k-nearest-neighbour graph weighted by 1 - |n_i . n_j| (Hoppe et al. 1992). Across a wall a
// few spacings thick the two sides' normals are parallel, so these edges weigh nothing, and
// with noise (the neighbourhoods grow with it) the tree crosses the wall: the whole far side is
// then oriented inward (a plate 3.5 spacings thick, 0.5% noise: half of its normals). Poisson
// reconstruction turns such a region into a membrane across the part: benchmark part, 25k
// points, 0.5% noise, seeds 1 and 3, a quarter of the normals inward, a surface straying
// 0.19 dB from the part, and with the curves protected Mesh_3 converging onto one point of it
// (mesh edges of 3e-9) until stopped.
//
// Here an edge also weighs how far each point lies off the other's tangent plane, relative to
// their distance: neighbours on one sheet lie near each other's tangent plane (up to the noise
// and the curvature), neighbours across a wall lie along the normal. The tree then goes around
// the rim of a wall rather than through it. Otherwise the propagation is Hoppe's: from the
// highest point, oriented up, each tree edge keeps n_i . n_j > 0.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_ORIENT_NORMALS_ALONG_SHEETS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_ORIENT_NORMALS_ALONG_SHEETS_H

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace reconstruction {

/// orients the unit `normals` of `points` consistently, by propagation over the `k` nearest
/// neighbours (see the file comment for the weights). Returns, per point, whether it was
/// reached: a point whose neighbourhood graph does not connect to the highest point keeps its
/// normal and is reported unoriented, as by `CGAL::mst_orient_normals()`.
template <typename GeomTraits>
std::vector<bool> orient_normals_along_sheets(const std::vector<typename GeomTraits::Point_3>& points,
                                              std::vector<typename GeomTraits::Vector_3>& normals,
                                              unsigned k)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Point_map;
  typedef CGAL::Search_traits_3<GeomTraits> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits>> Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance> Neighbor_search;
  typedef typename Neighbor_search::Tree Tree;

  const std::size_t n = points.size();
  std::vector<bool> reached(n, false);
  if(n == 0)
    return reached;
  const Point_map point_map = CGAL::make_property_map(points);
  Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n),
            typename Tree::Splitter(), Traits(point_map));
  const Distance distance(point_map);

  // how far q lies off the tangent plane of p, as the sine of the angle between q - p and it
  auto off_plane = [&](std::size_t p, std::size_t q) {
    const Vector_3 d = points[q] - points[p];
    const double length = std::sqrt(CGAL::to_double(d.squared_length()));
    return length > 0 ? std::abs(CGAL::to_double(normals[p] * d)) / length : 0.;
  };
  auto weight = [&](std::size_t p, std::size_t q) {
    return 1 - std::abs(CGAL::to_double(normals[p] * normals[q])) + (std::max)(off_plane(p, q), off_plane(q, p));
  };

  // the neighbour graph, made symmetric (q among the neighbours of p, or p among those of q)
  std::vector<std::vector<std::size_t>> neighbors(n);
  for(std::size_t p = 0; p < n; ++p) {
    Neighbor_search search(tree, points[p], k + 1, 0, true, distance);
    for(const auto& found : search)
      if(found.first != p) {
        neighbors[p].push_back(found.first);
        neighbors[found.first].push_back(p);
      }
  }

  // Prim's tree from the highest point, whose normal points up
  std::size_t top = 0;
  for(std::size_t p = 1; p < n; ++p)
    if(points[p].z() > points[top].z())
      top = p;
  if(CGAL::to_double(normals[top].z()) < 0)
    normals[top] = -normals[top];
  typedef std::tuple<double, std::size_t, std::size_t> Edge; // weight, to, from
  std::priority_queue<Edge, std::vector<Edge>, std::greater<Edge>> front;
  auto reach = [&](std::size_t p) {
    reached[p] = true;
    for(std::size_t q : neighbors[p])
      if(!reached[q])
        front.push(Edge(weight(p, q), q, p));
  };
  reach(top);
  while(!front.empty()) {
    const std::size_t to = std::get<1>(front.top()), from = std::get<2>(front.top());
    front.pop();
    if(reached[to])
      continue;
    if(CGAL::to_double(normals[to] * normals[from]) < 0)
      normals[to] = -normals[to];
    reach(to);
  }
  return reached;
}

} // namespace reconstruction
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_ORIENT_NORMALS_ALONG_SHEETS_H
