// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_READ_LAS_POINTS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_READ_LAS_POINTS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

// The layout of LAS 1.2 to 1.4 (ASPRS LAS Specification 1.4 R15), as far as positions go.
namespace LAS_layout {
constexpr char signature[4] = {'L', 'A', 'S', 'F'};
constexpr unsigned lowest_minor_version = 2;
constexpr unsigned highest_minor_version = 4;
// Size of the public header block of versions 1.2, 1.3 and 1.4; a header may be longer.
constexpr std::size_t header_size[] = {227, 235, 375};
// Byte offsets of the fields of the public header block that locate and decode the points.
constexpr std::size_t version_major_at = 24, version_minor_at = 25, header_size_at = 94, offset_to_points_at = 96, vlr_count_at = 100,
                      point_format_at = 104, record_length_at = 105, legacy_point_count_at = 107, scale_at = 131,
                      offset_at = 155, bounds_at = 179, point_count_at = 247;
// Point data record formats 0 to 10: their smallest record length (a record may carry extra
// bytes after it) and the first minor version that defines them.
constexpr unsigned highest_point_format = 10;
constexpr std::size_t record_size[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
constexpr unsigned first_minor_version[] = {2, 2, 2, 2, 3, 3, 4, 4, 4, 4, 4};
// LAZ (LASzip) files set the two high bits of the point format: the records are compressed.
constexpr unsigned compressed_format_bits = 0xC0;
// Every record starts with X, Y and Z as little-endian 32-bit integers.
constexpr std::size_t coordinate_bytes = 4;
} // namespace LAS_layout

inline std::uint64_t little_endian_unsigned(const unsigned char* bytes, std::size_t size)
{
  std::uint64_t v = 0;
  for(std::size_t i = size; i-- > 0;)
    v = (v << 8) | bytes[i];
  return v;
}

inline std::int32_t little_endian_int32(const unsigned char* bytes)
{
  const std::uint32_t u = std::uint32_t(little_endian_unsigned(bytes, 4));
  std::int32_t v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

inline double little_endian_double(const unsigned char* bytes)
{
  const std::uint64_t u = little_endian_unsigned(bytes, 8);
  double v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

} // namespace internal
} // namespace Sharp_feature_extraction

namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// Thrown by `LAS_point_reader` on a file it cannot read: not LAS, a version other than 1.2 to
/// 1.4, compressed (LAZ), an inconsistent header, a truncated file or a read error. `what()` is
/// one line saying what is wrong.
class LAS_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// \ingroup PkgSharpFeatureExtractionIORef
/// What the public header block of a LAS file says about its points.
struct LAS_header
{
  /// Minor version: 2, 3 or 4 (the major version is 1).
  unsigned version_minor = 0;
  /// Point data record format, 0 to 10.
  unsigned point_format = 0;
  /// Bytes per point record: at least the format's size, extra bytes after it are skipped.
  std::size_t record_length = 0;
  /// Number of point records (from the 64-bit count of LAS 1.4 when it is set, otherwise from
  /// the legacy 32-bit count).
  std::uint64_t point_count = 0;
  /// Byte offset of the first point record from the start of the file.
  std::uint64_t offset_to_points = 0;
  /// A coordinate is `integer * scale + offset`, per axis x, y, z.
  std::array<double, 3> scale{};
  /// See `scale`.
  std::array<double, 3> offset{};
  /// Lower corner of the bounding box as the header states it (not checked against the points).
  std::array<double, 3> min{};
  /// Upper corner of the bounding box as the header states it.
  std::array<double, 3> max{};
};

/// \ingroup PkgSharpFeatureExtractionIORef
/// Reads the point positions of an uncompressed LAS 1.2, 1.3 or 1.4 stream, point record
/// formats 0 to 10, a bounded number of points at a time: memory does not grow with the file.
/// The scale and offset of the header are applied. Variable length records are skipped; a
/// record may be longer than its format (extra bytes), the rest of it is skipped.
///
/// The constructor reads the header and leaves the stream at the first point record; open a
/// file with `std::ios::binary`. `seek()` needs a seekable stream, reading does not.
class LAS_point_reader
{
public:
  /// Reads and checks the header of the LAS stream `is`, which must start at the beginning of
  /// the file and outlive the reader.
  /// \throws LAS_error if the stream is not uncompressed LAS 1.2 to 1.4 with a consistent header
  ///   (signature, version, header size, point format and record length, finite non-zero scales,
  ///   finite offsets) or ends within the header.
  explicit LAS_point_reader(std::istream& is) : is_(is)
  {
    namespace L = Sharp_feature_extraction::internal::LAS_layout;
    unsigned char bytes[L::header_size[2]];
    read_bytes(bytes, L::header_size[0], "the file ends within the LAS header");
    if(std::memcmp(bytes, L::signature, sizeof L::signature) != 0)
      throw LAS_error("not a LAS file (it does not start with 'LASF')");
    const unsigned major = bytes[L::version_major_at], minor = bytes[L::version_minor_at];
    if(major != 1 || minor < L::lowest_minor_version || minor > L::highest_minor_version)
      throw LAS_error("LAS version " + std::to_string(major) + "." + std::to_string(minor) +
                      " is not supported (1.2 to 1.4 are)");
    header_.version_minor = minor;
    const std::size_t minimal_header = L::header_size[minor - L::lowest_minor_version];
    read_bytes(bytes + L::header_size[0], minimal_header - L::header_size[0], "the file ends within the LAS header");
    const std::size_t header_size = std::size_t(field(bytes, L::header_size_at, 2));
    if(header_size < minimal_header)
      throw LAS_error("the LAS header size " + std::to_string(header_size) + " is smaller than the " +
                      std::to_string(minimal_header) + " bytes of version 1." + std::to_string(minor));
    header_.offset_to_points = field(bytes, L::offset_to_points_at, 4);
    if(header_.offset_to_points < header_size)
      throw LAS_error("the point records start at byte " + std::to_string(header_.offset_to_points) +
                      ", within the header of " + std::to_string(header_size) + " bytes");
    read_point_format(bytes[L::point_format_at], std::size_t(field(bytes, L::record_length_at, 2)));
    header_.point_count = field(bytes, L::legacy_point_count_at, 4);
    if(minor >= 4 && field(bytes, L::point_count_at, 8) != 0)
      header_.point_count = field(bytes, L::point_count_at, 8);
    read_transform(bytes);
    skip_to(header_.offset_to_points, "the file ends before its point records");
  }

  /// The header of the stream.
  const LAS_header& header() const { return header_; }

  /// Index of the next point to read (the number read so far, unless `seek()` moved it).
  std::uint64_t position() const { return next_point_; }

  /// Reads the next points, at most `max_points`, and appends their coordinates to `xyz`
  /// (three doubles per point: x, y, z). Returns how many it read: fewer than `max_points`
  /// only at the end of the points, 0 there.
  /// \throws LAS_error if the stream ends before the number of points of the header, on a read
  ///   error, or if a coordinate is not finite (a scale large enough to overflow).
  std::size_t read(std::size_t max_points, std::vector<double>& xyz)
  {
    namespace L = Sharp_feature_extraction::internal::LAS_layout;
    const std::size_t count = std::size_t(std::min<std::uint64_t>(max_points, header_.point_count - next_point_));
    const std::size_t first_value = xyz.size();
    record_.resize(header_.record_length);
    for(std::size_t i = 0; i < count; ++i)
    {
      if(!is_.read(reinterpret_cast<char*>(record_.data()), std::streamsize(record_.size())))
      {
        xyz.resize(first_value);
        throw LAS_error(is_.bad() ? std::string("read error")
                                  : "the file ends after " + std::to_string(next_point_) + " of the " +
                                      std::to_string(header_.point_count) + " points its header announces");
      }
      for(std::size_t axis = 0; axis < 3; ++axis)
      {
        const std::int32_t integer =
          Sharp_feature_extraction::internal::little_endian_int32(record_.data() + L::coordinate_bytes * axis);
        const double v = double(integer) * header_.scale[axis] + header_.offset[axis];
        if(!std::isfinite(v))
        {
          xyz.resize(first_value);
          throw LAS_error("point " + std::to_string(next_point_) + ": non-finite coordinate");
        }
        xyz.push_back(v);
      }
      ++next_point_;
    }
    return count;
  }

  /// Moves to the point of index `index` (at most the point count), so that a file can be read
  /// by several processes, each its own range of points.
  /// \throws LAS_error if the stream cannot seek there.
  void seek(std::uint64_t index)
  {
    if(index > header_.point_count)
      throw LAS_error("cannot seek to point " + std::to_string(index) + " of " +
                      std::to_string(header_.point_count));
    const std::uint64_t farthest = std::uint64_t((std::numeric_limits<std::streamoff>::max)());
    is_.clear();
    if(index > (farthest - header_.offset_to_points) / header_.record_length ||
       !is_.seekg(std::streamoff(header_.offset_to_points + index * header_.record_length)))
      throw LAS_error("cannot seek to point " + std::to_string(index) + " (is the stream a file?)");
    next_point_ = index;
  }

private:
  static std::uint64_t field(const unsigned char* bytes, std::size_t at, std::size_t size)
  {
    return Sharp_feature_extraction::internal::little_endian_unsigned(bytes + at, size);
  }

  void read_bytes(unsigned char* bytes, std::size_t size, const char* at_end)
  {
    if(!is_.read(reinterpret_cast<char*>(bytes), std::streamsize(size)))
      throw LAS_error(is_.bad() ? "read error" : at_end);
    consumed_ += size;
  }

  // Skips the variable length records between the header and the points.
  void skip_to(std::uint64_t offset, const char* at_end)
  {
    const std::uint64_t gap = offset - consumed_;
    if(gap > 0 && (!is_.ignore(std::streamsize(gap)) || std::uint64_t(is_.gcount()) != gap))
      throw LAS_error(is_.bad() ? "read error" : at_end);
    consumed_ = offset;
  }

  void read_point_format(unsigned format_byte, std::size_t record_length)
  {
    namespace L = Sharp_feature_extraction::internal::LAS_layout;
    if((format_byte & L::compressed_format_bits) != 0)
      throw LAS_error("compressed LAS (LAZ) is not supported: decompress it first (for example with laszip)");
    if(format_byte > L::highest_point_format)
      throw LAS_error("unknown LAS point format " + std::to_string(format_byte) + " (0 to 10 are defined)");
    if(header_.version_minor < L::first_minor_version[format_byte])
      throw LAS_error("LAS point format " + std::to_string(format_byte) + " does not exist in version 1." +
                      std::to_string(header_.version_minor));
    if(record_length < L::record_size[format_byte])
      throw LAS_error("the LAS record length " + std::to_string(record_length) + " is shorter than the " +
                      std::to_string(L::record_size[format_byte]) + " bytes of point format " +
                      std::to_string(format_byte));
    header_.point_format = format_byte;
    header_.record_length = record_length;
  }

  void read_transform(const unsigned char* bytes)
  {
    namespace L = Sharp_feature_extraction::internal::LAS_layout;
    const char* const axes = "xyz";
    for(std::size_t axis = 0; axis < 3; ++axis)
    {
      header_.scale[axis] = Sharp_feature_extraction::internal::little_endian_double(bytes + L::scale_at + 8 * axis);
      header_.offset[axis] = Sharp_feature_extraction::internal::little_endian_double(bytes + L::offset_at + 8 * axis);
      // The bounds are stored max x, min x, max y, min y, max z, min z.
      header_.max[axis] = Sharp_feature_extraction::internal::little_endian_double(bytes + L::bounds_at + 16 * axis);
      header_.min[axis] = Sharp_feature_extraction::internal::little_endian_double(bytes + L::bounds_at + 16 * axis + 8);
      if(!std::isfinite(header_.scale[axis]) || header_.scale[axis] == 0)
        throw LAS_error(std::string("the LAS ") + axes[axis] + " scale factor is zero or not finite");
      if(!std::isfinite(header_.offset[axis]))
        throw LAS_error(std::string("the LAS ") + axes[axis] + " offset is not finite");
    }
  }

  std::istream& is_;
  LAS_header header_;
  std::uint64_t consumed_ = 0;
  std::uint64_t next_point_ = 0;
  std::vector<unsigned char> record_;
};

/// \ingroup PkgSharpFeatureExtractionIORef
/// Reads all the point positions of an uncompressed LAS 1.2 to 1.4 stream (see
/// `LAS_point_reader`), a chunk at a time, and appends them to `points`.
/// \tparam Point_3 a point type constructible from three doubles.
/// \param is the stream, at the beginning of the file, opened with `std::ios::binary`.
/// \param points receives the points on success, appended; left unchanged on failure.
/// \param error if not null, receives on failure one line saying what is wrong.
/// \returns `true` on success, `false` if the reader threw `LAS_error`.
template <typename Point_3>
bool read_LAS_points(std::istream& is, std::vector<Point_3>& points, std::string* error = nullptr)
{
  // Points decoded per read: the doubles of a chunk take 24 bytes a point, 1.5 MB.
  constexpr std::size_t chunk_points = 1 << 16;
  try
  {
    LAS_point_reader reader(is);
    std::vector<Point_3> read;
    std::vector<double> xyz;
    while(reader.read(chunk_points, xyz) > 0)
    {
      for(std::size_t i = 0; i < xyz.size(); i += 3)
        read.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
      xyz.clear();
    }
    points.insert(points.end(), read.begin(), read.end());
    return true;
  }
  catch(const LAS_error& e)
  {
    if(error != nullptr)
      *error = e.what();
    return false;
  }
}

} // namespace IO
} // namespace CGAL

#endif
