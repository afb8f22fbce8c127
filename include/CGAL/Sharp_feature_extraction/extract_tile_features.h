// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_TILE_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_TILE_FEATURES_H

#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/Tile_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/tiling_impl.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <functional>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Runs stages 1 to 3 (candidates, RMLS projection, smoothing) on one tile of a cloud and keeps
/// the feature points its core box owns: the first of the three pieces of a distributed
/// extraction (`estimate_sharp_feature_scales_for_tiles()` once, this function on every tile,
/// anywhere, in any order, then `stitch_tile_features()`).
///
/// `points` are the points of the cloud within `tile_halo_width()` of `core` (along each axis):
/// the core and its halo. With that halo, the feature points whose source lies in `core` are
/// exactly those that the whole cloud gives (up to rounding in the last bits: the points are
/// summed in another order); with a narrower one, those near the faces may differ. Stage 1
/// uses `scales.residual_threshold` as its candidate threshold, so that every tile shares it.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`. The result does not depend on the number of threads.
/// \param points the tile's points (core and halo); no normals are needed.
/// \param core the tile's core box, half-open: a point on its max faces belongs to the next tile.
/// \param scales the scales of the whole cloud, as `estimate_sharp_feature_scales_for_tiles()`
///   returns them (the same for every tile).
/// \param tile receives the feature points owned by `core` (see `Tile_features`).
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{read by stages 1 and 2}
///   \cgalParamNEnd
///   \cgalParamNBegin{sharpness_angle}
///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces that
///       meet at a sharp feature}
///     \cgalParamType{`double`}
///     \cgalParamDefault{25}
///     \cgalParamExtra{read by stage 2; must be in (0, 90)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{number of smoothing passes}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{3}
///     \cgalParamExtra{read by stage 3; give the same to `tile_halo_width()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of the work done (from 0
///       to 1); when it returns `false` the computation stops and the function returns `false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// A scale or `threshold_distance` (fixed by `scales`) and a parameter of stage 4 or 5 do not
/// compile.
/// \returns `false` if the callback interrupted the computation (`tile` is then partial).
/// \throws std::invalid_argument if a coordinate is not finite, a parameter is out of range, a
///   scale is negative or not finite, `scales.sampled_fraction` is not in (0, 1], or `core`
///   does not have min < max on every axis.
template <typename ConcurrencyTag, typename PointRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
bool extract_tile_features(const PointRange& points, const CGAL::Bbox_3& core,
                           const Sharp_feature_scales<typename GeomTraits::FT>& scales,
                           Tile_features<GeomTraits>& tile,
                           const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  static_assert(sfe::holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS, CGAL::internal_np::threshold_distance_t,
                                   CGAL::internal_np::maximum_angle_t, CGAL::internal_np::number_of_relaxation_steps_t>(),
                "extract_tile_features: the scales and the threshold come from `scales`; stages 4 and 5 run in the stitcher");
  sfe::require_core_box(core);
  tile = Tile_features<GeomTraits>();
  tile.core = core;
  tile.scales = scales;

  std::vector<bool> owned;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  for(const auto& item : points)
  {
    const auto& p = get(point_map, item);
    owned.push_back(sfe::in_core(core, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  tile.number_of_core_points = std::size_t(std::count(owned.begin(), owned.end(), true));

  const Sharp_feature_extraction_context<GeomTraits, ConcurrencyTag> context(
    points, scales, np.threshold_distance(CGAL::to_double(scales.residual_threshold)));
  tile.timings.context = context.construction_time();
  sfe::Progress progress(sfe::read_callback(np));
  const auto stage = [&](int s) {
    // The pipeline's shares of the progress, without stages 4 and 5.
    const double whole = sfe::progress_end_of_stage[2];
    sfe::Progress p = progress.sub(s == 0 ? 0. : sfe::progress_end_of_stage[s - 1] / whole,
                                   sfe::progress_end_of_stage[s] / whole);
    return CGAL::parameters::callback(std::function<bool(double)>([p](double f) mutable { return p.report(f); }));
  };
  CGAL::Real_timer timer;
  timer.start();
  Candidate_points<GeomTraits> candidates;
  if(!context.compute_candidate_points(candidates, stage(0)))
    return false;
  tile.timings.candidates = timer.time();
  timer.reset();
  Feature_point_set<GeomTraits> features;
  if(!context.rmls_project_candidates(candidates, features, stage(1)))
    return false;
  tile.timings.projection = timer.time();
  timer.reset();
  if(!context.smooth_feature_points(features, stage(2)))
    return false;
  tile.timings.smoothing = timer.time();

  for(std::size_t i : candidates.indices)
    tile.number_of_candidates += owned[i] ? 1 : 0;
  for(const Edge_point<GeomTraits>& e : features.edge_points)
    if(owned[e.source])
      tile.edge_points.push_back(e);
  for(const Corner_point<GeomTraits>& c : features.corner_points)
    if(owned[c.source])
      tile.corner_points.push_back(c);
  return progress.report(1.);
}

} // namespace CGAL

#endif
