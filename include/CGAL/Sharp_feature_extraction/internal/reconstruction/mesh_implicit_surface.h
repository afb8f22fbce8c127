// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Surface meshing of an implicit function with Mesh_3, the feature curves protected.
//
// The domain is a Labeled_mesh_domain_3 over the implicit function (negative inside), wrapped
// in Mesh_domain_with_polyline_features_3. With curves, Mesh_3 first covers every curve with
// protecting balls, whose centres become mesh vertices joined by mesh edges along the curve;
// the Delaunay refinement of the surface then cannot cut across a crease. Without curves the
// very same domain, criteria and options run, so the two results compare one thing only.
//
// This header is the only one of the package that includes Mesh_3 (a heavy compilation).

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_MESH_IMPLICIT_SURFACE_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_MESH_IMPLICIT_SURFACE_H

#include <CGAL/Sharp_feature_extraction/internal/reconstruction/project_polylines_onto_surface.h>

#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_error_code.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace reconstruction {

/// Mesh_3 criteria, as absolute lengths (derived from the sampling spacing unless given).
struct Mesh_sizes
{
  double edge_size = 0;      ///< largest protecting ball / mesh edge along a feature curve
  double facet_size = 0;     ///< largest radius of a surface Delaunay ball
  double facet_distance = 0; ///< largest distance from a facet to the surface
  double facet_angle = 25;   ///< smallest facet angle, in degrees
};

struct Surface_meshing_limits
{
  double time_limit = 0;                  ///< seconds; 0: none
  /// 0: none (the reconstruction sets one from the number of input points)
  std::size_t maximal_number_of_vertices = 0;
  double relative_error_bound = 1e-6;     ///< of the surface intersections, relative to the bounding sphere
  unsigned seed = 0;                      ///< of Mesh_3's random initial points
  /// Where the function is negative on the faces of the domain's cube (`far_field_samples`
  /// squared points per face), it is lifted by this many times its most negative value there:
  /// 10, so that the spurious patch, deeper inside the cube than on its faces but of the same
  /// order, is lifted too.
  double far_field_margin = 10;
  int far_field_samples = 32;
  /// Called about 5 times per second while Mesh_3 runs, with the seconds elapsed; returning
  /// false stops Mesh_3 (read only while it refines).
  std::function<bool(double)> heartbeat;
  /// Called once, with the seconds elapsed, when Mesh_3 is still at work at
  /// `unresponsive_time_limit_factor` times the time limit (stuck where it does not read its
  /// stop flag). Empty: keep waiting.
  std::function<void(double)> unresponsive_handler;
};

/// the largest of 0 and -f on a `samples` x `samples` grid on each face of the cube of half
/// side `radius` around `center`: how far below zero the function is where it should be
/// outside.
template <typename Function, typename Point_3>
double far_field_level(const Function& f, const Point_3& center, double radius, int samples)
{
  double level = 0;
  for(int axis = 0; axis < 3; ++axis)
    for(int side = -1; side <= 1; side += 2)
      for(int i = 0; i < samples; ++i)
        for(int j = 0; j < samples; ++j) {
          double c[3];
          c[axis] = side * radius;
          c[(axis + 1) % 3] = radius * (2. * (i + 0.5) / samples - 1);
          c[(axis + 2) % 3] = radius * (2. * (j + 0.5) / samples - 1);
          const Point_3 x(center.x() + c[0], center.y() + c[1], center.z() + c[2]);
          level = (std::max)(level, -CGAL::to_double(f(x)));
        }
  return level;
}

/// Beyond this multiple of the time limit, Mesh_3 is taken as stuck where it does not read its
/// stop flag (see mesh_implicit_surface()): twice the limit leaves it the whole limit to answer.
constexpr double unresponsive_time_limit_factor = 2;

/// the one line of a CGAL failure message that says what went wrong (its "Explanation:", or
/// else its first line and the failed expression): the message spans a dozen lines of file,
/// line and debugging data.
inline std::string first_line_of_failure(const std::string& message)
{
  auto line_after = [&](const std::string& key) -> std::string {
    const std::size_t at = message.find(key);
    if(at == std::string::npos)
      return "";
    const std::size_t begin = at + key.size();
    return message.substr(begin, message.find('\n', begin) - begin);
  };
  const std::string explanation = line_after("Explanation: ");
  if(!explanation.empty())
    return explanation;
  const std::size_t begin = message.find_first_not_of("\n ");
  if(begin == std::string::npos)
    return message;
  const std::string first = message.substr(begin, message.find('\n', begin) - begin);
  // An assertion without explanation: its expression says which check failed.
  const std::string expression = line_after("Expr: ");
  return expression.empty() ? first : first + " (" + expression + ")";
}

/// The step of the central differences that orient a facet of an unlabelled complex (see
/// `collect_surface()`), relative to its longest edge: small against the curvature of the
/// surface that the facet resolves.
constexpr double gradient_step_per_edge = 1e-2;

typedef std::array<std::size_t, 3> Triangle_indices;

/// A closed surface as a triangle soup, facets oriented outward.
template <typename Point_3>
struct Triangle_soup_3
{
  std::vector<Point_3> points;
  std::vector<Triangle_indices> triangles;
};

template <typename Point_3>
struct Surface_meshing_result
{
  Triangle_soup_3<Point_3> surface;
  std::size_t protected_vertices = 0; ///< vertices Mesh_3 put on the feature curves
  bool stopped = false;               ///< the time or vertex limit was reached
  double far_field = 0;               ///< the lift added to the function
  std::string error;                  ///< empty on success
};

/// A thread that, while Mesh_3 runs, calls the heartbeat about 5 times per second and sets
/// Mesh_3's stop flag at the time limit or when the heartbeat asks, and calls the unresponsive
/// handler when Mesh_3 is still running long after the time limit.
class Mesh_3_watchdog
{
public:
  /// Mesh_3's stop flag.
  std::atomic<bool> stop{false};

  explicit Mesh_3_watchdog(const Surface_meshing_limits& limits)
    : m_limits(limits), m_start(std::chrono::steady_clock::now()), m_thread([this] { watch(); })
  {}
  ~Mesh_3_watchdog() { finish(); }

  /// stops watching (Mesh_3 returned).
  void finish()
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_done = true;
    }
    m_done_signal.notify_all();
    if(m_thread.joinable())
      m_thread.join();
  }

private:
  void watch()
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    bool unresponsive_reported = false;
    while(!m_done_signal.wait_for(lock, std::chrono::milliseconds(200), [this] { return m_done; })) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
      if(m_limits.heartbeat && !m_limits.heartbeat(seconds))
        stop = true;
      const double limit = m_limits.time_limit;
      if(limit > 0 && seconds > limit)
        stop = true;
      // Mesh_3 5.5 reads the stop flag only while it refines. Stuck in the protection of the
      // feature curves (pinion, 25k points, 0.5% noise, seed 5: in Polyline::locate for over
      // 8 min) it never returns, and nothing can end it from outside but the process itself:
      // the caller decides.
      if(limit > 0 && seconds > unresponsive_time_limit_factor * limit && m_limits.unresponsive_handler &&
         !unresponsive_reported) {
        unresponsive_reported = true;
        m_limits.unresponsive_handler(seconds);
      }
    }
  }

  const Surface_meshing_limits& m_limits;
  const std::chrono::steady_clock::time_point m_start;
  std::mutex m_mutex;
  std::condition_variable m_done_signal;
  bool m_done = false;
  std::thread m_thread;
};

/// The shortest edge of a surface mesh: where a refinement that did not converge got stuck.
template <typename Point_3>
struct Shortest_edge
{
  double squared_length = std::numeric_limits<double>::infinity();
  Point_3 midpoint = CGAL::ORIGIN;
};

/// copies the facets of the complex into `result.surface`, each oriented away from the inside
/// of the domain, and counts the protected vertices; returns the shortest edge.
///
/// The inside is the cell of the facet that is in the complex. Mesh_3 labels the cells only
/// once the facets are refined: stopped before (the time or vertex limit), it has no cell in the
/// complex, one of the two cells of a facet on the convex hull is infinite, and the point of the
/// infinite vertex is not a point (a NaN reached the exact orientation test: "Mpzf from NaN",
/// rotor, 25k points, 0.5% noise, seed 4). Then the facet faces the way `function` (negative
/// inside) grows, and the infinite cell is never looked at.
template <typename C3t3, typename Function, typename Point_3>
Shortest_edge<Point_3> collect_surface(const C3t3& c3t3, const Function& function,
                                       Surface_meshing_result<Point_3>& result)
{
  typedef typename C3t3::Triangulation Tr;
  const Tr& tr = c3t3.triangulation();
  auto point_of = [&tr](typename Tr::Vertex_handle v) { return tr.geom_traits().construct_point_3_object()(v->point()); };
  std::map<typename Tr::Vertex_handle, std::size_t> index;
  auto index_of = [&](typename Tr::Vertex_handle v) {
    auto it = index.find(v);
    if(it != index.end())
      return it->second;
    index[v] = result.surface.points.size();
    result.surface.points.push_back(point_of(v));
    return result.surface.points.size() - 1;
  };
  Shortest_edge<Point_3> shortest;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    typename Tr::Cell_handle cell = f->first;
    int i = f->second;
    const typename Tr::Facet mirror = tr.mirror_facet(*f);
    if(c3t3.is_in_complex(mirror.first)) {
      cell = mirror.first;
      i = mirror.second;
    }
    Triangle_indices t = {index_of(cell->vertex((i + 1) & 3)), index_of(cell->vertex((i + 2) & 3)),
                          index_of(cell->vertex((i + 3) & 3))};
    const std::vector<Point_3>& p = result.surface.points;
    double longest = 0;
    for(int k = 0; k < 3; ++k) {
      const double l = CGAL::to_double(CGAL::squared_distance(p[t[k]], p[t[(k + 1) % 3]]));
      longest = (std::max)(longest, l);
      if(l < shortest.squared_length) {
        shortest.squared_length = l;
        shortest.midpoint = CGAL::midpoint(p[t[k]], p[t[(k + 1) % 3]]);
      }
    }
    bool faces_inside;
    if(c3t3.is_in_complex(cell)) {
      faces_inside = CGAL::orientation(p[t[0]], p[t[1]], p[t[2]], point_of(cell->vertex(i))) == CGAL::POSITIVE;
    } else {
      const Point_3 centroid = CGAL::centroid(p[t[0]], p[t[1]], p[t[2]]);
      const auto outward = central_gradient(function, centroid, gradient_step_per_edge * std::sqrt(longest));
      faces_inside = CGAL::cross_product(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]) * outward < 0;
    }
    if(faces_inside)
      std::swap(t[1], t[2]);
    result.surface.triangles.push_back(t);
  }
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    if(v->in_dimension() == 0 || v->in_dimension() == 1)
      ++result.protected_vertices;
  return shortest;
}

/// meshes the boundary of { x in `bound` : `function`(x) < 0 } with Mesh_3, protecting the
/// polylines `features` (each a `std::vector<Point_3>`; closed ones repeat their first point,
/// curves meet only at shared end points: see `find_mesh_3_polyline_problems()`).
///
/// The function must be positive on the faces of the cube around `bound`, which bounds the
/// domain. An implicit function fitted to samples (Poisson's) is zero far from them up to the
/// solver's noise, of either sign: a slightly negative patch there is a spurious inside that
/// the cube cuts open, where Mesh_3 refines the cut forever (then asserts that a point "is
/// already inserted on surface"), or from which it finds no surface at all. Where the faces are
/// negative, the function is lifted by a margin times their most negative value
/// (`Surface_meshing_result::far_field`; zero when they are all positive): the true surface
/// moves inward by that much, far below the facet distance of a sampled surface.
template <typename GeomTraits, typename Function>
Surface_meshing_result<typename GeomTraits::Point_3>
mesh_implicit_surface(const Function& function, const typename GeomTraits::Sphere_3& bound,
                      const std::vector<std::vector<typename GeomTraits::Point_3>>& features,
                      const Mesh_sizes& sizes, const Surface_meshing_limits& limits)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef CGAL::Labeled_mesh_domain_3<GeomTraits> Implicit_domain;
  typedef CGAL::Mesh_domain_with_polyline_features_3<Implicit_domain> Domain;
  typedef typename CGAL::Mesh_triangulation_3<Domain>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, typename Domain::Corner_index,
                                                  typename Domain::Curve_index> C3t3;
  typedef CGAL::Mesh_criteria_3<Tr> Criteria;
  namespace params = CGAL::parameters;

  Surface_meshing_result<Point_3> result;
  CGAL::Random random(limits.seed);
  const double radius = std::sqrt(CGAL::to_double(bound.squared_radius()));
  result.far_field = limits.far_field_margin *
                     far_field_level(function, bound.center(), radius, limits.far_field_samples);
  std::function<double(const Point_3&)> f = [&function, &result](const Point_3& x) {
    return CGAL::to_double(function(x)) + result.far_field;
  };
  Domain domain(Implicit_domain::create_implicit_mesh_domain(
    f, bound, params::relative_error_bound = limits.relative_error_bound, params::p_rng = &random));
  if(!features.empty())
    domain.add_features(features.begin(), features.end());

  Criteria criteria(params::edge_size = sizes.edge_size, params::facet_angle = sizes.facet_angle,
                    params::facet_size = sizes.facet_size,
                    params::facet_distance = sizes.facet_distance);

  Mesh_3_watchdog watchdog(limits);
  CGAL::Mesh_error_code error_code = CGAL::CGAL_MESH_3_NO_ERROR;
  C3t3 c3t3;
  try {
    c3t3 = CGAL::make_mesh_3<C3t3>(
      domain, criteria, params::no_perturb(), params::no_exude(), params::manifold(),
      params::mesh_3_options(params::maximal_number_of_vertices = limits.maximal_number_of_vertices,
                             params::pointer_to_error_code = &error_code,
                             params::pointer_to_stop_atomic_boolean = &watchdog.stop));
  } catch(const std::exception& e) {
    result.error = "Mesh_3 failed: " + first_line_of_failure(e.what());
  }
  watchdog.finish();
  if(!result.error.empty())
    return result;
  if(error_code != CGAL::CGAL_MESH_3_NO_ERROR) {
    result.stopped = true;
    result.error = CGAL::mesh_error_string(error_code);
  }
  const Shortest_edge<Point_3> shortest = collect_surface(c3t3, f, result);
  if(result.stopped && !result.surface.triangles.empty()) {
    std::ostringstream where;
    where.precision(6);
    where << " before converging; shortest mesh edge " << std::sqrt(shortest.squared_length) << " at ("
          << shortest.midpoint << ")";
    result.error += where.str();
  }
  if(result.surface.triangles.empty() && result.error.empty())
    result.error = "Mesh_3 found no surface (is the implicit function negative inside the bounding sphere?)";
  return result;
}

} // namespace reconstruction
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_MESH_IMPLICIT_SURFACE_H
