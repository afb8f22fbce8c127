// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The coder of `compress_point_cloud()` and `decompress_point_cloud()`: each height field
// resampled on a grid over its plane, the images packed side by side into one atlas, padded
// smoothly outside their masks, the heights coded with JPEG 2000 (lossy), the masks with
// JPEG 2000 (lossless), the frames quantized.
//
// Bitstream (integers little-endian, version 2; version 1 put every point at its cell's centre):
//   "SFEH" version:u8
//   box low corner 3 x f64, box extent f64, grid spacing f64, quantizer step f64
//   height offset:i32, height precision:u8, number of pieces:u32
//   per piece: width:u16 height:u16 origin 3 x u16 (in the box) rotation 3 x i16 (quaternion)
//   mask codestream size:u32, mask codestream, height codestream size:u32, height codestream
// The atlas layout is not stored: the decoder packs the same image sizes the same way.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_HEIGHT_IMAGE_CODING_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_HEIGHT_IMAGE_CODING_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/Jpeg2000_coding.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

constexpr char height_image_magic[4] = {'S', 'F', 'E', 'H'};
constexpr std::uint8_t height_image_version = 2;
/// Largest value of a quantized frame coordinate (unsigned 16 bits).
constexpr double frame_position_levels = 65535;
/// Largest magnitude of a quantized quaternion component (signed 16 bits).
constexpr double frame_rotation_levels = 32767;
/// Most bits of a quantized height: OpenJPEG's 9/7 wavelet is exact up to 16-bit images.
constexpr unsigned int largest_height_precision = 16;
/// Pixels left empty between two images of the atlas: the wavelet's support at the finest
/// level, so that one image's edge does not spill into the next one's first pixels.
constexpr unsigned int atlas_gap = 2;
/// Largest atlas (pixels) a bitstream may describe: 2^28 pixels (a gigabyte of 32-bit values)
/// is far beyond any cloud of a billion points, and refuses forged sizes before allocating.
constexpr double largest_atlas_pixels = double(1u << 28);

/// A piece's frame: grid origin, the two grid directions and the height direction.
struct Height_frame
{
  Vec3 origin;
  Eigen::Matrix3d axes; // columns: u, v, height
};

/// Where the frames' origins are quantized: the bounding box of the points, grown by half its
/// extent on every side (a grid origin lies outside the box when its plane is tilted).
struct Frame_box
{
  Vec3 low = Vec3::Zero();
  double extent = 1;

  Vec3 lowest() const { return low - Vec3::Constant(extent / 2); }
  double span() const { return 2 * extent; }
};

struct Quantized_frame
{
  std::array<std::uint16_t, 3> origin{};
  std::array<std::int16_t, 3> rotation{};
};

inline Height_frame dequantize_frame(const Quantized_frame& q, const Frame_box& box)
{
  Height_frame f;
  for(int c = 0; c < 3; ++c)
    f.origin[c] = box.lowest()[c] + box.span() * double(q.origin[c]) / frame_position_levels;
  const Vec3 xyz(q.rotation[0] / frame_rotation_levels, q.rotation[1] / frame_rotation_levels,
                 q.rotation[2] / frame_rotation_levels);
  const double w = std::sqrt((std::max)(0., 1 - xyz.squaredNorm()));
  f.axes = Eigen::Quaterniond(w, xyz.x(), xyz.y(), xyz.z()).normalized().toRotationMatrix();
  return f;
}

inline Quantized_frame quantize_frame(const Vec3& origin, const Eigen::Matrix3d& rotation, const Frame_box& box)
{
  Quantized_frame q;
  for(int c = 0; c < 3; ++c)
  {
    const double t = (origin[c] - box.lowest()[c]) / box.span();
    q.origin[c] = std::uint16_t(std::lround((std::min)(1., (std::max)(0., t)) * frame_position_levels));
  }
  Eigen::Quaterniond r(rotation);
  if(r.w() < 0)
    r.coeffs() = -r.coeffs();
  const Vec3 xyz(r.x(), r.y(), r.z());
  for(int c = 0; c < 3; ++c)
    q.rotation[c] = std::int16_t(std::lround(xyz[c] * frame_rotation_levels));
  return q;
}

/// A piece resampled on its grid: heights (in length units) and mask, row by row.
struct Height_image
{
  unsigned int width = 0, height = 0;
  std::vector<double> heights;
  std::vector<std::uint8_t> mask;
};

/// The images' places in the atlas: rows of images sorted by decreasing height (shelves), in
/// an atlas about as wide as it is high. Depends on the sizes only.
struct Atlas_layout
{
  unsigned int width = 0, height = 0;
  std::vector<unsigned int> x, y;

  /// The index in the atlas (row by row) of cell (cx, cy) of image `k`.
  std::size_t pixel(std::size_t k, unsigned int cx, unsigned int cy) const
  {
    return std::size_t(y[k] + cy) * width + x[k] + cx;
  }
};

inline Atlas_layout pack_atlas(const std::vector<std::array<unsigned int, 2>>& sizes)
{
  Atlas_layout layout;
  const std::size_t n = sizes.size();
  layout.x.assign(n, 0);
  layout.y.assign(n, 0);
  double area = 0;
  unsigned int widest = 0;
  for(const auto& s : sizes)
  {
    area += double(s[0] + atlas_gap) * double(s[1] + atlas_gap);
    widest = (std::max)(widest, s[0] + atlas_gap);
  }
  if(area > largest_atlas_pixels)
    throw std::invalid_argument("the height images are too large");
  const unsigned int row_width = (std::max)(widest, (unsigned int)(std::ceil(std::sqrt(area))));
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes[a][1] > sizes[b][1]; });
  unsigned int x = 0, y = 0, shelf = 0;
  for(std::size_t k : order)
  {
    if(x + sizes[k][0] + atlas_gap > row_width)
    {
      x = 0;
      y += shelf;
      shelf = 0;
    }
    layout.x[k] = x;
    layout.y[k] = y;
    x += sizes[k][0] + atlas_gap;
    shelf = (std::max)(shelf, sizes[k][1] + atlas_gap);
    layout.width = (std::max)(layout.width, x);
  }
  layout.height = y + shelf;
  return layout;
}

/// Fills the pixels of weight 0 smoothly from those of weight 1 (pull-push: mask-weighted
/// averages over a pyramid of halved images, then the coarse values, bilinearly interpolated,
/// where the fine ones are missing). The known pixels keep their values.
inline void fill_smoothly(unsigned int width, unsigned int height, std::vector<double>& values,
                          std::vector<double> weights)
{
  if(width <= 1 && height <= 1)
    return;
  const unsigned int w2 = (width + 1) / 2, h2 = (height + 1) / 2;
  std::vector<double> coarse(std::size_t(w2) * h2, 0.), coarse_weights(coarse.size(), 0.);
  for(unsigned int y = 0; y < height; ++y)
    for(unsigned int x = 0; x < width; ++x)
    {
      const std::size_t fine = std::size_t(y) * width + x, c = std::size_t(y / 2) * w2 + x / 2;
      coarse[c] += weights[fine] * values[fine];
      coarse_weights[c] += weights[fine];
    }
  for(std::size_t c = 0; c < coarse.size(); ++c)
  {
    if(coarse_weights[c] > 0)
      coarse[c] /= coarse_weights[c];
    coarse_weights[c] = (std::min)(1., coarse_weights[c]);
  }
  fill_smoothly(w2, h2, coarse, coarse_weights);
  auto at = [&](double x, double y) {
    // Bilinear, at fine pixel centres: coarse pixel c covers fine pixels 2c and 2c + 1.
    const double cx = (std::max)(0., (std::min)(double(w2 - 1), (x - 0.5) / 2)),
                 cy = (std::max)(0., (std::min)(double(h2 - 1), (y - 0.5) / 2));
    const unsigned int x0 = (std::min)(w2 - 1, (unsigned int)cx), y0 = (std::min)(h2 - 1, (unsigned int)cy);
    const unsigned int x1 = (std::min)(w2 - 1, x0 + 1), y1 = (std::min)(h2 - 1, y0 + 1);
    const double fx = cx - x0, fy = cy - y0;
    return (1 - fy) * ((1 - fx) * coarse[std::size_t(y0) * w2 + x0] + fx * coarse[std::size_t(y0) * w2 + x1]) +
           fy * ((1 - fx) * coarse[std::size_t(y1) * w2 + x0] + fx * coarse[std::size_t(y1) * w2 + x1]);
  };
  for(unsigned int y = 0; y < height; ++y)
    for(unsigned int x = 0; x < width; ++x)
    {
      const std::size_t i = std::size_t(y) * width + x;
      if(weights[i] < 1)
        values[i] = weights[i] * values[i] + (1 - weights[i]) * at(x + 0.5, y + 0.5);
    }
}

/// The height of the surface at `position` (in cell units) of cell (cx, cy): the least-squares
/// plane of the points of the 3 x 3 cells around it; their mean height if they do not span a
/// plane.
inline double height_at_cell(const std::vector<std::vector<std::size_t>>& cells, const std::vector<Vec3>& local,
                             unsigned int width, unsigned int height, unsigned int cx, unsigned int cy,
                             const Eigen::Vector2d& position)
{
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Vec3 rhs = Vec3::Zero();
  double sum = 0;
  std::size_t count = 0;
  for(unsigned int y = cy > 0 ? cy - 1 : 0; y <= (std::min)(height - 1, cy + 1); ++y)
    for(unsigned int x = cx > 0 ? cx - 1 : 0; x <= (std::min)(width - 1, cx + 1); ++x)
      for(std::size_t i : cells[std::size_t(y) * width + x])
      {
        const Vec3 row(1, local[i].x() - position.x(), local[i].y() - position.y());
        normal_matrix.noalias() += row * row.transpose();
        rhs += row * local[i].z();
        sum += local[i].z();
        ++count;
      }
  // A plane needs three points not on a line; the determinant of the normal matrix (in cell
  // units) vanishes on a line, and stays above this for three points a cell apart.
  const double smallest_determinant = 1e-3;
  if(count >= 3 && normal_matrix.determinant() > smallest_determinant)
    return normal_matrix.ldlt().solve(rhs)[0];
  return count > 0 ? sum / double(count) : 0.;
}

/// Calls `f(xx, yy, dx, dy)` for each cell (xx, yy) = (x + dx, y + dy) of the 3 x 3 square
/// around cell (x, y) that lies inside the width x height image.
template <typename Function>
void for_each_in_square(unsigned int width, unsigned int height, unsigned int x, unsigned int y, const Function& f)
{
  for(int dy = -1; dy <= 1; ++dy)
    for(int dx = -1; dx <= 1; ++dx)
    {
      const long xx = long(x) + dx, yy = long(y) + dy;
      if(xx >= 0 && yy >= 0 && xx < long(width) && yy < long(height))
        f((unsigned int)xx, (unsigned int)yy, dx, dy);
    }
}

/// Where the point of mask cell (x, y) lies, in cell units: the cell's centre, moved towards
/// the rest of the mask on its boundary. A boundary cell holds points only on the side of the
/// piece's edge that faces the mask; with the edge anywhere across the cell, their centroid lies
/// a quarter cell from the centre on average. Half the mean offset of the mask cells of the
/// 3 x 3 square is that quarter cell on a straight edge (the square's set cells lie half a cell
/// inwards on average) and on a corner, and 0 inside. Encoder and decoder both derive it from
/// the mask, so it costs no bit; it keeps the points of pieces that end on a crease from
/// overhanging the crease by up to half a cell. `in_mask(x, y)` tells whether a cell of the
/// width x height image is in the mask.
template <typename InMask>
Eigen::Vector2d cell_point(const InMask& in_mask, unsigned int width, unsigned int height, unsigned int x,
                           unsigned int y)
{
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();
  int set = 0;
  for_each_in_square(width, height, x, y, [&](unsigned int xx, unsigned int yy, int dx, int dy) {
    if(in_mask(xx, yy))
    {
      offset += Eigen::Vector2d(dx, dy);
      ++set;
    }
  });
  const double towards_mask = 0.5;
  return Eigen::Vector2d(x + 0.5, y + 0.5) + (set > 0 ? towards_mask / set : 0.) * offset;
}

/// The rank filter of a mask over the 3 x 3 square: a cell is set when at least `at_least`
/// cells of its square are (1: dilation, 9: erosion, 5: majority). Outside is unset.
inline std::vector<std::uint8_t> rank_filter(const std::vector<std::uint8_t>& mask, unsigned int width,
                                             unsigned int height, int at_least)
{
  std::vector<std::uint8_t> out(mask.size(), 0);
  for(unsigned int y = 0; y < height; ++y)
    for(unsigned int x = 0; x < width; ++x)
    {
      int set = 0;
      for_each_in_square(width, height, x, y, [&](unsigned int xx, unsigned int yy, int, int) {
        if(mask[std::size_t(yy) * width + xx])
          ++set;
      });
      out[std::size_t(y) * width + x] = set >= at_least ? 1 : 0;
    }
  return out;
}

/// The height image of `members` over `frame` with cells of side `cell`: the cells holding a
/// point, closed (holes of a cell filled), with the fitted height at each.
inline Height_image resample_height_field(const std::vector<Vec3>& points, const std::vector<std::size_t>& members,
                                          const Height_frame& frame, double cell, unsigned int width,
                                          unsigned int height)
{
  Height_image image;
  image.width = width;
  image.height = height;
  std::vector<Vec3> local;
  std::vector<std::vector<std::size_t>> cells(std::size_t(width) * height);
  std::vector<std::uint8_t> occupied(cells.size(), 0);
  for(std::size_t i : members)
  {
    const Vec3 d = frame.axes.transpose() * (points[i] - frame.origin);
    const Vec3 l(d.x() / cell, d.y() / cell, d.z());
    const auto x = (unsigned int)(std::min)(double(width - 1), (std::max)(0., std::floor(l.x())));
    const auto y = (unsigned int)(std::min)(double(height - 1), (std::max)(0., std::floor(l.y())));
    cells[std::size_t(y) * width + x].push_back(local.size());
    occupied[std::size_t(y) * width + x] = 1;
    local.push_back(l);
  }
  // Closed (holes of a cell filled), then smoothed by a majority: a ragged boundary costs
  // mask bits and adds no point that matters.
  constexpr int dilation = 1, erosion = 9, majority = 5;
  image.mask = rank_filter(rank_filter(rank_filter(occupied, width, height, dilation), width, height, erosion), width,
                           height, majority);
  image.heights.assign(cells.size(), 0.);
  auto in_mask = [&](unsigned int x, unsigned int y) { return image.mask[std::size_t(y) * width + x] != 0; };
  for(unsigned int y = 0; y < height; ++y)
    for(unsigned int x = 0; x < width; ++x)
      if(image.mask[std::size_t(y) * width + x])
        image.heights[std::size_t(y) * width + x] =
          height_at_cell(cells, local, width, height, x, y, cell_point(in_mask, width, height, x, y));
  return image;
}

/// Little-endian writer of the bitstream's fields.
struct Byte_writer
{
  std::vector<unsigned char>& out;

  template <typename Unsigned>
  void integer(Unsigned v, unsigned int bytes)
  {
    for(unsigned int b = 0; b < bytes; ++b)
      out.push_back(static_cast<unsigned char>((std::uint64_t(v) >> (8 * b)) & 0xFF));
  }
  void real(double v)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    integer(bits, 8);
  }
};

/// Little-endian reader: every read past the end throws.
struct Byte_reader
{
  const std::vector<unsigned char>& in;
  std::size_t position = 0;

  void need(std::size_t count) const
  {
    if(count > in.size() - position)
      throw std::invalid_argument("decompress_point_cloud: truncated bitstream");
  }
  std::uint64_t integer(unsigned int bytes)
  {
    need(bytes);
    std::uint64_t v = 0;
    for(unsigned int b = 0; b < bytes; ++b)
      v |= std::uint64_t(in[position++]) << (8 * b);
    return v;
  }
  double real()
  {
    const std::uint64_t bits = integer(8);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
};

/// The quantized frame, grid size and atlas image of every piece, and the scalars they share.
struct Height_image_set
{
  Frame_box box;
  double cell = 0, step = 0;
  std::int32_t offset = 0;
  unsigned int precision = 1;
  std::vector<Quantized_frame> frames;
  std::vector<std::array<unsigned int, 2>> sizes;
};

/// Codes the pieces of `points` given by `pieces` (each a list of point indices) on grids of
/// side `cell`, heights quantized with step `step`; appends the bitstream to `out`.
inline void encode_height_fields(const std::vector<Vec3>& points, const std::vector<std::vector<std::size_t>>& pieces,
                                 double cell, double step, std::vector<unsigned char>& out)
{
  Height_image_set set;
  set.cell = cell;
  set.step = step;
  Vec3 low = points.front(), high = low;
  for(const Vec3& p : points)
  {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  set.box.low = low;
  set.box.extent = (std::max)((high - low).maxCoeff(), cell);
  std::vector<Height_image> images;
  for(const auto& members : pieces)
  {
    Principal_axes axes;
    compute_principal_axes(members.size(), [&](std::size_t j) { return points[members[j]]; }, axes);
    Eigen::Matrix3d rotation;
    rotation.col(0) = axes.axes.col(2);
    rotation.col(1) = axes.axes.col(1);
    rotation.col(2) = rotation.col(0).cross(rotation.col(1));
    const Height_frame rotated = dequantize_frame(quantize_frame(axes.centroid, rotation, set.box), set.box);
    // The grid starts half a cell before the lowest point, so that the quantization of the
    // origin (a 65535th of twice the extent, far less than a cell) leaves every point inside.
    Vec3 lowest = Vec3::Constant((std::numeric_limits<double>::max)()), highest = -lowest;
    for(std::size_t i : members)
    {
      const Vec3 d = rotated.axes.transpose() * (points[i] - axes.centroid);
      lowest = lowest.cwiseMin(d);
      highest = highest.cwiseMax(d);
    }
    const Vec3 corner = axes.centroid + rotated.axes * Vec3(lowest.x() - cell / 2, lowest.y() - cell / 2, 0);
    const Quantized_frame q = quantize_frame(corner, rotated.axes, set.box);
    const Height_frame frame = dequantize_frame(q, set.box);
    const double cells_u = std::ceil((highest.x() - lowest.x()) / cell) + 1,
                 cells_v = std::ceil((highest.y() - lowest.y()) / cell) + 1;
    if(cells_u * cells_v > largest_atlas_pixels)
      throw std::invalid_argument("compress_point_cloud: grid_spacing too small for the extent of the points");
    set.frames.push_back(q);
    set.sizes.push_back({(unsigned int)cells_u, (unsigned int)cells_v});
    images.push_back(resample_height_field(points, members, frame, cell, set.sizes.back()[0], set.sizes.back()[1]));
  }

  const Atlas_layout layout = pack_atlas(set.sizes);
  const std::size_t pixels = std::size_t(layout.width) * layout.height;
  std::vector<double> heights(pixels, 0.), known(pixels, 0.);
  Gray_image mask{layout.width, layout.height, 1, std::vector<std::int32_t>(pixels, 0)};
  for(std::size_t k = 0; k < images.size(); ++k)
    for(unsigned int y = 0; y < images[k].height; ++y)
      for(unsigned int x = 0; x < images[k].width; ++x)
      {
        const std::size_t from = std::size_t(y) * images[k].width + x;
        const std::size_t to = layout.pixel(k, x, y);
        if(images[k].mask[from])
        {
          heights[to] = images[k].heights[from] / step;
          known[to] = 1;
          mask.pixels[to] = 1;
        }
      }
  fill_smoothly(layout.width, layout.height, heights, known);
  double lowest = 0, highest = 0;
  if(pixels > 0)
  {
    lowest = *std::min_element(heights.begin(), heights.end());
    highest = *std::max_element(heights.begin(), heights.end());
  }
  const double levels = std::round(highest) - std::round(lowest);
  if(!(levels < std::ldexp(1., int(largest_height_precision))))
    throw std::invalid_argument("compress_point_cloud: quantization_step too small: the heights need more than "
                                + std::to_string(largest_height_precision) + " bits");
  set.offset = -std::int32_t(std::lround(lowest));
  while(set.precision < largest_height_precision && levels >= std::ldexp(1., int(set.precision)))
    ++set.precision;
  Gray_image height_image{layout.width, layout.height, set.precision, std::vector<std::int32_t>(pixels, 0)};
  for(std::size_t i = 0; i < pixels; ++i)
    height_image.pixels[i] = std::int32_t(std::lround(heights[i])) + set.offset;

  Byte_writer w{out};
  out.insert(out.end(), height_image_magic, height_image_magic + 4);
  w.integer(height_image_version, 1);
  for(int c = 0; c < 3; ++c)
    w.real(set.box.low[c]);
  w.real(set.box.extent);
  w.real(set.cell);
  w.real(set.step);
  w.integer(std::uint32_t(set.offset), 4);
  w.integer(set.precision, 1);
  w.integer(set.frames.size(), 4);
  for(std::size_t k = 0; k < set.frames.size(); ++k)
  {
    w.integer(set.sizes[k][0], 2);
    w.integer(set.sizes[k][1], 2);
    for(int c = 0; c < 3; ++c)
      w.integer(set.frames[k].origin[c], 2);
    for(int c = 0; c < 3; ++c)
      w.integer(std::uint16_t(set.frames[k].rotation[c]), 2);
  }
  for(const auto& [image, lossless] : {std::make_pair(&mask, true), std::make_pair(&height_image, false)})
  {
    std::vector<unsigned char> codestream;
    encode_jpeg2000(*image, lossless, codestream);
    w.integer(codestream.size(), 4);
    out.insert(out.end(), codestream.begin(), codestream.end());
  }
}

/// Decodes a bitstream of `encode_height_fields()`: one point per mask pixel.
/// \throws std::invalid_argument if `in` is not such a bitstream, entirely.
inline std::vector<Vec3> decode_height_fields(const std::vector<unsigned char>& in)
{
  Byte_reader r{in};
  r.need(5);
  if(!std::equal(height_image_magic, height_image_magic + 4, in.begin()))
    throw std::invalid_argument("decompress_point_cloud: not a compressed point cloud (bad magic number)");
  r.position = 4;
  if(r.integer(1) != height_image_version)
    throw std::invalid_argument("decompress_point_cloud: unsupported bitstream version");
  Height_image_set set;
  for(int c = 0; c < 3; ++c)
    set.box.low[c] = r.real();
  set.box.extent = r.real();
  set.cell = r.real();
  set.step = r.real();
  set.offset = std::int32_t(std::uint32_t(r.integer(4)));
  set.precision = unsigned(r.integer(1));
  if(!set.box.low.allFinite() || !(set.box.extent > 0) || !std::isfinite(set.box.extent) || !(set.cell > 0) ||
     !std::isfinite(set.cell) || !(set.step > 0) || !std::isfinite(set.step) || set.precision < 1 ||
     set.precision > largest_height_precision)
    throw std::invalid_argument("decompress_point_cloud: invalid header");
  const std::size_t count = std::size_t(r.integer(4));
  const std::size_t bytes_per_piece = 16;
  r.need(count * bytes_per_piece);
  for(std::size_t k = 0; k < count; ++k)
  {
    const unsigned int width = unsigned(r.integer(2)), height = unsigned(r.integer(2));
    if(width == 0 || height == 0)
      throw std::invalid_argument("decompress_point_cloud: empty height image");
    set.sizes.push_back({width, height});
    Quantized_frame q;
    for(int c = 0; c < 3; ++c)
      q.origin[c] = std::uint16_t(r.integer(2));
    for(int c = 0; c < 3; ++c)
      q.rotation[c] = std::int16_t(std::uint16_t(r.integer(2)));
    set.frames.push_back(q);
  }
  Atlas_layout layout;
  try
  {
    layout = pack_atlas(set.sizes);
  }
  catch(const std::invalid_argument&)
  {
    throw std::invalid_argument("decompress_point_cloud: invalid header (height images too large)");
  }
  Gray_image images[2];
  for(int k = 0; k < 2; ++k)
  {
    const std::size_t size = std::size_t(r.integer(4));
    r.need(size);
    try
    {
      decode_jpeg2000(in.data() + r.position, size, layout.width, layout.height, k == 0 ? 1 : set.precision, images[k]);
    }
    catch(const std::invalid_argument& e)
    {
      throw std::invalid_argument(std::string("decompress_point_cloud: ") + (k == 0 ? "mask: " : "heights: ") + e.what());
    }
    r.position += size;
  }
  if(r.position != in.size())
    throw std::invalid_argument("decompress_point_cloud: bytes after the end of the bitstream");

  std::vector<Vec3> decoded;
  for(std::size_t k = 0; k < count; ++k)
  {
    const Height_frame frame = dequantize_frame(set.frames[k], set.box);
    auto in_mask = [&](unsigned int x, unsigned int y) { return images[0].pixels[layout.pixel(k, x, y)] != 0; };
    for(unsigned int y = 0; y < set.sizes[k][1]; ++y)
      for(unsigned int x = 0; x < set.sizes[k][0]; ++x)
      {
        if(!in_mask(x, y))
          continue;
        const std::size_t i = layout.pixel(k, x, y);
        // In doubles: a forged offset (any 32-bit value) minus a pixel overflows an int.
        const double h = (double(images[1].pixels[i]) - double(set.offset)) * set.step;
        const Eigen::Vector2d at = cell_point(in_mask, set.sizes[k][0], set.sizes[k][1], x, y);
        decoded.push_back(frame.origin + frame.axes * Vec3(at.x() * set.cell, at.y() * set.cell, h));
        // Every field is finite, yet a forged header can make their products overflow.
        if(!decoded.back().allFinite())
          throw std::invalid_argument("decompress_point_cloud: invalid header (decoded coordinates overflow)");
      }
  }
  return decoded;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
