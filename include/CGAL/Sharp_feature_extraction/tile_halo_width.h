// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_TILE_HALO_WIDTH_H
#define CGAL_SHARP_FEATURE_EXTRACTION_TILE_HALO_WIDTH_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/tiling_impl.h>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// The width of the halo that `extract_tile_features()` needs around a tile's core box: the
/// tile's points are those within this distance of the core box (along each axis), so that the
/// feature points the core owns are those the whole cloud gives.
///
/// With s the spacing, r1 the candidate radius, r2 the corner radius (the median radius of a
/// stage-2 neighbourhood), g the growth radius and n the number of smoothing passes, all from
/// `scales`:
///
///   halo = c + 2 (r1 + r2) + r2 + n x 2.2 g,
///
/// where c = 1.5 sqrt(3) s is the diagonal of the cells whose candidates share their surfaces in
/// stage 2 (0 when the noise exceeds 5% of the spacing: the candidates then search their own).
/// The terms: an edge point lies within its candidate's stage-1 neighbourhood, the surfaces it
/// is projected on come from a stage-2 neighbourhood (both counted twice their median radius,
/// for thinner sampling), corner points are grouped over r2, and each smoothing pass reaches the
/// 60 nearest edge points, within 1.9 to 2.7 g for 99% of the edge points of CGAL's fandisk,
/// anchor and pinion. Isolated edge points (far from a crease) reach farther: near a tile face,
/// such a point may be smoothed with other neighbours than in the whole cloud (6 of 15,697
/// edge points, by 4% of the spacing, on fandisk with 0.2% noise cut into 27 tiles).
///
/// \param scales the scales of the cloud (see `estimate_sharp_feature_scales_for_tiles()`).
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{number of smoothing passes (stage 3) the tiles will run}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the halo width, a distance (0 for zero scales).
/// \throws std::invalid_argument if a scale is negative or not finite, or the sampled fraction
///   is not in (0, 1].
template <typename FT, typename NamedParameters = parameters::Default_named_parameters>
FT tile_halo_width(const Sharp_feature_scales<FT>& scales, const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_only_smoothing_parameters<NamedParameters>(),
                "tile_halo_width: only number_of_iterations changes the halo");
  const sfe::Scales working = sfe::convert_scales<double>(scales);
  sfe::require_valid_scales(working);
  return FT(sfe::halo_width(working, sfe::read_smoothing_parameters(np).passes));
}

} // namespace CGAL

#endif
