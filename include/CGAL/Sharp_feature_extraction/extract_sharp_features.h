// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_SHARP_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_SHARP_FEATURES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
// The stage functions, so that one include gives the whole pipeline, stage by stage too.
#include <CGAL/Sharp_feature_extraction/compute_candidate_points.h>
#include <CGAL/Sharp_feature_extraction/rmls_project_candidates.h>
#include <CGAL/Sharp_feature_extraction/smooth_feature_points.h>
#include <CGAL/Sharp_feature_extraction/grow_feature_polylines.h>
#include <CGAL/Sharp_feature_extraction/complete_feature_polylines.h>
#include <CGAL/Sharp_feature_extraction/internal/candidate_points_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/completion_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/conversions.h>
#include <CGAL/Sharp_feature_extraction/internal/polyline_growing_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/rmls_projection_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/smoothing_impl.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Real_timer.h>

#include <type_traits>
#include <vector>

namespace CGAL {

namespace Sharp_feature_extraction {
namespace internal {

/// Share of the progress range given to each stage (stage 1 and 2 dominate).
constexpr double progress_end_of_stage[5] = {0.35, 0.9, 0.97, 0.99, 1.0};

/// The five stages on `input`, whose spatial index serves stages 1 and 2. The time spent
/// reading and indexing the input counts in stage 1.
template <typename ConcurrencyTag, typename GT>
bool run_pipeline(const Indexed_input& input, const Settings& settings, Sharp_features<GT>& result)
{
  result = Sharp_features<GT>();
  Progress progress(settings.callback);
  CGAL::Real_timer timer;

  timer.start();
  Candidate_output candidates;
  if(!compute_candidates<ConcurrencyTag>(input, settings, progress.sub(0, progress_end_of_stage[0]), candidates))
    return false;
  const Scales& scales = candidates.scales;
  result.candidates = to_public<GT>(input, candidates);
  result.timings.candidates = timer.time();

  timer.reset();
  Feature_samples features;
  if(!rmls_project<ConcurrencyTag>(input, candidates.candidates, candidates.residuals, scales, settings,
                                   progress.sub(progress_end_of_stage[0], progress_end_of_stage[1]), features))
    return false;
  result.projected = to_public<GT>(features, scales);
  result.timings.projection = timer.time();

  timer.reset();
  if(!smooth_edge_points<ConcurrencyTag>(features, settings,
                                         progress.sub(progress_end_of_stage[1], progress_end_of_stage[2])))
    return false;
  result.smoothed = to_public<GT>(features, scales);
  result.timings.smoothing = timer.time();

  timer.reset();
  Progress growing = progress.sub(progress_end_of_stage[2], progress_end_of_stage[3]);
  Curve_network network = grow_polylines(features, scales.growth_radius, growing);
  if(growing.cancelled())
    return false;
  result.grown = to_public<GT>(network, scales);
  result.timings.growing = timer.time();

  timer.reset();
  complete_polylines(network, scales, settings);
  result.network = to_public<GT>(network, scales);
  result.timings.completion = timer.time();
  return progress.report(1.);
}

} // namespace internal
} // namespace Sharp_feature_extraction

/// \ingroup PkgSharpFeatureExtractionRef
/// Extracts the sharp feature curves of a point cloud: the five stages of Daniels et al. 2007
/// (`compute_candidate_points()`, `rmls_project_candidates()`, `smooth_feature_points()`,
/// `grow_feature_polylines()`, `complete_feature_polylines()`), with every intermediate result.
///
/// The default call needs only the points: every scale is derived from the data (see
/// `compute_candidate_points()` and `Sharp_feature_scales`) and `result.network.scales` reports
/// the values used.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`. The result does not depend on the number of threads.
/// \param points the input points; no normals are needed.
/// \param result receives the curves, corners, normals and every intermediate point set.
/// \param np any named parameter of the five stage functions.
/// \returns `false` if the `callback` interrupted the computation (the result is then partial).
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
///
/// Exact duplicates count once (every stage merges them: they add no surface information), so a
/// cloud and the same cloud with its points repeated, in any number, give the same curves. A
/// cloud with fewer than 20 distinct points yields no curves (and the function returns `true`).
template <typename ConcurrencyTag, typename PointRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
bool extract_sharp_features(const PointRange& points, Sharp_features<GeomTraits>& result,
                            const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  const sfe::Settings settings = sfe::read_settings(np);
  CGAL::Real_timer indexing;
  indexing.start();
  sfe::Indexed_input input;
  sfe::index_input_points<ConcurrencyTag>(points, np, input);
  indexing.stop();
  const bool completed = sfe::run_pipeline<ConcurrencyTag>(input, settings, result);
  result.timings.candidates += indexing.time();
  return completed;
}

/// \ingroup PkgSharpFeatureExtractionRef
/// Extracts the sharp feature curves of a point cloud and writes each one, as a
/// `std::vector<Point_3>`, to `polylines`: the format `Mesh_domain_with_polyline_features_3::add_features()`
/// takes. Closed curves repeat their first point exactly; curves meeting at a corner share that
/// exact point. Same parameters as the overload that fills a `Sharp_features`.
/// \returns `false` if the `callback` interrupted the computation (nothing is written then).
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
std::enable_if_t<!std::is_base_of<Sharp_features<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>,
                                  OutputIterator>::value, bool>
extract_sharp_features(const PointRange& points, OutputIterator polylines,
                       const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  Sharp_features<GT> result;
  if(!extract_sharp_features<ConcurrencyTag>(points, result, np))
    return false;
  for(const Feature_polyline<GT>& p : result.network.polylines)
    *polylines++ = p.points;
  return true;
}

} // namespace CGAL

#endif
