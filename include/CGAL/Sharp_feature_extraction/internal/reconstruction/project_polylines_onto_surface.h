// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The protected polylines moved onto the implicit surface that Mesh_3 meshes.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_PROJECT_POLYLINES_ONTO_SURFACE_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_PROJECT_POLYLINES_ONTO_SURFACE_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_contract.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_repair.h>
#include <CGAL/Sharp_feature_extraction/internal/Spatial_grid.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace reconstruction {

/// The tolerances of `project_polylines_onto_surface()`, as absolute distances.
struct Polyline_projection_settings
{
  /// Step of the central differences of the gradient of the function.
  double gradient_step = 0;
  /// A vertex farther than this from the zero set is off the surface.
  double maximal_move = 0;
  /// Another sheet of the zero set nearer than this to a vertex, along its normal, makes the
  /// vertex unfit for protection.
  double clearance = 0;
  /// The step of the search for that sheet.
  double clearance_step = 0;
  /// Every curve is cut within this distance of a vertex (of any curve) off the surface or
  /// near another sheet.
  double cut_margin = 0;
  /// Pieces shorter than this are dropped.
  double minimum_length = 0;
};

/// What `project_polylines_onto_surface()` did.
struct Polyline_projection_counts
{
  std::size_t moved_onto_surface = 0;   ///< vertices moved
  std::size_t cut_off_surface = 0;      ///< curves cut where a vertex was off the surface
  std::size_t cut_near_other_sheet = 0; ///< curves cut where another sheet was too near a vertex
};

/// the gradient of `function` at `x` by central differences `h` apart.
template <typename Function, typename Point_3>
typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 central_gradient(const Function& function, const Point_3& x,
                                                                         double h)
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector_3;
  return Vector_3((function(x + Vector_3(h, 0, 0)) - function(x - Vector_3(h, 0, 0))) / (2 * h),
                  (function(x + Vector_3(0, h, 0)) - function(x - Vector_3(0, h, 0))) / (2 * h),
                  (function(x + Vector_3(0, 0, h)) - function(x - Vector_3(0, 0, h))) / (2 * h));
}

/// moves `p` onto the zero set of `function` (a signed distance, up to a factor near 1) by
/// Newton steps along its gradient, taken by central differences `gradient_step` apart. Returns
/// false, leaving `p`, when no zero within `max_move` is found.
template <typename Function, typename Point_3>
bool project_onto_zero_set(const Function& function, Point_3& p, double gradient_step, double max_move)
{
  // converged: a hundredth of the gradient step, far below any facet distance
  const double tolerance = 1e-2 * gradient_step;
  const int maximal_steps = 20;
  Point_3 x = p;
  for(int step = 0; step < maximal_steps; ++step) {
    const double value = function(x);
    if(std::abs(value) <= tolerance) {
      if(mesh_polylines::point_distance(x, p) > max_move)
        return false;
      p = x;
      return true;
    }
    const auto gradient = central_gradient(function, x, gradient_step);
    const double squared_norm = CGAL::to_double(gradient.squared_length());
    if(!(squared_norm > 0))
      return false;
    x = x - (value / squared_norm) * gradient;
    if(mesh_polylines::point_distance(x, p) > max_move)
      return false;
  }
  return false;
}

/// whether the zero set of `function` has no other sheet than the one through `p` (a point of
/// it) within `settings.clearance` of `p` along its normal: inward, the far side of a wall
/// (where the function turns positive again), outward, the near side of a gap (where it turns
/// negative), searched `settings.clearance_step` apart.
template <typename Function, typename Point_3>
bool is_clear_of_other_sheets(const Function& function, const Point_3& p, const Polyline_projection_settings& settings)
{
  const auto gradient = central_gradient(function, p, settings.gradient_step);
  const double norm = std::sqrt(CGAL::to_double(gradient.squared_length()));
  if(!(norm > 0))
    return false;
  const auto normal = gradient / norm;
  for(double t = settings.clearance_step; t < settings.clearance; t += settings.clearance_step)
    if(function(p - t * normal) > 0 || function(p + t * normal) < 0)
      return false;
  return true;
}

/// Mesh_3 makes every protected vertex a mesh vertex and refines the surface around it until
/// the facets are within the facet distance of the surface: a protected vertex off the implicit
/// surface can never be reached, and the refinement shrinks towards it without end. So every
/// vertex of `curves` is moved onto the zero set of `function` (leaving the vertices within
/// half the facet distance where they were still let Mesh_3 converge onto a point: anchor,
/// 25k points, noise 0, seed 2). Mesh_3 covers the vertices with protecting balls that must
/// meet no other sheet of the surface; where one does (a curve along a wall thinner than a
/// ball), Mesh_3 shrinks the balls and refines the facets between them without end. Where a
/// vertex has no zero within `maximal_move`, or another sheet within `clearance` (see
/// `is_clear_of_other_sheets()`), the surface is not protectable there (a spurious curve, a
/// corner the surface rounds off, a thin wall, a fold of the surface): every curve is cut
/// within `cut_margin` of such a vertex, its own and the others, and pieces shorter than
/// `minimum_length` are dropped. (Pinion, 25k points, noise 0, seed 1: at a corner of three
/// curves, the implicit surface folds into the gap between two teeth; two of the curves found
/// it and were cut, the third kept its end at the corner, then, cut 3 s from the first two,
/// a vertex 2.7 s from the fold, and Mesh_3 refined its protecting ball onto the fold for the
/// whole time limit.) Shared points stay shared: the projection is a function of the point
/// alone.
template <typename GeomTraits, typename Function>
void project_polylines_onto_surface(std::vector<Feature_polyline<GeomTraits>>& curves, const Function& function,
                                    const Polyline_projection_settings& settings, Polyline_projection_counts& counts)
{
  typedef Feature_polyline<GeomTraits> Curve;
  typedef typename GeomTraits::Point_3 Point_3;
  using namespace mesh_polylines;
  // the unprotectable vertices of all curves, each with whether it is off the surface
  std::vector<std::vector<bool>> protectable(curves.size());
  std::vector<bool> unprotectable_off_surface;
  Spatial_grid<Point_3> unprotectable(settings.cut_margin);
  for(std::size_t k = 0; k < curves.size(); ++k) {
    Curve& c = curves[k];
    protectable[k].resize(c.points.size());
    for(std::size_t i = 0; i < c.points.size(); ++i) {
      const Point_3 before = c.points[i];
      const bool on_surface = project_onto_zero_set(function, c.points[i], settings.gradient_step,
                                                    settings.maximal_move);
      counts.moved_onto_surface += (on_surface && c.points[i] != before) ? 1 : 0;
      protectable[k][i] = on_surface && is_clear_of_other_sheets(function, c.points[i], settings);
      if(!protectable[k][i]) {
        unprotectable.insert(c.points[i], unprotectable_off_surface.size());
        unprotectable_off_surface.push_back(!on_surface);
      }
    }
  }
  std::vector<Curve> kept;
  for(std::size_t k = 0; k < curves.size(); ++k) {
    Curve& c = curves[k];
    const std::size_t n = c.points.size();
    // clear: protectable, and no unprotectable vertex of any curve within the cut margin
    std::vector<bool> clear(n);
    bool off_surface = false, near_other_sheet = false;
    for(std::size_t i = 0; i < n; ++i) {
      clear[i] = protectable[k][i];
      unprotectable.for_each_within(c.points[i], settings.cut_margin, [&](std::size_t id, double) {
        clear[i] = false;
        off_surface = off_surface || unprotectable_off_surface[id];
        near_other_sheet = near_other_sheet || !unprotectable_off_surface[id];
      });
    }
    if(!off_surface && !near_other_sheet) {
      kept.push_back(std::move(c));
      continue;
    }
    counts.cut_off_surface += off_surface ? 1 : 0;
    counts.cut_near_other_sheet += near_other_sheet ? 1 : 0;
    const std::vector<double> arc = arc_lengths(c);
    for(std::size_t first = 0; first < n;) {
      if(!clear[first]) {
        ++first;
        continue;
      }
      std::size_t last = first;
      while(last < n && clear[last])
        ++last;
      // the run [first, last) of clear vertices
      if(last >= first + 2 && arc[last - 1] - arc[first] >= settings.minimum_length) {
        std::vector<std::size_t> cuts;
        if(first > 0)
          cuts.push_back(first);
        if(last < n)
          cuts.push_back(last - 1);
        // the piece between the cuts: the second of the split's pieces if it starts with a cut
        const std::vector<Curve> pieces = split(c, cuts);
        kept.push_back(pieces[first > 0 ? 1 : 0]);
      }
      first = last;
    }
  }
  curves = std::move(kept);
}
} // namespace reconstruction
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_PROJECT_POLYLINES_ONTO_SURFACE_H
