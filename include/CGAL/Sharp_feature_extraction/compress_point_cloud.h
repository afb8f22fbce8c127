// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_COMPRESS_POINT_CLOUD_H
#define CGAL_SHARP_FEATURE_EXTRACTION_COMPRESS_POINT_CLOUD_H

#include <CGAL/Sharp_feature_extraction/internal/height_image_coding_impl.h>
#include <CGAL/Sharp_feature_extraction/partition_into_height_fields.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// The default quantizer step, relative to the grid spacing: a hundredth of a cell, below the
/// resampling error of a curved surface on a grid of that spacing.
constexpr double default_step_per_grid_spacing = 0.01;

} // namespace internal
} // namespace Sharp_feature_extraction

/// \ingroup PkgSharpFeatureExtractionRef
/// Compresses a point cloud partitioned into height fields (the coder of Ochotta and Saupe
/// 2004, with JPEG 2000 in place of their shape-adaptive wavelet coder).
///
/// Each piece is resampled on a grid of side `grid_spacing` over its least-squares plane: a
/// cell holding a point (or surrounded by such cells) is in the piece's mask. Its point lies at
/// its centre, or, on the mask's boundary, a quarter cell towards the rest of the mask (where
/// the points of a cell that the piece's edge crosses lie on average; both sides derive it from
/// the mask), and takes the height there of the plane fitted to the points of the 3 x 3 cells
/// around it. The
/// images are packed into one atlas; the heights outside the masks are filled smoothly (a
/// mask-weighted pyramid), and the atlas is coded with JPEG 2000's irreversible 9/7 wavelet,
/// heights quantized with step `quantization_step` in every band. The masks are coded losslessly
/// (JPEG 2000, reversible), the frames with 16 bits per coordinate. `decompress_point_cloud()`
/// gives back one point per mask cell: about one per cell of the surface, not one per input
/// point. The bitstream starts with the magic number "SFEH" and a version.
///
/// Needs OpenJPEG (link with libopenjp2).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
///   (the spacing estimate only).
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
///
/// \param points the input points.
/// \param labels the piece of every point, e.g. from `partition_into_height_fields()` (with the
///   same `grid_spacing`); a piece that is not a height field is coded all the same, with a
///   larger error.
/// \param bytes receives the bitstream (cleared first); its size is the compressed size.
/// \param np optional named parameters among the ones listed below; a parameter of the
///   extraction or of the partition alone does not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is a CGAL `Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::grid_spacing}
///     \cgalParamDescription{side of a cell of the height images}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the sampling spacing: the mean distance from a point to its 6th nearest neighbour}
///     \cgalParamExtra{0 selects the default}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::quantization_step}
///     \cgalParamDescription{quantizer step of the heights (a distance): the larger, the smaller the bitstream}
///     \cgalParamType{`double`}
///     \cgalParamDefault{a hundredth of the grid spacing}
///     \cgalParamExtra{the heights of the atlas must span fewer than 65536 steps}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument if there are no points, a coordinate is not finite, `labels`
///   does not hold one label per point, or a parameter is out of range.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
void compress_point_cloud(const PointRange& points, const std::vector<std::size_t>& labels,
                          std::vector<unsigned char>& bytes, const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_no_extraction_parameters<NamedParameters>() &&
                  sfe::holds_none_of<NamedParameters, Sharp_feature_extraction::internal_np::height_field_angle_t,
                                     Sharp_feature_extraction::internal_np::initial_labels_t,
                                     CGAL::internal_np::callback_t>(),
                "compress_point_cloud: a parameter of another function");
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const sfe::Height_field_parameters p = sfe::read_height_field_parameters(np);
  std::vector<sfe::Vec3> read = sfe::read_points_with_map(points, np);
  if(read.empty())
    throw std::invalid_argument("compress_point_cloud: no points");
  if(labels.size() != read.size())
    throw std::invalid_argument("compress_point_cloud: labels must hold one label per point");
  double cell = p.grid_spacing;
  if(!(cell > 0))
  {
    sfe::Progress silent;
    sfe::Height_field_cloud cloud;
    sfe::build_height_field_cloud<ConcurrencyTag>(read, silent, cloud);
    cell = sfe::grid_spacing_of(p, cloud);
  }
  if(!(cell > 0))
    throw std::invalid_argument("compress_point_cloud: the points have no extent (all coincide)");
  const double step = choose_parameter(get_parameter(np, Sharp_feature_extraction::internal_np::quantization_step),
                                       sfe::default_step_per_grid_spacing * cell);
  if(!(step > 0) || !std::isfinite(step))
    throw std::invalid_argument("compress_point_cloud: quantization_step must be a positive distance");
  bytes.clear();
  sfe::encode_height_fields(read, sfe::group_by_label(read.size(), labels), cell, step, bytes);
}

} // namespace CGAL

#endif
