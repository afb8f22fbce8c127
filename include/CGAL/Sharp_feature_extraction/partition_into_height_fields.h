// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_PARTITION_INTO_HEIGHT_FIELDS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_PARTITION_INTO_HEIGHT_FIELDS_H

#include <CGAL/Sharp_feature_extraction/internal/Indexed_input.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/height_field_partition_impl.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// The default grid spacing, relative to the sampling spacing (mean distance to the 6th
/// nearest neighbour): a cell then holds about two points of a uniform sample, so that few
/// cells inside a piece are empty.
constexpr double grid_spacing_per_sampling_spacing = 1.0;
/// The default `height_field_angle`, in degrees: steeper normals stretch a grid cell over more
/// than twice its side on the surface.
constexpr double default_height_field_angle = 60;

/// The partition's parameters, read from named parameters.
struct Height_field_parameters
{
  double angle = default_height_field_angle;
  /// 0: `grid_spacing_per_sampling_spacing` times the sampling spacing.
  double grid_spacing = 0;
  std::vector<std::size_t> initial_labels;
};

template <typename NamedParameters>
Height_field_parameters read_height_field_parameters(const NamedParameters& np)
{
  using namespace parameter_reading;
  Height_field_parameters p;
  p.angle = choose_parameter(get_parameter(np, own_np::height_field_angle), p.angle);
  p.grid_spacing = choose_parameter(get_parameter(np, own_np::grid_spacing), p.grid_spacing);
  p.initial_labels = choose_parameter(get_parameter(np, own_np::initial_labels), p.initial_labels);
  require_angle(p.angle, "height_field_angle");
  require_distance(p.grid_spacing, "grid_spacing");
  return p;
}

/// The points of `points` through the `point_map` of `np`.
/// \throws std::invalid_argument if a coordinate is not finite.
template <typename PointRange, typename NamedParameters>
std::vector<Vec3> read_points_with_map(const PointRange& points, const NamedParameters& np)
{
  typedef typename CGAL::GetPointMap<PointRange, NamedParameters>::const_type PointMap;
  return read_input_points(points, CGAL::parameters::choose_parameter<PointMap>(
                                     CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map)));
}

/// Whether `NamedParameters` holds none of the parameters of the extraction's stages and scales,
/// which would have no effect on the height fields and their coding.
template <typename NamedParameters>
constexpr bool holds_no_extraction_parameters()
{
  return holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS, CGAL::internal_np::degree_fitting_t,
                       CGAL::internal_np::threshold_distance_t, CGAL::internal_np::sharpness_angle_t,
                       CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                       CGAL::internal_np::number_of_relaxation_steps_t>();
}

/// The grid spacing of `p` for `cloud`.
inline double grid_spacing_of(const Height_field_parameters& p, const Height_field_cloud& cloud)
{
  return p.grid_spacing > 0 ? p.grid_spacing : grid_spacing_per_sampling_spacing * cloud.spacing;
}

} // namespace internal
} // namespace Sharp_feature_extraction

/// \ingroup PkgSharpFeatureExtractionRef
/// Partitions a point cloud into height fields: the split-merge partition of the point-cloud
/// coder of Ochotta and Saupe (2004), on which `compress_point_cloud()` codes each piece as a
/// height image.
///
/// A piece is a height field within the bound when the normal of each of its points (the
/// plane of its 12 nearest points) makes at most `height_field_angle` with the normal of the
/// piece's least-squares plane, and no two of its points over one cell of a grid of side
/// `grid_spacing` on that plane differ in height by more than the angle allows (two layers,
/// e.g. both sides of a thin plate). The split starts from the connected components (along
/// the links of every point to its 6 nearest) of the whole cloud, or of each set of points
/// sharing an initial label, and splits a piece that is not a height field in two (at its
/// plane when it has two layers, across its longest axis otherwise) until each is one, or
/// holds fewer than 12 points. The merge then repeatedly joins two linked pieces whose union
/// is a height field within the bound, the most promising first (the largest smallest cosine
/// between the union's plane normal and the normals, estimated from bins of 15 degrees), while
/// one is; it may join pieces of different initial labels. Last, a piece of fewer than 12
/// points joins the piece it shares most links with, height field or not (a frame would cost
/// more than its points).
///
/// With initial labels from `segment_into_patches()` (the guided partition), the pieces of
/// the split never cross a feature curve.
///
/// The result depends on the points and parameters only: the same whatever the number of
/// threads.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`.
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
///
/// \param points the input points.
/// \param labels receives the piece of every input point, in input order; pieces are numbered
///   from 0 in the order of their first point.
/// \param np optional named parameters among the ones listed below; a parameter of the
///   extraction or of `compress_point_cloud()` alone does not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is a CGAL `Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::height_field_angle}
///     \cgalParamDescription{largest angle, in degrees, between a point's normal and its piece's plane normal}
///     \cgalParamType{`double`, in (0, 90)}
///     \cgalParamDefault{60}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::grid_spacing}
///     \cgalParamDescription{side of a cell of the grid over which a piece is a height field (the
///       same as given to `compress_point_cloud()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the sampling spacing: the mean distance from a point to its 6th nearest neighbour}
///     \cgalParamExtra{0 selects the default}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::initial_labels}
///     \cgalParamDescription{a label per input point: the split starts from the sets of points sharing one}
///     \cgalParamType{`std::vector<std::size_t>`, as many as points}
///     \cgalParamDefault{none: the split starts from the whole cloud}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{receives the progress in [0,1]; returning `false` stops the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the number of pieces, 0 if the callback interrupted the computation (`labels` is
///   then empty).
/// \throws std::invalid_argument if a coordinate is not finite, a parameter is out of range, or
///   `initial_labels` does not hold one label per point.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::size_t partition_into_height_fields(const PointRange& points, std::vector<std::size_t>& labels,
                                         const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_no_extraction_parameters<NamedParameters>() &&
                  sfe::holds_none_of<NamedParameters, Sharp_feature_extraction::internal_np::quantization_step_t>(),
                "partition_into_height_fields: a parameter of another function");
  const sfe::Height_field_parameters p = sfe::read_height_field_parameters(np);
  labels.clear();
  sfe::Progress progress(sfe::read_callback(np));
  sfe::Height_field_cloud cloud;
  sfe::Progress indexing = progress.sub(0, 0.3);
  if(!sfe::build_height_field_cloud<ConcurrencyTag>(sfe::read_points_with_map(points, np), indexing, cloud))
    return 0;
  if(!p.initial_labels.empty() && p.initial_labels.size() != cloud.size())
    throw std::invalid_argument("partition_into_height_fields: initial_labels must hold one label per point");
  const sfe::Height_field_bound bound(p.angle, sfe::grid_spacing_of(p, cloud));
  std::vector<std::vector<std::size_t>> pieces =
    sfe::split_into_height_fields(cloud, sfe::group_by_label(cloud.size(), p.initial_labels), bound);
  sfe::Progress merging = progress.sub(0.5, 1);
  if(!merging.report(0))
    return 0;
  pieces = sfe::merge_height_fields(cloud, std::move(pieces), bound, merging);
  if(!merging.report(1))
    return 0;
  labels = sfe::piece_labels(cloud.size(), pieces);
  return pieces.size();
}

} // namespace CGAL

#endif
