// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_DECOMPRESS_POINT_CLOUD_H
#define CGAL_SHARP_FEATURE_EXTRACTION_DECOMPRESS_POINT_CLOUD_H

#include <CGAL/Sharp_feature_extraction/internal/height_image_coding_impl.h>

#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Decodes a bitstream of `compress_point_cloud()` into points: one per cell of the height
/// images' masks, piece after piece.
///
/// Needs OpenJPEG (link with libopenjp2).
///
/// \tparam Point_3 a point type of a CGAL kernel.
/// \param bytes the whole bitstream, nothing before or after it.
/// \param points receives the decoded points (cleared first).
/// \throws std::invalid_argument if `bytes` is not such a bitstream: another file (wrong magic
///   number), another version, truncated, followed by other bytes, or corrupt.
template <typename Point_3>
void decompress_point_cloud(const std::vector<unsigned char>& bytes, std::vector<Point_3>& points)
{
  const std::vector<Sharp_feature_extraction::internal::Vec3> decoded =
    Sharp_feature_extraction::internal::decode_height_fields(bytes);
  points.clear();
  points.reserve(decoded.size());
  for(const auto& p : decoded)
    points.emplace_back(p.x(), p.y(), p.z());
}

} // namespace CGAL

#endif
