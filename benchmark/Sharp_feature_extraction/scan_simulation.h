// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A simulated range scanner: the point clouds that real scanners produce, from a triangle mesh.
// Each viewpoint sweeps a grid of rays over the object, line by line (dense along a line,
// sparser across lines when asked); a ray returns the first surface it hits (occlusion), with
// an error along the ray (range noise), and returns nothing when it misses or hits a surface at
// a grazing angle. Optionally one view is misregistered (its points shifted, as after a poor
// registration of two overlapping scans, which doubles the surface), the rays without return
// are written as (0,0,0) (as many scanners do in their grid files), and every point gets a
// constant offset (georeferenced coordinates).
//
// Plain double geometry and CGAL's AABB tree only, independent of the library under test, so
// that the benchmark (bench_support.h) and the tests (test_scanner_inputs.cpp) use the same
// scans. Deterministic for a given seed, whatever the number of threads: every scan line draws
// from its own random generator and the lines are written in order.

#ifndef SFE_BENCHMARK_SCAN_SIMULATION_H
#define SFE_BENCHMARK_SCAN_SIMULATION_H

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/for_each.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

namespace sfe_scan {

typedef std::array<double, 3> Xyz;

/// A triangle mesh: triangles given by indices into `vertices`.
struct Mesh
{
  std::vector<Xyz> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// How the object is scanned. Lengths are fractions of the diagonal dB of the mesh's bounding box.
struct Scan_options
{
  /// Number of viewpoints, 1 to 8. The first four look at the centre of the bounding box from
  /// the vertices of a regular tetrahedron around it (together they see each face of a convex
  /// object from two sides of it); the next four from the opposite directions.
  std::size_t views = 4;
  /// Distance of the viewpoints from the centre of the bounding box, in units of dB: 1.5 puts the
  /// object within a cone of half-angle 20 degrees, as a scanner set up a few object sizes away.
  double distance = 1.5;
  /// Half-angle of each view's ray grid over the half-angle under which the scanner sees the
  /// bounding sphere of the box (>= 1): scanners sweep wider than the object, and the rays
  /// beyond it find no return.
  double window = 1;
  /// Number of returns to aim at, over all views (the angular step is chosen from a coarse
  /// pilot scan; the result is within a few percent of it).
  std::size_t returns = 100000;
  /// Angular step across scan lines over the step along a line (>= 1): 1 is an even grid,
  /// 4 puts the lines 4 times farther apart than the points on a line.
  double line_spacing_ratio = 1;
  /// Half-width of the uniform range error along each ray, as a fraction of dB.
  double range_noise = 0;
  /// A ray whose angle with the surface normal exceeds this (degrees) gets no return: scanners
  /// lose the signal at grazing incidence.
  double max_incidence_degrees = 80;
  /// The points of the last view are shifted by this (fraction of dB) along its viewing
  /// direction: a registration error between overlapping scans, which doubles the surface.
  double misregistration = 0;
  /// If true, every ray without a return (a miss or a grazing hit) is written as (0,0,0).
  bool no_returns_as_origin = false;
  /// Added to every return (not to the (0,0,0) of missing returns): georeferenced coordinates.
  Xyz offset = {{0, 0, 0}};
  std::uint64_t seed = 1;
};

/// The scanned points, in scan order (view by view, line by line), and what became of the rays.
struct Scan
{
  std::vector<Xyz> points;
  std::size_t rays = 0;
  /// Rays that hit the object.
  std::size_t returns = 0;
  /// Rays that missed the object.
  std::size_t misses = 0;
  /// Rays that hit it at a grazing angle (no return).
  std::size_t grazing = 0;
};

namespace scan_internal {

typedef CGAL::Simple_cartesian<double> K;
typedef std::vector<K::Triangle_3>::const_iterator Triangle_iterator;
typedef CGAL::AABB_triangle_primitive<K, Triangle_iterator> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

inline K::Vector_3 unit(const K::Vector_3& v) { return v / std::sqrt(v.squared_length()); }

/// Viewing directions (from the centre towards the scanner), in the order the views use them.
inline std::vector<K::Vector_3> view_directions()
{
  const std::vector<K::Vector_3> tetrahedron = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::vector<K::Vector_3> directions;
  for(const K::Vector_3& d : tetrahedron)
    directions.push_back(unit(d));
  for(const K::Vector_3& d : tetrahedron)
    directions.push_back(-unit(d));
  return directions;
}

/// One scanner position and its ray grid: lines at azimuths -half_angle + i * across_step,
/// points on a line at elevations -half_angle + j * along_step.
struct View
{
  K::Point_3 eye;
  K::Vector_3 forward, right, up;
  double half_angle = 0, along_step = 0, across_step = 0;
  std::size_t lines = 0, per_line = 0;
  K::Vector_3 shift = {0, 0, 0};

  K::Vector_3 ray(std::size_t line, std::size_t j) const
  {
    const double azimuth = -half_angle + double(line) * across_step;
    const double elevation = -half_angle + double(j) * along_step;
    return (forward * std::cos(azimuth) + right * std::sin(azimuth)) * std::cos(elevation) + up * std::sin(elevation);
  }
};

// Uniform in [-1, 1) from the 53 high bits of one word (the standard fixes mt19937_64's output,
// not its distributions).
inline double symmetric_uniform(std::mt19937_64& generator)
{
  return 2 * (double(generator() >> 11) * 0x1.0p-53) - 1;
}

/// The points of one scan line, and what became of its rays.
struct Line
{
  std::vector<Xyz> points;
  std::size_t returns = 0, misses = 0, grazing = 0;
};

class Scanner
{
public:
  Scanner(const Mesh& mesh, const Scan_options& options) : m_options(options)
  {
    if(mesh.triangles.empty())
      throw std::invalid_argument("scan simulation: the mesh has no triangle");
    if(options.views < 1 || options.views > view_directions().size())
      throw std::invalid_argument("scan simulation: views must be 1 to 8");
    if(!(options.line_spacing_ratio >= 1) || !(options.window >= 1) || !(options.distance > 0.5))
      throw std::invalid_argument("scan simulation: line_spacing_ratio and window must be >= 1, distance > 0.5 dB");
    // The grid's azimuths and elevations cover one hemisphere at most.
    if(!(std::asin(0.5 / options.distance) * options.window < std::acos(0.)))
      throw std::invalid_argument("scan simulation: the window is wider than a hemisphere");
    K::Point_3 low(mesh.vertices.front()[0], mesh.vertices.front()[1], mesh.vertices.front()[2]), high = low;
    for(const Xyz& v : mesh.vertices)
    {
      low = K::Point_3((std::min)(low.x(), v[0]), (std::min)(low.y(), v[1]), (std::min)(low.z(), v[2]));
      high = K::Point_3((std::max)(high.x(), v[0]), (std::max)(high.y(), v[1]), (std::max)(high.z(), v[2]));
    }
    m_diagonal = std::sqrt(CGAL::squared_distance(low, high));
    m_center = CGAL::midpoint(low, high);
    for(const auto& t : mesh.triangles)
    {
      const auto at = [&](std::size_t k) {
        if(t[k] >= mesh.vertices.size())
          throw std::invalid_argument("scan simulation: a triangle refers to a missing vertex");
        return K::Point_3(mesh.vertices[t[k]][0], mesh.vertices[t[k]][1], mesh.vertices[t[k]][2]);
      };
      const K::Triangle_3 triangle(at(0), at(1), at(2));
      if(!triangle.is_degenerate())
        m_triangles.push_back(triangle);
    }
    m_tree.insert(m_triangles.begin(), m_triangles.end());
    m_tree.build(); // before the parallel queries: the tree is otherwise built by the first one
  }

  /// The scan with angular step `along_step` along the lines (radians).
  Scan scan(double along_step) const
  {
    Scan result;
    const std::vector<K::Vector_3> directions = view_directions();
    for(std::size_t v = 0; v < m_options.views; ++v)
    {
      const View view = make_view(directions[v], along_step, v + 1 == m_options.views && m_options.views > 1);
      std::vector<Line> lines(view.lines);
      std::vector<std::size_t> indices(view.lines);
      std::iota(indices.begin(), indices.end(), std::size_t(0));
      CGAL::for_each<CGAL::Parallel_if_available_tag>(indices, [&](std::size_t i) {
        lines[i] = scan_line(view, v, i);
        return true;
      });
      for(Line& line : lines)
      {
        result.points.insert(result.points.end(), line.points.begin(), line.points.end());
        result.returns += line.returns;
        result.misses += line.misses;
        result.grazing += line.grazing;
        line = Line();
      }
      result.rays += view.lines * view.per_line;
    }
    return result;
  }

  /// The angular step that gives about `m_options.returns` returns: returns grow as the inverse
  /// square of the step, measured on a pilot scan of about `pilot_returns` returns.
  double step_for_target() const
  {
    // A pilot of this many returns estimates the hit rate within about 1% (the grid's share of
    // rays on the object changes with the step only at the object's silhouette).
    constexpr double pilot_returns = 20000;
    // Start from a step that puts this many rays in the window of each view.
    const double half_angle = std::asin(0.5 / m_options.distance) * m_options.window;
    double step = 2 * half_angle / std::sqrt(pilot_returns * m_options.line_spacing_ratio / double(m_options.views));
    const Scan pilot = scan(step);
    if(pilot.returns == 0)
      throw std::runtime_error("scan simulation: no ray hits the object");
    return step * std::sqrt(double(pilot.returns) / double((std::max)(m_options.returns, std::size_t(1))));
  }

private:
  View make_view(const K::Vector_3& direction, double along_step, bool misregistered) const
  {
    View view;
    view.eye = m_center + direction * (m_options.distance * m_diagonal);
    view.forward = -direction;
    // The scanner's rotation axis: vertical (z) unless the scanner looks along it.
    const K::Vector_3 vertical = std::abs(direction.z()) < 0.9 ? K::Vector_3(0, 0, 1) : K::Vector_3(1, 0, 0);
    view.right = unit(CGAL::cross_product(view.forward, vertical));
    view.up = CGAL::cross_product(view.right, view.forward);
    // The window covers the bounding sphere of the box (radius dB / 2), or more.
    view.half_angle = std::asin(0.5 / m_options.distance) * m_options.window;
    view.along_step = along_step;
    view.across_step = along_step * m_options.line_spacing_ratio;
    view.lines = std::size_t(2 * view.half_angle / view.across_step) + 1;
    view.per_line = std::size_t(2 * view.half_angle / view.along_step) + 1;
    if(misregistered)
      view.shift = view.forward * (m_options.misregistration * m_diagonal);
    return view;
  }

  Line scan_line(const View& view, std::size_t v, std::size_t i) const
  {
    // Each line its own generator, seeded from (seed, view, line): the scan does not depend on
    // the order in which lines are computed.
    std::seed_seq seeds{std::uint32_t(m_options.seed), std::uint32_t(m_options.seed >> 32), std::uint32_t(v),
                        std::uint32_t(i)};
    std::mt19937_64 generator(seeds);
    const double cos_max_incidence = std::cos(m_options.max_incidence_degrees * 3.14159265358979323846 / 180);
    const double noise = m_options.range_noise * m_diagonal;
    Line line;
    line.points.reserve(view.per_line);
    for(std::size_t j = 0; j < view.per_line; ++j)
    {
      const K::Vector_3 d = view.ray(i, j);
      const auto hit = m_tree.first_intersection(K::Ray_3(view.eye, d));
      const K::Point_3* point = hit ? boost::get<K::Point_3>(&hit->first) : nullptr;
      bool returned = false;
      if(!point)
        ++line.misses; // a ray lying in a triangle's plane (Segment) also counts as a miss
      else if(std::abs(unit(hit->second->supporting_plane().orthogonal_vector()) * d) < cos_max_incidence)
        ++line.grazing;
      else
      {
        const double range = std::sqrt(CGAL::squared_distance(view.eye, *point)) + noise * symmetric_uniform(generator);
        const K::Point_3 p = view.eye + d * range + view.shift;
        line.points.push_back({{p.x() + m_options.offset[0], p.y() + m_options.offset[1], p.z() + m_options.offset[2]}});
        ++line.returns;
        returned = true;
      }
      if(!returned && m_options.no_returns_as_origin)
        line.points.push_back({{0, 0, 0}});
    }
    return line;
  }

  Scan_options m_options;
  std::vector<K::Triangle_3> m_triangles;
  Tree m_tree;
  double m_diagonal = 0;
  K::Point_3 m_center;
};

} // namespace scan_internal

/// Scans `mesh` as `options` say: about `options.returns` returns from `options.views` viewpoints.
/// Throws std::invalid_argument for an empty mesh or options out of range, std::runtime_error if
/// no ray hits the mesh.
inline Scan scan_mesh(const Mesh& mesh, const Scan_options& options)
{
  const scan_internal::Scanner scanner(mesh, options);
  return scanner.scan(scanner.step_for_target());
}

} // namespace sfe_scan

#endif // SFE_BENCHMARK_SCAN_SIMULATION_H
