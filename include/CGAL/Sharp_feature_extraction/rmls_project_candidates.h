// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_RMLS_PROJECT_CANDIDATES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_RMLS_PROJECT_CANDIDATES_H

#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Stage 2: projects the candidate points onto the intersections of the smooth surfaces that
/// meet near them (paper, section 3.3), with robust moving least squares (RMLS).
///
/// For each candidate, a forward search splits its `rmls_neighbors` nearest points into smooth
/// surfaces: a least-residual seed of 12 points (20 on noisy data) grows by batches of the best-fitting points while
/// their residual stays below the RMLS tolerance; the surface is removed and the search repeats,
/// up to three surfaces. Surfaces whose normals differ by less than `sharpness_angle` are one
/// surface split by noise. With one surface the candidate is dropped; with two, a Newton-like
/// iteration projects it onto their intersection (an edge point with both normals); with three,
/// also onto the common point of the three (a corner point). Corner points within the corner
/// radius are grouped, keeping the one closest to the weighted average (weights 1/|c - e|);
/// groups of fewer than 3 corner points are dropped.
///
/// On noise-free data, neighbouring candidates share their surfaces: the candidates are grouped
/// by grid cells of 1.5 spacings, the forward search runs around the candidate of largest
/// residual in each cell (the next ones if it finds fewer than two surfaces, up to three), and
/// every candidate of the cell that those surfaces explain (it lies on one of them, and so do
/// more than 90% of the searched points around it) is projected onto them; the others search
/// their own. Every candidate still gives its own edge point, for about one forward search per
/// cell. On noisy data every candidate searches its own surfaces, so that its edge point is an
/// independent estimate for the smoothing of stage 3 to average.
///
/// \param points the input points (the same range as given to `compute_candidate_points()`).
/// \param candidates the output of `compute_candidate_points()`: its indices, residuals (which
///   rank the candidates of a cell; without one residual per point, they rank by index) and
///   scales are used. The points are indexed again, with these scales: to run several stages
///   on the same points, use a `Sharp_feature_extraction_context`.
/// \param projected receives the edge and corner points.
/// \param np optional named parameters: `point_map`, `geom_traits`, `callback` as in
///   `compute_candidate_points()`, and
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{degree_fitting} degree of the surface fits (1 or 2); default: 2. \cgalParamNEnd
///   \cgalParamNBegin{sharpness_angle} smallest angle, in degrees, between the normals of two
///     surfaces that meet at a sharp feature; default: 25. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors} stage-2 neighbourhood
///     size; default: `candidates.scales.rmls_neighbors`. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance} RMLS tolerance (a
///     distance); default: `candidates.scales.rmls_tolerance`. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius} corner grouping radius;
///     default: `candidates.scales.corner_radius`. \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the callback interrupted the computation.
/// \throws std::invalid_argument if a coordinate is not finite, a candidate index is out of the
///   range of the points or a parameter is out of range.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
bool rmls_project_candidates(
  const PointRange& points,
  const Candidate_points<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>& candidates,
  Feature_point_set<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>& projected,
  const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  namespace own_np = Sharp_feature_extraction::internal_np;
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  static_assert(sfe::holds_none_of<NamedParameters, own_np::candidate_neighbors_t, own_np::growth_radius_t,
                                   own_np::completion_distance_t, CGAL::internal_np::threshold_distance_t,
                                   CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                                   CGAL::internal_np::number_of_relaxation_steps_t>(),
                "rmls_project_candidates: a parameter of another stage");
  const Sharp_feature_extraction_context<GT, ConcurrencyTag> context(points, candidates.scales, np);
  return context.rmls_project_candidates(candidates, projected, np);
}

} // namespace CGAL

#endif
