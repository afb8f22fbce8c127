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
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map} maps a range item to its `Point_3`; default: identity. \cgalParamNEnd
///   \cgalParamNBegin{geom_traits} an instance of a CGAL kernel; default: the point's kernel. \cgalParamNEnd
///   \cgalParamNBegin{degree_fitting} degree of the jet (1 or 2); default: 2. \cgalParamNEnd
///   \cgalParamNBegin{threshold_distance} the residual threshold tau (a distance); default: the mean residual of the points whose residual is at most their neighbourhood's radius (larger ones come from outliers). \cgalParamNEnd
///   \cgalParamNBegin{callback} a `std::function<bool(double)>` called with the progress in [0,1];
///     returning `false` stops the computation. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors} stage-1 neighbourhood size;
///     default: derived (see `estimate_sharp_feature_scales()`). \cgalParamNEnd
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
