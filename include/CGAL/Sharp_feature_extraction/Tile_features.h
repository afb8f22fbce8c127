// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_TILE_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_TILE_FEATURES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Bbox_3.h>

#include <cstddef>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// What `extract_tile_features()` computes on one tile of a cloud and
/// `stitch_tile_features()` joins: the feature points (stages 1 to 3) that the tile's core box
/// owns.
///
/// A feature point belongs to the tile whose core box holds its source, the input point it
/// was projected from; the boxes are half-open ([min, max) on each axis), so tiles that share
/// faces own every input point, hence every feature point, exactly once. Given a halo of
/// `tile_halo_width()` around the core, these points are those the whole cloud gives with the
/// same scales and threshold (but for isolated edge points near the faces: see
/// `tile_halo_width()`).
template <typename GeomTraits>
struct Tile_features
{
  /// The core box of the tile.
  CGAL::Bbox_3 core;
  /// The smoothed edge points (stage 3) whose source lies in `core`. `source` is the index of
  /// that point in the tile's point range.
  std::vector<Edge_point<GeomTraits>> edge_points;
  /// The corner points (stage 2, grouped) whose source lies in `core`; `source` as above.
  std::vector<Corner_point<GeomTraits>> corner_points;
  /// The scales the tile was extracted with (every tile of a cloud must share them).
  Sharp_feature_scales<typename GeomTraits::FT> scales;
  /// The number of input points of the tile's range that lie in `core`.
  std::size_t number_of_core_points = 0;
  /// The number of those that are candidates (stage 1).
  std::size_t number_of_candidates = 0;
  /// Wall-clock time of the context and of stages 1 to 3 on the tile (core and halo).
  Sharp_feature_timings timings;
};

} // namespace CGAL

#endif
