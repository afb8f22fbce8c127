// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// One-channel images to and from JPEG 2000 codestreams in memory, with OpenJPEG (link with
// libopenjp2).

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_JPEG2000_CODING_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_JPEG2000_CODING_H

#include <openjpeg.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Wavelet decomposition levels of a lossy image: beyond 5, the coarsest band of an image of a
/// few hundred pixels is a few pixels wide and further levels gain nothing.
constexpr unsigned int jpeg2000_largest_levels = 5;
/// Size of OpenJPEG's stream buffer (bytes): the default of its file streams.
constexpr std::size_t jpeg2000_stream_buffer = 1 << 20;

/// A one-channel image of unsigned integers of `precision` bits, row by row.
struct Gray_image
{
  unsigned int width = 0, height = 0, precision = 1;
  std::vector<std::int32_t> pixels;
};

namespace jpeg2000 {

/// Bytes read from or written to memory by OpenJPEG's stream callbacks.
struct Memory
{
  std::vector<unsigned char>* bytes = nullptr;
  const unsigned char* data = nullptr;
  std::size_t size = 0, position = 0;
};

inline OPJ_SIZE_T read(void* buffer, OPJ_SIZE_T count, void* user)
{
  Memory& m = *static_cast<Memory*>(user);
  if(m.position >= m.size)
    return OPJ_SIZE_T(-1);
  const std::size_t n = (std::min)(std::size_t(count), m.size - m.position);
  std::memcpy(buffer, m.data + m.position, n);
  m.position += n;
  return n;
}

inline OPJ_SIZE_T write(void* buffer, OPJ_SIZE_T count, void* user)
{
  Memory& m = *static_cast<Memory*>(user);
  const unsigned char* from = static_cast<const unsigned char*>(buffer);
  m.bytes->insert(m.bytes->end(), from, from + count);
  return count;
}

inline OPJ_OFF_T skip(OPJ_OFF_T count, void* user)
{
  Memory& m = *static_cast<Memory*>(user);
  if(count < 0 || std::size_t(count) > m.size - (std::min)(m.size, m.position))
    return OPJ_OFF_T(-1);
  m.position += std::size_t(count);
  return count;
}

inline OPJ_BOOL seek(OPJ_OFF_T position, void* user)
{
  Memory& m = *static_cast<Memory*>(user);
  if(position < 0 || std::size_t(position) > m.size)
    return OPJ_FALSE;
  m.position = std::size_t(position);
  return OPJ_TRUE;
}

/// Keeps OpenJPEG's last error message, for the exception.
inline void keep_message(const char* message, void* user)
{
  *static_cast<std::string*>(user) = message;
}

struct Codec_deleter
{
  void operator()(opj_codec_t* c) const { opj_destroy_codec(c); }
};
struct Stream_deleter
{
  void operator()(opj_stream_t* s) const { opj_stream_destroy(s); }
};
struct Image_deleter
{
  void operator()(opj_image_t* i) const { opj_image_destroy(i); }
};
typedef std::unique_ptr<opj_codec_t, Codec_deleter> Codec;
typedef std::unique_ptr<opj_stream_t, Stream_deleter> Stream;
typedef std::unique_ptr<opj_image_t, Image_deleter> Image;

inline Stream memory_stream(Memory& memory, bool input)
{
  Stream s(opj_stream_create(jpeg2000_stream_buffer, input ? OPJ_TRUE : OPJ_FALSE));
  if(!s)
    throw std::bad_alloc();
  opj_stream_set_user_data(s.get(), &memory, nullptr);
  if(input)
  {
    opj_stream_set_user_data_length(s.get(), memory.size);
    opj_stream_set_read_function(s.get(), read);
  }
  else
    opj_stream_set_write_function(s.get(), write);
  opj_stream_set_skip_function(s.get(), skip);
  opj_stream_set_seek_function(s.get(), seek);
  return s;
}

inline void silence(opj_codec_t* codec, std::string& error)
{
  opj_set_info_handler(codec, nullptr, nullptr);
  opj_set_warning_handler(codec, nullptr, nullptr);
  opj_set_error_handler(codec, keep_message, &error);
}

} // namespace jpeg2000

/// Appends the JPEG 2000 codestream of `image` to `out`. Lossless (reversible 5/3 wavelet, no
/// decomposition: for masks) or lossy (irreversible 9/7 wavelet: the quantizer step of each band
/// is one unit of the pixel values, normalised by the band's gain, and every coding pass is kept).
inline void encode_jpeg2000(const Gray_image& image, bool lossless, std::vector<unsigned char>& out)
{
  namespace j = jpeg2000;
  opj_image_cmptparm_t component;
  std::memset(&component, 0, sizeof(component));
  component.dx = component.dy = 1;
  component.w = image.width;
  component.h = image.height;
  component.prec = image.precision;
  component.sgnd = 0;
  j::Image encoded(opj_image_create(1, &component, OPJ_CLRSPC_GRAY));
  if(!encoded)
    throw std::bad_alloc();
  encoded->x0 = encoded->y0 = 0;
  encoded->x1 = image.width;
  encoded->y1 = image.height;
  std::copy(image.pixels.begin(), image.pixels.end(), encoded->comps[0].data);

  opj_cparameters_t parameters;
  opj_set_default_encoder_parameters(&parameters);
  parameters.tcp_numlayers = 1;
  parameters.tcp_rates[0] = 0; // every coding pass
  parameters.cp_disto_alloc = 1;
  parameters.irreversible = lossless ? 0 : 1;
  unsigned int levels = 0;
  while(!lossless && levels < jpeg2000_largest_levels && (std::min)(image.width, image.height) >> (levels + 1) > 0)
    ++levels;
  parameters.numresolution = int(levels) + 1;

  std::string error;
  j::Codec codec(opj_create_compress(OPJ_CODEC_J2K));
  j::silence(codec.get(), error);
  j::Memory memory;
  memory.bytes = &out;
  j::Stream stream = j::memory_stream(memory, false);
  if(!opj_setup_encoder(codec.get(), &parameters, encoded.get()) ||
     !opj_start_compress(codec.get(), encoded.get(), stream.get()) || !opj_encode(codec.get(), stream.get()) ||
     !opj_end_compress(codec.get(), stream.get()))
    throw std::runtime_error("JPEG 2000 encoding failed: " + error);
}

/// Decodes the JPEG 2000 codestream `bytes[0, size)` into `image`, which must be a one-channel
/// image of `width` x `height` pixels of `precision` bits.
/// \throws std::invalid_argument if it is not.
inline void decode_jpeg2000(const unsigned char* bytes, std::size_t size, unsigned int width, unsigned int height,
                            unsigned int precision, Gray_image& image)
{
  namespace j = jpeg2000;
  std::string error;
  j::Codec codec(opj_create_decompress(OPJ_CODEC_J2K));
  j::silence(codec.get(), error);
  opj_dparameters_t parameters;
  opj_set_default_decoder_parameters(&parameters);
  j::Memory memory;
  memory.data = bytes;
  memory.size = size;
  j::Stream stream = j::memory_stream(memory, true);
  opj_image_t* header = nullptr;
  const bool read = opj_setup_decoder(codec.get(), &parameters) && opj_decoder_set_strict_mode(codec.get(), OPJ_TRUE) &&
                    opj_read_header(stream.get(), codec.get(), &header);
  j::Image decoded(header);
  if(!read)
    throw std::invalid_argument("not a JPEG 2000 codestream: " + error);
  // The size is checked before decoding: a forged header would make OpenJPEG allocate it.
  if(decoded->numcomps != 1 || decoded->x0 != 0 || decoded->y0 != 0 || decoded->x1 != width ||
     decoded->y1 != height || decoded->comps[0].prec != precision || decoded->comps[0].sgnd != 0 ||
     decoded->comps[0].dx != 1 || decoded->comps[0].dy != 1)
    throw std::invalid_argument("the JPEG 2000 image does not have the size of the height images");
  if(!opj_decode(codec.get(), stream.get(), decoded.get()) || !opj_end_decompress(codec.get(), stream.get()) ||
     decoded->comps[0].data == nullptr || decoded->comps[0].w != width || decoded->comps[0].h != height)
    throw std::invalid_argument("corrupt JPEG 2000 codestream: " + error);
  image.width = width;
  image.height = height;
  image.precision = precision;
  image.pixels.assign(decoded->comps[0].data, decoded->comps[0].data + std::size_t(width) * height);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
