// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_ESTIMATE_SHARP_FEATURE_SCALES_FOR_TILES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_ESTIMATE_SHARP_FEATURE_SCALES_FOR_TILES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/tiling_impl.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Estimates, once for a whole cloud, the scales that every tile of it shares (see
/// `extract_tile_features()`): those of `estimate_sharp_feature_scales()`, and the candidate
/// threshold of stage 1 (`residual_threshold`), which the untiled pipeline takes from every
/// point's residual and which here comes from the residuals of the same regular subsample of at
/// most 20,000 points as the other scales (the mean of those at most `candidate_radius`).
///
/// `points` may be the whole cloud or a part of it that keeps its sampling density: whole
/// tiles, say, never every k-th point (a sparser cloud has a larger spacing, and all the
/// scales follow it).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`.
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
/// \param points the input points.
/// \param np optional named parameters: those of `estimate_sharp_feature_scales()` (`point_map`,
///   `geom_traits`, `degree_fitting` and the scales), and:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{threshold_distance}
///     \cgalParamDescription{the candidate threshold tau (a distance)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{estimated on the subsample, as above}
///     \cgalParamExtra{a negative value selects the default}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the scales, `residual_threshold` included. Fewer than 20 distinct points, or no
///   extent: every scale is 0.
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
Sharp_feature_scales<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits::FT>
estimate_sharp_feature_scales_for_tiles(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_none_of<NamedParameters, CGAL::internal_np::sharpness_angle_t,
                  CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                  CGAL::internal_np::number_of_relaxation_steps_t, CGAL::internal_np::callback_t>(),
                "estimate_sharp_feature_scales_for_tiles: a parameter of a stage, not of the scales");
  return sfe::convert_scales<typename GT::FT>(sfe::scales_for_tiles<ConcurrencyTag>(points, np));
}

} // namespace CGAL

#endif
