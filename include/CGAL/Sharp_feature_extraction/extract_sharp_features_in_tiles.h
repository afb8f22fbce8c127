// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_SHARP_FEATURES_IN_TILES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_SHARP_FEATURES_IN_TILES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/Tile_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/estimate_sharp_feature_scales_for_tiles.h>
#include <CGAL/Sharp_feature_extraction/extract_tile_features.h>
#include <CGAL/Sharp_feature_extraction/stitch_tile_features.h>
#include <CGAL/Sharp_feature_extraction/tile_halo_width.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/tiling_impl.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Real_timer.h>

#include <array>
#include <functional>
#include <stdexcept>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Extracts the sharp feature curves of a point cloud tile by tile, as workers that each hold
/// one tile would: the scales estimated once (`estimate_sharp_feature_scales_for_tiles()`),
/// stages 1 to 3 on every tile of a grid over the bounding box with a halo of
/// `tile_halo_width()` (`extract_tile_features()`, one tile at a time, so that only one tile is
/// indexed at once), and the tiles' feature points stitched into curves
/// (`stitch_tile_features()`).
///
/// The curves are those of `extract_sharp_features()` run with the same scales and threshold
/// (`threshold_distance` set to the `residual_threshold` of the tiled scales): the feature
/// points are the same, and the curves grown through all of them at once. With the default
/// threshold, the untiled run takes it from every point and this one from a subsample: the two
/// differ by the sampling error of a mean over 20,000 residuals.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`: the threads share each tile. The result does not depend
///   on the number of threads.
/// \param points the input points; no normals are needed.
/// \param result receives the curves (see `stitch_tile_features()`: `network`, `grown` and
///   `smoothed`, whose `source` here indexes `points`).
/// \param np optional named parameters: those of `extract_sharp_features()`, and:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::number_of_tiles}
///     \cgalParamDescription{the least number of tiles}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{8}
///     \cgalParamExtra{the bounding box is cut into a grid of at least that many cells, splitting
///       in turn the axis along which the cells are longest (8: 2 x 2 x 2 on a cube); must be at
///       least 1}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the `callback` interrupted the computation (the result is then partial).
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
template <typename ConcurrencyTag, typename PointRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
bool extract_sharp_features_in_tiles(const PointRange& points, Sharp_features<GeomTraits>& result,
                                     const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Const_point_map Point_map;
  typedef typename boost::property_traits<Point_map>::value_type Input_point;
  constexpr std::size_t default_number_of_tiles = 8;
  const std::size_t number_of_tiles = parameters::choose_parameter(
    parameters::get_parameter(np, Sharp_feature_extraction::internal_np::number_of_tiles), default_number_of_tiles);
  sfe::parameter_reading::require(number_of_tiles >= 1, "number_of_tiles must be at least 1");
  const sfe::Candidate_parameters candidate_parameters = sfe::read_candidate_parameters(np);
  const sfe::Projection_parameters projection_parameters = sfe::read_projection_parameters(np);
  const sfe::Smoothing_parameters smoothing_parameters = sfe::read_smoothing_parameters(np);
  const sfe::Completion_parameters completion_parameters = sfe::read_completion_parameters(np);
  sfe::Progress progress(sfe::read_callback(np));
  const auto progress_callback = [](sfe::Progress p) {
    return std::function<bool(double)>([p](double f) mutable { return p.report(f); });
  };

  CGAL::Real_timer timer;
  timer.start();
  const Sharp_feature_scales<typename GeomTraits::FT> scales =
    sfe::convert_scales<typename GeomTraits::FT>(sfe::scales_for_tiles<ConcurrencyTag>(points, np));
  const double scale_time = timer.time();
  if(!(scales.spacing > 0))
  {
    // Too few points: no features, as for `extract_sharp_features()`.
    result = Sharp_features<GeomTraits>();
    result.candidates.scales = result.projected.scales = result.smoothed.scales = result.grown.scales =
      result.network.scales = scales;
    return progress.report(1.);
  }
  const double halo = CGAL::to_double(tile_halo_width(scales, parameters::number_of_iterations(smoothing_parameters.passes)));
  const Point_map point_map = NP_helper::get_const_point_map(points, np);
  const auto coordinates = [&](const Input_point& p) {
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  CGAL::Bbox_3 box;
  for(const auto& item : points)
  {
    const std::array<double, 3> c = coordinates(get(point_map, item));
    box += CGAL::Bbox_3(c[0], c[1], c[2], c[0], c[1], c[2]);
  }
  const std::array<std::size_t, 3> counts = sfe::tile_grid(box, number_of_tiles);
  const std::size_t tile_count = counts[0] * counts[1] * counts[2];
  // Stages 1 to 3 are nearly all of the work (see `progress_end_of_stage`).
  const double tiles_share = sfe::progress_end_of_stage[2];

  std::vector<Tile_features<GeomTraits>> tiles(tile_count);
  std::vector<Input_point> tile_points;
  std::vector<std::size_t> tile_indices;
  for(std::size_t t = 0; t < tile_count; ++t)
  {
    const std::array<std::size_t, 3> cell = {{t % counts[0], (t / counts[0]) % counts[1], t / (counts[0] * counts[1])}};
    const CGAL::Bbox_3 core = sfe::tile_core(box, counts, cell);
    const CGAL::Bbox_3 extended(core.xmin() - halo, core.ymin() - halo, core.zmin() - halo,
                                core.xmax() + halo, core.ymax() + halo, core.zmax() + halo);
    tile_points.clear();
    tile_indices.clear();
    std::size_t i = 0;
    for(const auto& item : points)
    {
      const Input_point& p = get(point_map, item);
      const std::array<double, 3> c = coordinates(p);
      if(sfe::in_core(extended, c[0], c[1], c[2]))
      {
        tile_points.push_back(p);
        tile_indices.push_back(i);
      }
      ++i;
    }
    const sfe::Progress tile_progress = progress.sub(tiles_share * double(t) / double(tile_count),
                                                     tiles_share * double(t + 1) / double(tile_count));
    if(!extract_tile_features<ConcurrencyTag>(tile_points, core, scales, tiles[t],
         parameters::degree_fitting(candidate_parameters.degree_fitting)
           .sharpness_angle(projection_parameters.sharpness_angle)
           .number_of_iterations(smoothing_parameters.passes)
           .callback(progress_callback(tile_progress))))
      return false;
    for(Edge_point<GeomTraits>& e : tiles[t].edge_points)
      e.source = tile_indices[e.source];
    for(Corner_point<GeomTraits>& c : tiles[t].corner_points)
      c.source = tile_indices[c.source];
  }
  if(!stitch_tile_features(tiles, result,
                           parameters::maximum_angle(completion_parameters.aperture)
                             .number_of_relaxation_steps(completion_parameters.laplacian_passes)
                             .callback(progress_callback(progress.sub(tiles_share, 1.)))))
    return false;
  result.timings.context += scale_time;
  return progress.report(1.);
}

} // namespace CGAL

#endif
