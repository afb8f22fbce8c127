// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_ESTIMATE_SHARP_FEATURE_SCALES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_ESTIMATE_SHARP_FEATURE_SCALES_H

#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Estimates the scales that drive the five stages (see `Sharp_feature_scales`), as the
/// extraction context does when it is built.
///
/// From a regular subsample of at most 20,000 points: the spacing s (mean distance to the 6th
/// nearest neighbour), the noise (median RMS residual of the jets fitted to the 36 nearest
/// points; when a neighbourhood 5 noise scales wide holds more points, the lower quartile of
/// the RMS residuals of the jets fitted to that many, at most 400 of them spread over up to
/// 4,000 nearest, repeated while it grows; on the means below, or beyond 400 points, also until
/// a widening raises it by a larger factor than the one before, which reads curvature, not
/// noise). From these:
/// the stage-1 neighbourhood size (36 points, grown with the square of noise/s above 0.25 for
/// the noise over 36 points, or above 0.3 for the widened one if that asks for more, at most
/// 100; where the noise asks for k > 100, the cloud is thinned, by a hash of each point's
/// coordinates, to the fraction 400 / k if below 1 (the sampled points, see
/// `Sharp_feature_scales::sampled_fraction`), then to 100 / k, each point kept moving to the
/// mean of the sampled points it represents (see `Sharp_feature_scales::search_fraction`), and
/// the scales are measured again on the means with 100-point neighbourhoods, which span the
/// radius the noise asked for), the stage-2 size (twice as many), the RMLS tolerance
/// (2.25 x noise, at least 0.05 s), the corner radius (median radius of a stage-2
/// neighbourhood), the growth radius (median radius of a stage-1 neighbourhood) and the
/// completion distance (max(7 s, 3 x growth radius)). A scale given as a named parameter
/// replaces its estimate, and the scales derived from it follow (a larger
/// `candidate_neighbors` gives a larger growth radius).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`.
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
/// \param points the input points. Fewer than 20 distinct points, or no extent: every scale is 0.
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `SharpFeatureExtractionTraits`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{degree of the jets whose residuals measure the noise}
///     \cgalParamType{`int`: 1 or 2}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors}
///     \cgalParamDescription{number of points in a stage-1 neighbourhood}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{derived from the noise, as above}
///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors}
///     \cgalParamDescription{number of points in a stage-2 (RMLS) neighbourhood}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{twice `candidate_neighbors`}
///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance}
///     \cgalParamDescription{largest residual (a distance) of a point that belongs to a smooth
///       surface in the forward search of stage 2}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{2.25 times the noise, at least 5% of the spacing}
///     \cgalParamExtra{0 selects the default}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius}
///     \cgalParamDescription{corner points closer than this distance are grouped into one corner
///       (stage 2)}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{the median radius of a stage-2 neighbourhood}
///     \cgalParamExtra{0 selects the default}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius}
///     \cgalParamDescription{neighbourhood radius of polyline growing (stage 4)}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{the median radius of a stage-1 neighbourhood}
///     \cgalParamExtra{0 selects the default}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance}
///     \cgalParamDescription{largest gap bridged by completion (stage 5)}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{7 times the spacing, at least 3 times the growth radius}
///     \cgalParamExtra{0 selects the default}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the scales (the candidate threshold `residual_threshold` is left 0: stage 1 sets it).
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
Sharp_feature_scales<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits::FT>
estimate_sharp_feature_scales(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  static_assert(Sharp_feature_extraction::internal::holds_none_of<NamedParameters,
                  CGAL::internal_np::threshold_distance_t, CGAL::internal_np::sharpness_angle_t,
                  CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                  CGAL::internal_np::number_of_relaxation_steps_t, CGAL::internal_np::callback_t>(),
                "estimate_sharp_feature_scales: a parameter of a stage, not of the scales");
  return Sharp_feature_extraction_context<GT, ConcurrencyTag>(points, np).scales();
}

} // namespace CGAL

#endif
