// Tests of the height-field partition (partition_into_height_fields) and of the point-cloud
// coder (compress_point_cloud, decompress_point_cloud), on small samples of the unit cube and
// of the chamfered box.

#include "analytic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/compress_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/decompress_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/partition_into_height_fields.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <tuple>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
using namespace sfe_test;
namespace sfe = CGAL::Sharp_feature_extraction::parameters;
namespace internal = CGAL::Sharp_feature_extraction::internal;

/// Small enough for a test of a second, large enough for a dozen cells across a cube face.
constexpr std::size_t number_of_points = 6000;

/// Distance from `p` to the surface of the unit cube [0, 1]^3.
double distance_to_unit_cube(const Point_3& p)
{
  const double c[3] = {p.x(), p.y(), p.z()};
  double outside = 0, inside = 1;
  for(double x : c)
  {
    const double beyond = (std::max)(0., (std::max)(-x, x - 1));
    outside += beyond * beyond;
    inside = (std::min)(inside, (std::min)(x, 1 - x));
  }
  return outside > 0 ? std::sqrt(outside) : inside;
}

double rms_distance_to_unit_cube(const std::vector<Point_3>& points)
{
  double sum = 0;
  for(const Point_3& p : points)
    sum += distance_to_unit_cube(p) * distance_to_unit_cube(p);
  return std::sqrt(sum / double(points.size()));
}

internal::Height_field_cloud cloud_of(const std::vector<Point_3>& points)
{
  internal::Progress silent;
  internal::Height_field_cloud cloud;
  internal::build_height_field_cloud<CGAL::Sequential_tag>(
    internal::read_input_points(points, CGAL::Identity_property_map<Point_3>()), silent, cloud);
  return cloud;
}

std::vector<std::vector<std::size_t>> pieces_of(const std::vector<std::size_t>& labels)
{
  return internal::group_by_label(labels.size(), labels);
}

} // namespace

TEST_CASE("partition: every piece of a chamfered box is a height field within the bound", "[compression]")
{
  const std::vector<Point_3> points = to_points<Point_3>(sample(chamfered_box(), number_of_points, 0));
  const internal::Height_field_cloud cloud = cloud_of(points);
  for(const double angle : {50., 60.})
  {
    std::vector<std::size_t> labels;
    const std::size_t count = CGAL::partition_into_height_fields<CGAL::Parallel_if_available_tag>(
      points, labels, sfe::height_field_angle(angle));
    REQUIRE(labels.size() == points.size());
    const auto pieces = pieces_of(labels);
    REQUIRE(pieces.size() == count);
    std::cout << "chamfered box, bound " << angle << " degrees: " << count << " pieces" << std::endl;
    // A closed surface is no height field: at least two pieces (a box, at least its 6 faces
    // grouped in twos or threes).
    CHECK(count >= 2);
    const internal::Height_field_bound bound(angle, internal::grid_spacing_per_sampling_spacing * cloud.spacing);
    // Every piece is a height field but for the points of the small pieces it absorbed (crease
    // points, whose normals lean towards both sides): a few in a hundred.
    std::size_t leaning = 0;
    for(const auto& piece : pieces)
    {
      CHECK(piece.size() >= internal::smallest_piece);
      const internal::Height_field_test t = internal::test_height_field(cloud, piece, bound);
      const Eigen::Vector3d normal = t.axes.axes.col(0);
      for(std::size_t i : piece)
        leaning += std::abs(cloud.normals[i].dot(normal)) < bound.cos_maximum_angle ? 1 : 0;
      std::vector<std::tuple<std::int64_t, std::int64_t, double>> cells;
      const Eigen::Vector3d u = t.axes.axes.col(2), v = t.axes.axes.col(1);
      for(std::size_t i : piece)
      {
        const Eigen::Vector3d d = cloud.points[i] - t.axes.centroid;
        cells.emplace_back(std::int64_t(std::floor(d.dot(u) / bound.grid_spacing)),
                           std::int64_t(std::floor(d.dot(v) / bound.grid_spacing)), d.dot(normal));
      }
      CHECK(!internal::has_layers(cells, bound.layer_tolerance));
    }
    const double largest_leaning_fraction = 0.02;
    std::cout << "  points whose normal leans beyond the bound: " << leaning << std::endl;
    CHECK(double(leaning) <= largest_leaning_fraction * double(points.size()));
  }
  // The same whatever the thread count.
  std::vector<std::size_t> sequential, parallel;
  CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, sequential);
  CGAL::partition_into_height_fields<CGAL::Parallel_if_available_tag>(points, parallel);
  CHECK(sequential == parallel);
}

TEST_CASE("partition: the guided split never crosses a boundary of the initial labels", "[compression]")
{
  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), number_of_points, 0));
  // Initial labels that cut faces across (the plane x + 2y = 1.2) as well as along the creases
  // (the sign of z - 0.5): the split must respect both.
  std::vector<std::size_t> initial;
  for(const Point_3& p : points)
    initial.push_back((p.x() + 2 * p.y() > 1.2 ? 1 : 0) + (p.z() > 0.5 ? 2 : 0));
  const internal::Height_field_cloud cloud = cloud_of(points);
  const internal::Height_field_bound bound(internal::default_height_field_angle, cloud.spacing);
  const auto pieces = internal::split_into_height_fields(cloud, internal::group_by_label(points.size(), initial), bound);
  std::set<std::size_t> seen;
  for(const auto& piece : pieces)
  {
    std::set<std::size_t> labels;
    for(std::size_t i : piece)
      labels.insert(initial[i]);
    CHECK(labels.size() == 1);
    seen.insert(labels.begin(), labels.end());
  }
  CHECK(seen.size() == 4);
  // Through the public call: the labels given are used (a wrong count is refused).
  std::vector<std::size_t> labels;
  CHECK(CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, labels, sfe::initial_labels(initial)) >= 4);
  initial.pop_back();
  CHECK_THROWS_AS(CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, labels, sfe::initial_labels(initial)),
                  std::invalid_argument);
  CHECK_THROWS_AS(CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, labels, sfe::height_field_angle(90.)),
                  std::invalid_argument);
}

TEST_CASE("coder: the round-trip error falls with the quantizer step, the size grows", "[compression]")
{
  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), number_of_points, 0));
  std::vector<std::size_t> labels;
  CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, labels);
  const double cell = internal::grid_spacing_per_sampling_spacing * cloud_of(points).spacing;
  double previous_error = std::numeric_limits<double>::infinity();
  std::size_t previous_size = 0;
  // From a step of a cell (coarse heights) to a 64th of one (near the resampling error).
  for(const double step_per_cell : {1., 1. / 8, 1. / 64})
  {
    std::vector<unsigned char> bytes;
    CGAL::compress_point_cloud<CGAL::Sequential_tag>(points, labels, bytes, sfe::quantization_step(step_per_cell * cell));
    std::vector<Point_3> decoded;
    CGAL::decompress_point_cloud(bytes, decoded);
    const double error = rms_distance_to_unit_cube(decoded);
    std::cout << "cube, step " << step_per_cell << " cell: " << bytes.size() << " bytes, " << decoded.size()
              << " points, rms error " << error << std::endl;
    CHECK(error < previous_error);
    CHECK(bytes.size() > previous_size);
    // One point per cell of the faces, each cell holding about two input points.
    CHECK(decoded.size() > points.size() / 4);
    CHECK(decoded.size() < points.size());
    previous_error = error;
    previous_size = bytes.size();
  }
  // At the finest step, the error is a small fraction of a cell.
  const double finest_error_per_cell = 0.1;
  CHECK(previous_error < finest_error_per_cell * cell);
}

TEST_CASE("coder: the points of a piece that ends on a crease do not overhang it", "[compression]")
{
  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), number_of_points, 0));
  std::vector<std::size_t> labels;
  CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, labels);
  // A coarse grid, as for the lowest rates: 4 sampling spacings per cell.
  const double coarse_cells = 4;
  const double cell = coarse_cells * internal::grid_spacing_per_sampling_spacing * cloud_of(points).spacing;
  std::vector<unsigned char> bytes;
  CGAL::compress_point_cloud<CGAL::Sequential_tag>(points, labels, bytes, sfe::grid_spacing(cell));
  std::vector<Point_3> decoded;
  CGAL::decompress_point_cloud(bytes, decoded);
  // Every piece is one face of the cube, and its edges are creases: a decoded point outside the
  // cube overhangs an edge. Points at the centres of the cells of a piece's boundary overhang by
  // up to half a cell (0.40 cell here, rms error 0.075 cell); moved towards the rest of the mask
  // by the quarter cell where the points of a boundary cell lie on average, by 0.24 cell (rms
  // 0.046 cell).
  double overhang = 0;
  for(const Point_3& p : decoded)
    for(const double x : {p.x(), p.y(), p.z()})
      overhang = (std::max)(overhang, (std::max)(-x, x - 1));
  std::cout << "cube, grid of " << coarse_cells << " spacings: " << decoded.size() << " points, largest overhang "
            << overhang / cell << " cell, rms error " << rms_distance_to_unit_cube(decoded) / cell << " cell"
            << std::endl;
  const double largest_overhang_per_cell = 0.3;
  CHECK(overhang < largest_overhang_per_cell * cell);
}

TEST_CASE("coder: the bitstream is the file, and a bad one is refused", "[compression]")
{
  const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), number_of_points / 4, 0));
  std::vector<std::size_t> labels;
  CGAL::partition_into_height_fields<CGAL::Sequential_tag>(points, labels);
  std::vector<unsigned char> bytes;
  CGAL::compress_point_cloud<CGAL::Sequential_tag>(points, labels, bytes);
  std::vector<Point_3> decoded;
  CGAL::decompress_point_cloud(bytes, decoded);
  REQUIRE(!decoded.empty());

  // Written to a file, it takes exactly its byte count and reads back the same.
  const char* path = "test_compress_point_cloud.sfeh";
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  }
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> read((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path);
  CHECK(read.size() == bytes.size());
  std::vector<Point_3> again;
  CGAL::decompress_point_cloud(read, again);
  CHECK(again == decoded);

  auto refused = [](const std::vector<unsigned char>& b) {
    std::vector<Point_3> out;
    CHECK_THROWS_AS(CGAL::decompress_point_cloud(b, out), std::invalid_argument);
  };
  refused({});
  refused(std::vector<unsigned char>(bytes.begin(), bytes.end() - 1));         // truncated
  refused(std::vector<unsigned char>(bytes.begin(), bytes.begin() + bytes.size() / 2));
  std::vector<unsigned char> longer(bytes);
  longer.push_back(0);
  refused(longer);                                                             // trailing byte
  std::vector<unsigned char> other(bytes);
  other[0] = 'X';
  refused(other);                                                              // magic number
  for(const unsigned char version : {1, 3})
  {
    other = bytes;
    other[4] = version;
    refused(other);                                                            // version
  }
  // Any height offset is a valid header, even one whose difference with a pixel overflows an
  // int (found by fuzz_decompress_point_cloud): every point moves along its piece's normal by
  // the change of offset times the quantizer step.
  {
    const std::size_t offset_at = 4 + 1 + 8 * 6; // magic, version, box, extent, grid spacing, step
    double step;
    std::memcpy(&step, bytes.data() + offset_at - 8, sizeof step);
    std::int32_t offset;
    std::memcpy(&offset, bytes.data() + offset_at, sizeof offset);
    const std::int32_t forged_offset = std::numeric_limits<std::int32_t>::min() + 1;
    other = bytes;
    std::memcpy(other.data() + offset_at, &forged_offset, sizeof forged_offset);
    std::vector<Point_3> shifted;
    CGAL::decompress_point_cloud(other, shifted);
    REQUIRE(shifted.size() == decoded.size());
    const double shift = (double(offset) - double(forged_offset)) * step;
    for(std::size_t i = 0; i < decoded.size(); i += (std::max)(std::size_t(1), decoded.size() / 10))
      CHECK(std::sqrt(CGAL::squared_distance(shifted[i], decoded[i])) == Approx(shift).epsilon(1e-9));
  }
  // A finite but huge grid spacing: the decoded coordinates overflow (the fuzzer found such a
  // header).
  {
    const std::size_t grid_spacing_at = 4 + 1 + 8 * 4; // magic, version, box, extent
    const double huge = std::numeric_limits<double>::max();
    other = bytes;
    std::memcpy(other.data() + grid_spacing_at, &huge, sizeof huge);
    refused(other);
  }
  std::vector<unsigned char> garbage(bytes.size());
  for(std::size_t i = 0; i < garbage.size(); ++i)
    garbage[i] = static_cast<unsigned char>((i * 2654435761u) >> 13);
  std::copy(bytes.begin(), bytes.begin() + 5, garbage.begin());
  refused(garbage);                                                            // right header, garbage after

  // Bad input of the coder.
  std::vector<std::size_t> short_labels(labels.begin(), labels.end() - 1);
  CHECK_THROWS_AS(CGAL::compress_point_cloud<CGAL::Sequential_tag>(points, short_labels, bytes), std::invalid_argument);
  CHECK_THROWS_AS(CGAL::compress_point_cloud<CGAL::Sequential_tag>(points, labels, bytes, sfe::quantization_step(-1.)),
                  std::invalid_argument);
}
