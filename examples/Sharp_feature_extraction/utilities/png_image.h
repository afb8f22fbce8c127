// A minimal RGB image that writes itself as a PNG file (ISO/IEC 15948), deflated by zlib.
//
// Every row is "Up"-filtered (each byte minus the byte above it): the renderings are smooth
// shading on a flat background, where that difference is mostly zero and deflates to little.

#ifndef SFE_UTILITIES_PNG_IMAGE_H
#define SFE_UTILITIES_PNG_IMAGE_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <zlib.h>

namespace sfe_utilities {

/// An 8-bit RGB image, origin at the top-left corner, `x` to the right and `y` downwards.
/// Writes outside the image are silently clipped, so drawing code need not test bounds.
class Png_image
{
public:
  /// creates a `width` x `height` image filled with the background colour (`r`, `g`, `b`).
  Png_image(int width, int height,
            unsigned char r = 255, unsigned char g = 255, unsigned char b = 255)
    : m_width(std::max(width, 0)), m_height(std::max(height, 0)),
      m_pixels(3 * static_cast<std::size_t>(m_width) * static_cast<std::size_t>(m_height))
  {
    for(std::size_t i = 0; i < m_pixels.size(); i += 3) {
      m_pixels[i] = r;
      m_pixels[i + 1] = g;
      m_pixels[i + 2] = b;
    }
  }

  int width() const { return m_width; }
  int height() const { return m_height; }

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < m_width && y < m_height; }

  /// returns the colour of a pixel inside the image.
  std::array<unsigned char, 3> pixel(int x, int y) const
  {
    const std::size_t i = index(x, y);
    return {m_pixels[i], m_pixels[i + 1], m_pixels[i + 2]};
  }

  void set_pixel(int x, int y, unsigned char r, unsigned char g, unsigned char b)
  {
    if(!contains(x, y))
      return;
    const std::size_t i = index(x, y);
    m_pixels[i] = r;
    m_pixels[i + 1] = g;
    m_pixels[i + 2] = b;
  }

  /// mixes (`r`, `g`, `b`) into the pixel with opacity `alpha` in [0,1] (0 leaves the pixel as is).
  void blend_pixel(int x, int y, unsigned char r, unsigned char g, unsigned char b, double alpha)
  {
    if(!contains(x, y) || !(alpha > 0))
      return;
    alpha = std::min(alpha, 1.);
    const std::size_t i = index(x, y);
    const unsigned char source[3] = {r, g, b};
    for(std::size_t c = 0; c < 3; ++c) {
      const double mixed = (1. - alpha) * m_pixels[i + c] + alpha * source[c];
      m_pixels[i + c] = static_cast<unsigned char>(std::min(255., mixed + 0.5));
    }
  }

  /// writes the image as a PNG file; returns `false` if the file cannot be written.
  bool write(const std::string& path) const
  {
    if(m_width == 0 || m_height == 0) // PNG has no empty images
      return false;
    std::vector<unsigned char> header;
    append_big_endian(header, static_cast<std::uint32_t>(m_width));
    append_big_endian(header, static_cast<std::uint32_t>(m_height));
    header.push_back(8); // bits per channel
    header.push_back(2); // colour type: RGB triples
    header.push_back(0); // compression method: deflate
    header.push_back(0); // filter method: adaptive, with per-row filter type bytes
    header.push_back(0); // no interlacing

    const std::vector<unsigned char> pixels = zlib_deflated(filtered_rows());
    if(pixels.empty())
      return false;
    std::ofstream out(path, std::ios::binary);
    if(!out)
      return false;
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    out.write(reinterpret_cast<const char*>(signature), 8);
    write_chunk(out, "IHDR", header);
    write_chunk(out, "IDAT", pixels);
    write_chunk(out, "IEND", {});
    out.close();
    return static_cast<bool>(out);
  }

private:
  std::size_t index(int x, int y) const
  {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) + static_cast<std::size_t>(x));
  }

  static void append_big_endian(std::vector<unsigned char>& bytes, std::uint32_t value)
  {
    for(int shift = 24; shift >= 0; shift -= 8)
      bytes.push_back(static_cast<unsigned char>((value >> shift) & 0xFF));
  }

  // Every PNG row starts with its filter type; 2 ("Up"): each byte minus the byte above it
  // (the row above the first is zero).
  std::vector<unsigned char> filtered_rows() const
  {
    const std::size_t row_size = 3 * static_cast<std::size_t>(m_width);
    const unsigned char up_filter = 2;
    std::vector<unsigned char> rows;
    rows.reserve((row_size + 1) * static_cast<std::size_t>(m_height));
    for(int y = 0; y < m_height; ++y) {
      rows.push_back(up_filter);
      const std::size_t row = row_size * static_cast<std::size_t>(y);
      for(std::size_t i = 0; i < row_size; ++i)
        rows.push_back(static_cast<unsigned char>(m_pixels[row + i] - (y > 0 ? m_pixels[row - row_size + i] : 0)));
    }
    return rows;
  }

  // the zlib stream (RFC 1950) of `data`, at zlib's best compression; empty if zlib fails.
  static std::vector<unsigned char> zlib_deflated(const std::vector<unsigned char>& data)
  {
    uLongf size = compressBound(static_cast<uLong>(data.size()));
    std::vector<unsigned char> stream(size);
    if(compress2(stream.data(), &size, data.data(), static_cast<uLong>(data.size()), Z_BEST_COMPRESSION) != Z_OK)
      return {};
    stream.resize(size);
    return stream;
  }

  // CRC-32 with the reflected polynomial 0xEDB88320, as used by PNG (and zip, gzip, ethernet).
  static std::uint32_t crc32(const unsigned char* bytes, std::size_t size, std::uint32_t crc)
  {
    static const std::array<std::uint32_t, 256> table = [] {
      std::array<std::uint32_t, 256> t{};
      for(std::uint32_t n = 0; n < 256; ++n) {
        std::uint32_t c = n;
        for(int k = 0; k < 8; ++k)
          c = (c & 1) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
        t[n] = c;
      }
      return t;
    }();
    for(std::size_t i = 0; i < size; ++i)
      crc = table[(crc ^ bytes[i]) & 0xFF] ^ (crc >> 8);
    return crc;
  }

  // A chunk is: length, 4-letter type, data, CRC of type and data.
  static void write_chunk(std::ofstream& out, const char type[4], const std::vector<unsigned char>& data)
  {
    std::vector<unsigned char> bytes;
    bytes.reserve(data.size() + 12);
    append_big_endian(bytes, static_cast<std::uint32_t>(data.size()));
    bytes.insert(bytes.end(), type, type + 4);
    bytes.insert(bytes.end(), data.begin(), data.end());
    const std::uint32_t crc = crc32(bytes.data() + 4, bytes.size() - 4, 0xFFFFFFFFu) ^ 0xFFFFFFFFu;
    append_big_endian(bytes, crc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }

  int m_width;
  int m_height;
  std::vector<unsigned char> m_pixels; // row-major RGB triples
};

} // namespace sfe_utilities

#endif // SFE_UTILITIES_PNG_IMAGE_H
