// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_MESH_3_POLYLINE_PROBLEM_H
#define CGAL_SHARP_FEATURE_EXTRACTION_MESH_3_POLYLINE_PROBLEM_H

#include <cstddef>
#include <string>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// One reason why `Mesh_domain_with_polyline_features_3::add_features()` could reject a set of
/// polylines, as found by `find_mesh_3_polyline_problems()`.
struct Mesh_3_polyline_problem
{
  /// What is wrong.
  enum Kind {
    TOO_FEW_POINTS,      ///< a polyline with fewer than two points
    NON_FINITE_POINT,    ///< a coordinate is infinite or NaN
    ZERO_LENGTH_SEGMENT, ///< two consecutive points are equal
    DEGENERATE_LOOP,     ///< a closed polyline with fewer than three distinct points
    UNSHARED_END,        ///< an end lies near an end (of another polyline, or of its own) without being that point
    END_ON_INTERIOR,     ///< an end lies on the interior of a polyline, which is not split there
    SHARP_TURN,          ///< the polyline turns by more than the maximum angle inside
    UNSHARED_CONTACT     ///< vertices of two polylines (or far apart along one) are close without being one point
  };
  /// What is wrong.
  Kind kind = TOO_FEW_POINTS;
  /// The index of the polyline concerned.
  std::size_t polyline = 0;
  /// The index of the other polyline involved (`polyline` itself when there is none).
  std::size_t other_polyline = 0;
  /// One line of explanation, for people.
  std::string description;
};

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_MESH_3_POLYLINE_PROBLEM_H
