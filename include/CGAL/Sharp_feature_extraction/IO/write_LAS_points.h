// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_LAS_POINTS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_LAS_POINTS_H

#include <CGAL/Sharp_feature_extraction/IO/read_LAS_points.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

inline void put_little_endian(std::vector<unsigned char>& bytes, std::size_t at, std::uint64_t v, std::size_t size)
{
  for(std::size_t i = 0; i < size; ++i, v >>= 8)
    bytes[at + i] = static_cast<unsigned char>(v & 0xFF);
}

inline void put_double(std::vector<unsigned char>& bytes, std::size_t at, double v)
{
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  put_little_endian(bytes, at, u, 8);
}

} // namespace internal
} // namespace Sharp_feature_extraction

namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// How `write_LAS_points()` lays out a LAS file.
struct LAS_write_options
{
  /// Minor version, 2 to 4 (LAS 1.2 to 1.4).
  unsigned version_minor = 2;
  /// Point data record format, 0 to 10 (4 and 5 need 1.3, 6 to 10 need 1.4). Fields other than
  /// the position are written as zeros.
  unsigned point_format = 0;
  /// Bytes appended to every record after its format's fields (LAS "extra bytes").
  std::size_t extra_bytes = 0;
  /// Bytes of variable length records between the header and the points (one record of
  /// that size in all, header included; 0 for none, otherwise at least the 54-byte VLR header).
  std::size_t vlr_bytes = 0;
};

/// \ingroup PkgSharpFeatureExtractionIORef
/// Writes the positions of `points` as an uncompressed LAS file that `LAS_point_reader` reads.
/// Positions are stored as 32-bit integers: the offset is the centre of the bounding box and
/// the scale the same on all axes, so that the half extent maps to 2^30; a coordinate comes
/// back within half a scale step of the one written (about 1e-9 of the extent).
/// \tparam PointRange a range of points with `x()`, `y()` and `z()`.
/// \param os the stream, opened with `std::ios::binary`.
/// \param points the points, written in their order.
/// \param options the version, point format and sizes of the file.
/// \throws std::invalid_argument if the options are not a valid layout (version, format,
///   record or VLR size) or a coordinate is not finite.
/// \returns `true` if the stream is good after writing.
template <typename PointRange>
bool write_LAS_points(std::ostream& os, const PointRange& points, const LAS_write_options& options = {})
{
  namespace L = Sharp_feature_extraction::internal::LAS_layout;
  namespace sfe = Sharp_feature_extraction::internal;
  // Integers used for the half extent: 2^30 leaves a factor 2 of margin to INT32_MAX for rounding.
  constexpr double integer_half_range = 1073741824.0;
  // Size of the header of one variable length record (user id, record id, length, description).
  constexpr std::size_t vlr_header_bytes = 54;
  constexpr std::size_t record_length_limit = 0xFFFF;

  if(options.version_minor < L::lowest_minor_version || options.version_minor > L::highest_minor_version)
    throw std::invalid_argument("write_LAS_points: the minor version must be 2, 3 or 4");
  if(options.point_format > L::highest_point_format ||
     options.version_minor < L::first_minor_version[options.point_format])
    throw std::invalid_argument("write_LAS_points: point format " + std::to_string(options.point_format) +
                                " does not exist in LAS 1." + std::to_string(options.version_minor));
  const std::size_t record_length = L::record_size[options.point_format] + options.extra_bytes;
  if(record_length > record_length_limit)
    throw std::invalid_argument("write_LAS_points: a record cannot exceed 65535 bytes");
  if(options.vlr_bytes != 0 && options.vlr_bytes < vlr_header_bytes)
    throw std::invalid_argument("write_LAS_points: a variable length record takes at least 54 bytes");

  std::array<double, 3> low{0, 0, 0}, high{0, 0, 0};
  std::size_t count = 0;
  for(const auto& p : points)
  {
    const double xyz[3] = {double(p.x()), double(p.y()), double(p.z())};
    for(std::size_t axis = 0; axis < 3; ++axis)
    {
      if(!std::isfinite(xyz[axis]))
        throw std::invalid_argument("write_LAS_points: point " + std::to_string(count) + " is not finite");
      low[axis] = count == 0 ? xyz[axis] : (std::min)(low[axis], xyz[axis]);
      high[axis] = count == 0 ? xyz[axis] : (std::max)(high[axis], xyz[axis]);
    }
    ++count;
  }
  std::array<double, 3> offset{};
  double half_extent = 0;
  for(std::size_t axis = 0; axis < 3; ++axis)
  {
    offset[axis] = low[axis] / 2 + high[axis] / 2; // halves first: no overflow near DBL_MAX
    half_extent = (std::max)(half_extent, high[axis] / 2 - low[axis] / 2);
  }
  // A cloud of one position: any scale stores it exactly (every integer is 0).
  const double scale = half_extent > 0 ? half_extent / integer_half_range : 1;

  const std::size_t minor_index = options.version_minor - L::lowest_minor_version;
  const std::size_t header_size = L::header_size[minor_index];
  std::vector<unsigned char> header(header_size + options.vlr_bytes, 0);
  std::memcpy(header.data(), L::signature, sizeof L::signature);
  header[L::version_major_at] = 1;
  header[L::version_minor_at] = static_cast<unsigned char>(options.version_minor);
  sfe::put_little_endian(header, L::header_size_at, header_size, 2);
  sfe::put_little_endian(header, L::offset_to_points_at, header.size(), 4);
  sfe::put_little_endian(header, L::vlr_count_at, options.vlr_bytes == 0 ? 0 : 1, 4);
  header[L::point_format_at] = static_cast<unsigned char>(options.point_format);
  sfe::put_little_endian(header, L::record_length_at, record_length, 2);
  // The legacy 32-bit count must be 0 for formats 6 to 10 and for counts beyond 32 bits.
  const bool legacy_count = options.point_format < 6 && count <= std::numeric_limits<std::uint32_t>::max();
  sfe::put_little_endian(header, L::legacy_point_count_at, legacy_count ? count : 0, 4);
  if(options.version_minor >= 4)
    sfe::put_little_endian(header, L::point_count_at, count, 8);
  for(std::size_t axis = 0; axis < 3; ++axis)
  {
    sfe::put_double(header, L::scale_at + 8 * axis, scale);
    sfe::put_double(header, L::offset_at + 8 * axis, offset[axis]);
    sfe::put_double(header, L::bounds_at + 16 * axis, high[axis]);
    sfe::put_double(header, L::bounds_at + 16 * axis + 8, low[axis]);
  }
  // The length of the record after its header, at byte 20 of the VLR header.
  constexpr std::size_t vlr_length_at = 20;
  if(options.vlr_bytes != 0)
    sfe::put_little_endian(header, header_size + vlr_length_at, options.vlr_bytes - vlr_header_bytes, 2);
  os.write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));

  std::vector<unsigned char> record(record_length, 0);
  for(const auto& p : points)
  {
    const double xyz[3] = {double(p.x()), double(p.y()), double(p.z())};
    for(std::size_t axis = 0; axis < 3; ++axis)
    {
      const std::int32_t integer = static_cast<std::int32_t>(std::lround((xyz[axis] - offset[axis]) / scale));
      std::uint32_t u;
      std::memcpy(&u, &integer, sizeof u);
      sfe::put_little_endian(record, L::coordinate_bytes * axis, u, L::coordinate_bytes);
    }
    os.write(reinterpret_cast<const char*>(record.data()), std::streamsize(record.size()));
  }
  return bool(os);
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, into the file `filename`.
/// \param filename the file, created or overwritten.
/// \param points the points, written in their order.
/// \param options the version, point format and sizes of the file.
/// \returns `false` if the file cannot be written.
template <typename PointRange>
bool write_LAS_points(const std::string& filename, const PointRange& points, const LAS_write_options& options = {})
{
  std::ofstream os(filename, std::ios::binary);
  return os && write_LAS_points(os, points, options);
}

} // namespace IO
} // namespace CGAL

#endif
