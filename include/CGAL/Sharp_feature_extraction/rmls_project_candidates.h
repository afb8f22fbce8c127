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
/// cell. On noisy data (noise above 5% of the spacing) the cells are 1.5 RMLS tolerances wide,
/// the candidates of a cell search their own surfaces in turn until one gives an edge point
/// within two cell sides of itself, and only those that found surfaces are projected: the
/// neighbourhoods of candidates that close hold mostly the same points, so their edge points
/// would repeat one estimate. A candidate does not search when the search before it in its cell
/// found one plane and no crease, and that plane holds all but 3% of the points around the
/// candidate within the tolerance: its own search would find that plane alone too. Near a
/// corner or a shallow crease (within the corner radius of a candidate whose search found three
/// surfaces, or two whose normals are less than 40 degrees apart) the candidates that this
/// first pass did not reach also search their own surfaces and are projected: a corner gets its
/// group of corner points, and a shallow crease, where few searches succeed under noise, every
/// edge point they give.
///
/// \param points the input points (the same range as given to `compute_candidate_points()`).
/// \param candidates the output of `compute_candidate_points()`: its indices, residuals (which
///   rank the candidates of a cell; without one residual per point, they rank by index) and
///   scales are used. The points are indexed again, with these scales: to run several stages
///   on the same points, use a `Sharp_feature_extraction_context`.
/// \param projected receives the edge and corner points.
/// \param np optional named parameters among the ones listed below; a parameter of another
///   stage does not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `SharpFeatureExtractionTraits`}
///     \cgalParamDefault{the kernel of the point type of `point_map`}
///     \cgalParamExtra{it gives the type of `candidates` and `projected`}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{degree of the smooth surfaces fitted in the forward search: 1
///       (planes) or 2 (quadrics)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{on noisy data (a noise scale above 5% of the spacing, see
///       `Sharp_feature_scales`) the surfaces are planes whatever this value}
///   \cgalParamNEnd
///   \cgalParamNBegin{sharpness_angle}
///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces that
///       meet at a sharp feature; surfaces closer in angle are one surface split by noise}
///     \cgalParamType{`double`}
///     \cgalParamDefault{25}
///     \cgalParamExtra{must be in (0, 90)}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of the work done (from 0
///       to 1); when it returns `false` the computation stops and the function returns `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors}
///     \cgalParamDescription{number of points in a stage-2 (RMLS) neighbourhood}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`candidates.scales.rmls_neighbors`}
///     \cgalParamExtra{0 keeps the default; a positive value replaces
///       `candidates.scales.rmls_neighbors` for this call}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance}
///     \cgalParamDescription{largest residual (a distance) of a point that belongs to a smooth
///       surface in the forward search}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{`candidates.scales.rmls_tolerance`}
///     \cgalParamExtra{0 keeps the default; a positive value replaces
///       `candidates.scales.rmls_tolerance` for this call}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius}
///     \cgalParamDescription{corner points closer than this distance are grouped into one corner}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{`candidates.scales.corner_radius`}
///     \cgalParamExtra{0 keeps the default; a positive value replaces
///       `candidates.scales.corner_radius` for this call}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the callback interrupted the computation.
/// \throws std::invalid_argument if a coordinate is not finite, a candidate index is out of the
///   range of the points, a parameter is out of range or a scale of `candidates.scales` is
///   negative or not finite.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
bool rmls_project_candidates(
  const PointRange& points,
  const Candidate_points<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>& candidates,
  Feature_point_set<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>& projected,
  const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  static_assert(sfe::holds_only_projection_parameters<NamedParameters>(),
                "rmls_project_candidates: a parameter of another stage");
  const Sharp_feature_extraction_context<GT, ConcurrencyTag> context(points, candidates.scales, np);
  return context.rmls_project_candidates(candidates, projected, np);
}

} // namespace CGAL

#endif
