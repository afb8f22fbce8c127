// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_COMPUTE_CANDIDATE_POINTS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_COMPUTE_CANDIDATE_POINTS_H

#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Stage 1: finds the points near potential sharp features (paper, section 3.2).
///
/// For every point p, a jet (degree-2 polynomial height field over the principal plane) is fitted
/// to its nearest neighbours; the residual r(p) is the largest distance, along the plane normal,
/// from a neighbour to the jet. Points with r(p) above the threshold tau (default: the mean
/// residual, as in the paper) are candidates. Outliers also score high; stage 2 rejects them.
///
/// The scales come from the extraction context built on `points` (see
/// `estimate_sharp_feature_scales()`); `candidates.scales` carries them, with the threshold, to
/// the later stages. To run several stages on the same points without indexing them again,
/// use a `Sharp_feature_extraction_context`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`.
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
///
/// \param points the input points (at least 20 distinct ones for any candidate to be found).
///   Exact duplicates are merged before indexing: every copy of a point gets the residual of the
///   first copy, and is a candidate when that one is.
/// \param candidates receives the residuals, the candidate indices and the scales.
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
///     \cgalParamExtra{it gives the type of `candidates`}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{degree of the jets fitted to the neighbourhoods: 1 (planes) or 2
///       (quadrics)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{the jets that estimate the noise, from which the scales are derived, have
///       this degree too (see `estimate_sharp_feature_scales()`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{threshold_distance}
///     \cgalParamDescription{the candidate threshold tau: a point whose residual exceeds it is a
///       candidate}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{the mean residual of the points whose residual is at most the radius of a
///       stage-1 neighbourhood (`Sharp_feature_scales::candidate_radius`; larger residuals come
///       from outliers); on noisy clouds at most 1.3 times the median residual (the mean then
///       also holds the fits of smooth surfaces that bend within a neighbourhood, and can rise
///       above the residuals of the creases)}
///     \cgalParamExtra{a negative value selects the default; the threshold used is stored in
///       `candidates.scales.residual_threshold`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of the work done (from 0
///       to 1); when it returns `false` the computation stops and the function returns `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors}
///     \cgalParamDescription{number of points in a stage-1 neighbourhood}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{derived from the noise (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]. The
///       scales derived from it (`rmls_neighbors`, the growth radius, the completion distance)
///       follow}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `false` if the callback interrupted the computation (then `candidates` is incomplete).
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
bool compute_candidate_points(
  const PointRange& points,
  Candidate_points<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>& candidates,
  const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  namespace own_np = Sharp_feature_extraction::internal_np;
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  static_assert(sfe::holds_none_of<NamedParameters, own_np::rmls_neighbors_t, own_np::rmls_tolerance_t,
                                   own_np::corner_radius_t, own_np::growth_radius_t, own_np::completion_distance_t,
                                   CGAL::internal_np::sharpness_angle_t, CGAL::internal_np::number_of_iterations_t,
                                   CGAL::internal_np::maximum_angle_t, CGAL::internal_np::number_of_relaxation_steps_t>(),
                "compute_candidate_points: a parameter of another stage");
  const Sharp_feature_extraction_context<GT, ConcurrencyTag> context(points, np);
  return context.compute_candidate_points(candidates);
}

} // namespace CGAL

#endif
