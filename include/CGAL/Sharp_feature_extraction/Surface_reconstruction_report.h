// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_SURFACE_RECONSTRUCTION_REPORT_H
#define CGAL_SHARP_FEATURE_EXTRACTION_SURFACE_RECONSTRUCTION_REPORT_H

#include <CGAL/Sharp_feature_extraction/Mesh_3_polyline_repair_report.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/find_mesh_3_polyline_problems.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// The exception thrown by `reconstruct_surface_with_sharp_features()` when it cannot produce a
/// surface: too few points, a feature network without scales, a Poisson solver that does not
/// converge, a Mesh_3 failure (its assertion, in one line), or no surface found.
/// `what()` says which, in one line.
class Surface_reconstruction_error : public std::runtime_error
{
public:
  /// an error with the message `what`.
  explicit Surface_reconstruction_error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSharpFeatureExtractionRef
/// What `reconstruct_surface_with_sharp_features()` did: the sizes it chose, what it did to the
/// feature polylines and the normals, and how long each step took.
template <typename GeomTraits>
struct Surface_reconstruction_report
{
  /// The sampling spacing used (the feature network's, mean distance to the 6th nearest neighbour).
  double spacing = 0;
  /// The noise scale used (the feature network's).
  double noise = 0;
  /// Mesh_3's largest radius of a surface Delaunay ball.
  double facet_size = 0;
  /// Mesh_3's largest distance from a facet to the implicit surface.
  double facet_distance = 0;
  /// Mesh_3's largest protecting ball along a polyline (mesh edge along a crease).
  double edge_size = 0;
  /// Mesh_3's smallest facet angle, in degrees.
  double facet_angle = 0;
  /// The lift added to the implicit function where it was negative far from the points (a
  /// distance; zero on most inputs).
  double far_field = 0;

  /// What the Mesh_3 repair of the polylines changed.
  Mesh_3_polyline_repair_report repair;
  /// What the repair changed when it ran again on the polylines moved onto the implicit
  /// surface (the move and the cuts can undo the first repair), and the polylines it dropped
  /// last because they still did not pass `find_mesh_3_polyline_problems()`.
  Mesh_3_polyline_repair_report repair_after_projection;
  /// Polyline vertices moved onto the implicit surface before meshing.
  std::size_t moved_onto_surface = 0;
  /// Polylines cut where a vertex had no point of the implicit surface near it.
  std::size_t cut_off_surface = 0;
  /// Polylines cut where the implicit surface had another sheet within a protecting ball of a
  /// vertex (a wall thinner than the ball, or a gap narrower than it): Mesh_3 cannot protect
  /// them there.
  std::size_t cut_near_other_sheet = 0;
  /// Polyline vertices moved onto the crease of the two surfaces fitted on either side.
  std::size_t projected_onto_creases = 0;
  /// The polylines protected in Mesh_3, as it got them (repaired, and moved onto the implicit
  /// surface); empty when `protect_polylines` is `false`.
  std::vector<Feature_polyline<GeomTraits>> protected_polylines;
  /// Mesh vertices Mesh_3 put on the protected polylines.
  std::size_t protected_vertices = 0;

  /// Points whose normal was replaced by the normal of their own side of a crease.
  std::size_t corrected_normals = 0;
  /// Points whose normal could not be oriented (left out of the implicit surface).
  std::size_t unoriented_points = 0;

  /// `true` if Mesh_3 was stopped (time limit, vertex limit, or `callback`): the surface is
  /// incomplete, and may be neither closed nor manifold.
  bool stopped = false;
  /// Why Mesh_3 was stopped, in one line (empty when it was not).
  std::string stop_reason;

  /// Seconds spent on the normals (estimation, orientation, correction).
  double seconds_normals = 0;
  /// Seconds spent on the implicit function.
  double seconds_poisson = 0;
  /// Seconds spent in Mesh_3.
  double seconds_meshing = 0;
};

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_SURFACE_RECONSTRUCTION_REPORT_H
