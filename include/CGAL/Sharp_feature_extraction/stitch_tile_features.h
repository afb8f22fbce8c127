// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_STITCH_TILE_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_STITCH_TILE_FEATURES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/Tile_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/completion_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/polyline_growing_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/tiling_impl.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace CGAL {

namespace Sharp_feature_extraction {
namespace internal {

template <typename FT>
bool same_scales(const Sharp_feature_scales<FT>& a, const Sharp_feature_scales<FT>& b)
{
  return a.spacing == b.spacing && a.noise == b.noise && a.candidate_neighbors == b.candidate_neighbors
    && a.candidate_radius == b.candidate_radius && a.rmls_neighbors == b.rmls_neighbors
    && a.residual_threshold == b.residual_threshold && a.rmls_tolerance == b.rmls_tolerance
    && a.corner_radius == b.corner_radius && a.growth_radius == b.growth_radius
    && a.completion_distance == b.completion_distance && a.sampled_fraction == b.sampled_fraction
    && a.search_fraction == b.search_fraction;
}

/// The tiles in the order of their core boxes, checked: one set of scales, disjoint cores.
template <typename GT, typename TileRange>
std::vector<const Tile_features<GT>*> tiles_in_box_order(const TileRange& tiles)
{
  std::vector<const Tile_features<GT>*> sorted;
  for(const Tile_features<GT>& t : tiles)
    sorted.push_back(&t);
  std::sort(sorted.begin(), sorted.end(),
            [](const Tile_features<GT>* a, const Tile_features<GT>* b) { return box_before(a->core, b->core); });
  for(std::size_t i = 0; i < sorted.size(); ++i)
  {
    if(!same_scales(sorted[i]->scales, sorted.front()->scales))
      throw std::invalid_argument("stitch_tile_features: the tiles were extracted with different scales");
    for(std::size_t j = i + 1; j < sorted.size() && sorted[j]->core.xmin() < sorted[i]->core.xmax(); ++j)
      if(interiors_overlap(sorted[i]->core, sorted[j]->core))
        throw std::invalid_argument("stitch_tile_features: the core boxes of two tiles overlap");
  }
  return sorted;
}

} // namespace internal
} // namespace Sharp_feature_extraction

/// \ingroup PkgSharpFeatureExtractionRef
/// Joins the feature points of the tiles of a cloud (see `extract_tile_features()`) and runs
/// stages 4 and 5 (polyline growing and completion) on them: the last of the three pieces of a
/// distributed extraction.
///
/// The tiles' feature points, which their disjoint core boxes own once each, form the feature
/// point set of the whole cloud; they are put in an order of their own (by position), whatever
/// the order of `tiles`, and the curves are grown through all of them at once. So there is
/// nothing to join at the faces of the tiles: a curve crossing a face is one curve, corners are
/// shared by their curves and closed curves are closed, as in `extract_sharp_features()`. The
/// result is the same for any order of `tiles`. Only the feature points are held (about the
/// candidates' share of the cloud, a few percent), never the cloud.
///
/// \tparam TileRange a model of `ConstRange` whose value type is `Tile_features<GeomTraits>`.
/// \param tiles the tiles of the cloud, extracted with the same scales.
/// \param result receives the curves: `network` and `grown`, and `smoothed`, the tiles' feature
///   points joined (their `source` is the index in their tile's point range). `candidates` and
///   `projected` are left empty (their scales set); `timings` adds up the tiles' times.
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{maximum_angle}
///     \cgalParamDescription{half-angle, in degrees, of the completion search cone at a free end}
///     \cgalParamType{`double`}
///     \cgalParamDefault{30}
///     \cgalParamExtra{read by stage 5; must be in (0, 90)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_relaxation_steps}
///     \cgalParamDescription{number of Laplacian smoothing passes over the completed curves}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{read by stage 5}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of stage 4 done (from 0
///       to 1; stage 5, short, is not interrupted); when it returns `false` the computation stops
///       and the function returns `false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// A parameter of stages 1 to 3, or a scale (fixed by the tiles), does not compile.
/// \returns `false` if the callback interrupted the computation (the result is then partial).
/// \throws std::invalid_argument if the tiles have different scales or overlapping core boxes,
///   a parameter is out of range, or a scale of the tiles is negative or not finite.
template <typename TileRange, typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
bool stitch_tile_features(const TileRange& tiles, Sharp_features<GeomTraits>& result,
                          const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS, CGAL::internal_np::degree_fitting_t,
                                   CGAL::internal_np::threshold_distance_t, CGAL::internal_np::sharpness_angle_t,
                                   CGAL::internal_np::number_of_iterations_t>(),
                "stitch_tile_features: a parameter of stages 1 to 3 (give it to extract_tile_features), or a scale");
  const sfe::Completion_parameters completion = sfe::read_completion_parameters(np);
  result = Sharp_features<GeomTraits>();
  const std::vector<const Tile_features<GeomTraits>*> sorted = sfe::tiles_in_box_order<GeomTraits>(tiles);
  Feature_point_set<GeomTraits>& features = result.smoothed;
  for(const Tile_features<GeomTraits>* t : sorted)
  {
    features.edge_points.insert(features.edge_points.end(), t->edge_points.begin(), t->edge_points.end());
    features.corner_points.insert(features.corner_points.end(), t->corner_points.begin(), t->corner_points.end());
    result.timings.context += t->timings.context;
    result.timings.candidates += t->timings.candidates;
    result.timings.projection += t->timings.projection;
    result.timings.smoothing += t->timings.smoothing;
  }
  if(!sorted.empty())
    features.scales = sorted.front()->scales;
  result.candidates.scales = result.projected.scales = features.scales;
  std::sort(features.edge_points.begin(), features.edge_points.end(), sfe::edge_point_before<GeomTraits>);
  std::sort(features.corner_points.begin(), features.corner_points.end(), sfe::corner_point_before<GeomTraits>);

  CGAL::Real_timer timer;
  timer.start();
  sfe::Progress progress(sfe::read_callback(np));
  if(!sfe::grow_feature_curve_network(features, result.grown, parameters::default_values(),
                                      [progress](double f) mutable { return progress.report(f); }))
    return false;
  result.timings.growing = timer.time();
  timer.reset();
  result.network = result.grown;
  sfe::complete_feature_curve_network(result.network, parameters::default_values(), completion);
  result.timings.completion = timer.time();
  return progress.report(1.);
}

} // namespace CGAL

#endif
