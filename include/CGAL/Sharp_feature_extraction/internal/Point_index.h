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

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Puts the `k` smallest elements of `ranked` (at least `k`, all distinct, such as (distance,
/// index) pairs) at its front, in ascending order: the order of a full sort there, at a
/// fraction of the cost of a sort or of a heap over all of them.
template <typename T>
void sort_smallest(std::vector<T>& ranked, std::size_t k)
{
  std::nth_element(ranked.begin(), ranked.begin() + (k - 1), ranked.end());
  std::sort(ranked.begin(), ranked.begin() + k);
}

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

  /// Workspace of `nearest_ranked()`, one per thread.
  struct Ranked_query
  {
    /// The distance to the k-th neighbour of the last query (0 before the first): the next
    /// query, nearby, likely finds its k neighbours within about that distance.
    double last_radius = 0;
    std::vector<std::size_t> found;
    std::vector<std::pair<double, std::size_t>> ranked;
  };

  /// The `k` nearest points to `q`, nearest first and ties by index (indices in `out`, cleared
  /// first): the k smallest (squared distance, index) pairs, whatever the order of the queries.
  /// A query near the previous one of `query` ranks the points of a ball slightly wider than
  /// the previous k-th distance (see `ranked_query_margin`), which is several times faster than
  /// the k-nearest search of the tree for large `k`; when that ball holds fewer than k points,
  /// the tree's search gives the k-th distance and the ball of that radius is ranked.
  void nearest_ranked(const Vec3& q, std::size_t k, Ranked_query& query, std::vector<std::size_t>& out) const
  {
    out.clear();
    k = (std::min)(k, m_points.size());
    if(k == 0)
      return;
    if(query.last_radius > 0 && rank_ball(q, k, ranked_query_margin * query.last_radius, query, out))
      return;
    Knn search(*m_tree, Point(q.x(), q.y(), q.z()), (unsigned int)k, 0, true, Distance(m_map), true);
    double kth = 0;
    for(const auto& entry : search)
    {
      out.push_back(entry.first);
      kth = (std::max)(kth, entry.second);
    }
    // The ball slightly wider than the k-th distance, so that rounding in its test cannot drop
    // a point at that distance; should that fail all the same, the tree's order stays.
    rank_ball(q, k, std::sqrt(kth) * (1 + ball_rounding_margin), query, out);
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
  /// The ball of a ranked query is this much wider than the previous query's k-th distance:
  /// wide enough that a query a spacing or two away still finds k points in it, and holding
  /// only about 1.2^2 = 1.44 times k points on a surface.
  static constexpr double ranked_query_margin = 1.2;
  /// Relative widening of a ball around a distance that it must contain, against rounding.
  static constexpr double ball_rounding_margin = 1e-9;

  // The k smallest (squared distance, index) pairs of the points within `radius` of `q`, in
  // `out` (replacing its content), and true, if that ball holds at least k points and its
  // k-th point lies inside it by more than rounding (so that no point outside it can be
  // nearer); false otherwise.
  bool rank_ball(const Vec3& q, std::size_t k, double radius, Ranked_query& query, std::vector<std::size_t>& out) const
  {
    query.found.clear();
    m_tree->search(std::back_inserter(query.found), Sphere(Point(q.x(), q.y(), q.z()), radius, 0, m_tree->traits()));
    if(query.found.size() < k)
      return false;
    query.ranked.clear();
    for(std::size_t i : query.found)
    {
      const Point& p = m_points[i];
      const double dx = p.x() - q.x(), dy = p.y() - q.y(), dz = p.z() - q.z();
      query.ranked.emplace_back(dx * dx + dy * dy + dz * dz, i);
    }
    sort_smallest(query.ranked, k);
    const double kth = query.ranked[k - 1].first;
    if(!(kth <= radius * radius * (1 - ball_rounding_margin)))
      return false;
    query.last_radius = std::sqrt(kth);
    out.clear();
    for(std::size_t r = 0; r < k; ++r)
      out.push_back(query.ranked[r].second);
    return true;
  }

  std::vector<Point> m_points;
  Index_to_point m_map;
  std::unique_ptr<Tree> m_tree;
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
