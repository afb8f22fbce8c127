// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_POINT_INDEX_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_POINT_INDEX_H

#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// k-nearest-neighbour and ball queries over a fixed set of points, answered with indices.
/// Built once and shared by the stages that search the same set; const queries are thread-safe.
class Point_index
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 Point;

  struct Index_to_point
  {
    typedef std::size_t key_type;
    typedef Point value_type;
    typedef const Point& reference;
    typedef boost::readable_property_map_tag category;
    const std::vector<Point>* points = nullptr;
    friend reference get(const Index_to_point& m, std::size_t i) { return (*m.points)[i]; }
  };

  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Index_to_point, Base_traits> Traits;
  typedef CGAL::Distance_adapter<std::size_t, Index_to_point, CGAL::Euclidean_distance<Base_traits>> Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance> Knn;
  typedef CGAL::Kd_tree<Traits> Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

public:
  template <typename ConcurrencyTag>
  void build(const std::vector<Vec3>& points)
  {
    m_points.clear();
    m_points.reserve(points.size());
    for(const Vec3& p : points)
      m_points.emplace_back(p.x(), p.y(), p.z());
    Index_to_point map;
    map.points = &m_points;
    m_map = map;
    m_tree.reset();
    // CGAL's Kd_tree requires a non-empty set; the queries answer nothing without a tree.
    if(m_points.empty())
      return;
    m_tree.reset(new Tree(boost::counting_iterator<std::size_t>(0),
                          boost::counting_iterator<std::size_t>(m_points.size()),
                          Tree::Splitter(), Traits(map)));
    m_tree->template build<ConcurrencyTag>();
  }

  std::size_t size() const { return m_points.size(); }

  /// The `k` nearest points to `q` (indices appended to `out`, cleared first): nearest first
  /// when `sorted`, in an unspecified (but deterministic) order otherwise, which is faster.
  void nearest(const Vec3& q, std::size_t k, std::vector<std::size_t>& out, bool sorted = true) const
  {
    out.clear();
    if(m_points.empty() || k == 0)
      return;
    Knn search(*m_tree, Point(q.x(), q.y(), q.z()), (unsigned int)k, 0, true, Distance(m_map), sorted);
    for(const auto& entry : search)
      out.push_back(entry.first);
  }

  /// Every point within `radius` of `q` (unordered; indices appended to `out`, cleared first).
  void within(const Vec3& q, double radius, std::vector<std::size_t>& out) const
  {
    out.clear();
    if(m_points.empty())
      return;
    m_tree->search(std::back_inserter(out), Sphere(Point(q.x(), q.y(), q.z()), radius, 0, m_tree->traits()));
  }

private:
  std::vector<Point> m_points;
  Index_to_point m_map;
  std::unique_ptr<Tree> m_tree;
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
