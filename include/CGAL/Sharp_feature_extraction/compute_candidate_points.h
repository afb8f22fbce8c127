// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_COMPUTE_CANDIDATE_POINTS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_COMPUTE_CANDIDATE_POINTS_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/candidate_points_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/conversions.h>
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
/// This stage also derives every scale of the pipeline from the data (see `Sharp_feature_scales`):
/// the spacing s (mean distance to the 6th neighbour), the noise (median RMS residual of 36-point
/// jets), the neighbourhood sizes (36 points, grown quadratically with noise/s above 0.25, at
/// most 400; stage 2 uses twice as many), the RMLS tolerance (2.25 x noise, at least 0.05 s), the
/// corner radius (median radius of a stage-2 neighbourhood), the growth radius (median radius of
/// a stage-1 neighbourhood) and the completion distance (max(7 s, 3 x growth radius)).
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
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors} stage-1 neighbourhood size; default: derived. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors} stage-2 neighbourhood size; default: twice the stage-1 size. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance} RMLS tolerance (a distance); default: derived. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius} corner grouping radius; default: derived. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius} polyline growing radius; default: derived. \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance} largest gap bridged by completion; default: derived.
///     These five only set the scales stored in `candidates.scales` for the later stages
///     (see `Sharp_feature_scales`). \cgalParamNEnd
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
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  const sfe::Settings settings = sfe::read_settings(np);
  sfe::Indexed_input input;
  sfe::index_input_points<ConcurrencyTag>(points, np, input);
  sfe::Candidate_output out;
  const bool completed = sfe::compute_candidates<ConcurrencyTag>(input, settings,
                                                                 sfe::Progress(settings.callback), out);
  candidates = sfe::to_public<GT>(input, out);
  return completed;
}

} // namespace CGAL

#endif
