// libFuzzer target: the whole pipeline, CGAL::extract_sharp_features(), on small clouds decoded
// from the fuzz bytes. The bytes choose a shape sampled by a seeded generator (none, cube,
// plane, segment, wedge, box volume, sphere, one point) and its size N (0 to a few thousand),
// a noise level, then optional distortions: a scale from 2^-1100 to 2^1100 (tiny, huge and
// overflowing to infinity), a georeferencing offset, a coarse grid (coincident and degenerate
// points), each point repeated, a cluster of coincident points; then optional overrides of the
// neighbourhood sizes and the sharpness angle, always within their valid ranges; last, the
// remaining bytes as points, 24 bytes (three doubles, any bit pattern: NaN, infinities,
// denormals) each. FuzzedDataProvider reads its numbers from the end of the input, little
// endian (corpus/make_seeds.py writes the seeds in that layout).
//
// Besides the sanitizers and CGAL's assertions, it checks what the package documents:
// `std::invalid_argument` exactly when a coordinate is not finite, and a well-formed curve
// network otherwise (finite vertices, one pair of normals per vertex, at least two vertices per
// curve, corners that are the exact end points of their curves).
#include "fuzz_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
namespace sfe = CGAL::Sharp_feature_extraction::parameters;

// A few thousand points keep one run of the pipeline well under a second with the sanitizers.
const std::size_t largest_cloud = 4000;

enum class Shape { none, cube, plane, segment, wedge, box, sphere, one_point, count };

struct Raw_point
{
  double x, y, z;
};

// Point on `shape` for three uniform numbers in [0, 1); the unit is the shape's size.
Raw_point shape_point(Shape shape, double u, double v, double w, double wedge_angle)
{
  const double pi = 3.14159265358979323846;
  switch(shape)
  {
  case Shape::cube:
  {
    const int face = int(w * 6) % 6; // one of 6 faces, u and v on it
    const double side = (face % 2) ? 1 : 0;
    return face < 2 ? Raw_point{side, u, v} : face < 4 ? Raw_point{u, side, v} : Raw_point{u, v, side};
  }
  case Shape::plane: return {u, v, 0};
  case Shape::segment: return {u, 2 * u, 3 * u};
  case Shape::wedge: // two half-planes meeting along the y axis at `wedge_angle`
    return w < 0.5 ? Raw_point{u, v, 0} : Raw_point{u * std::cos(wedge_angle), v, u * std::sin(wedge_angle)};
  case Shape::box: return {u, v, w};
  case Shape::sphere:
  {
    const double z = 2 * u - 1, r = std::sqrt(std::max(0., 1 - z * z)), phi = 2 * pi * v;
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  default: return {0.25, 0.5, 0.75};
  }
}

struct Decoded_input
{
  std::vector<Point_3> points;
  bool finite = true;
  // Overrides (0: derived from the data).
  std::size_t candidate_neighbors = 0, rmls_neighbors = 0;
  double sharpness_angle = 25;
};

Decoded_input decode(FuzzedDataProvider& bytes)
{
  std::vector<Raw_point> raw;
  const Shape shape = Shape(bytes.ConsumeIntegralInRange<int>(0, int(Shape::count) - 1));
  const std::size_t n = bytes.ConsumeIntegralInRange<std::size_t>(0, largest_cloud);
  std::mt19937 generator(bytes.ConsumeIntegral<std::uint32_t>());
  std::uniform_real_distribution<double> uniform(0, 1);
  std::normal_distribution<double> gaussian(0, 1);
  // Noise from 0 to 2^-2 of the shape's size.
  const int noise_exponent = bytes.ConsumeIntegralInRange<int>(-30, -2);
  const double noise = noise_exponent == -30 ? 0 : std::ldexp(1., noise_exponent);
  const double wedge_angle = bytes.ConsumeFloatingPointInRange<double>(0.01, 3.13);
  if(shape != Shape::none)
    for(std::size_t i = 0; i < n; ++i)
    {
      const double u = uniform(generator), v = uniform(generator), w = uniform(generator);
      Raw_point p = shape_point(shape, u, v, w, wedge_angle);
      p.x += noise * gaussian(generator);
      p.y += noise * gaussian(generator);
      p.z += noise * gaussian(generator);
      raw.push_back(p);
    }

  const std::uint8_t flags = bytes.ConsumeIntegral<std::uint8_t>();
  if(flags & 1) // tiny or huge: 2^-1100 is below the smallest denormal, 2^1100 overflows
  {
    const double scale = std::ldexp(1., bytes.ConsumeIntegralInRange<int>(-1100, 1100));
    for(Raw_point& p : raw)
      p = {p.x * scale, p.y * scale, p.z * scale};
  }
  if(flags & 2) // georeferenced: offsets from 1 to 2^80 (1e24)
  {
    const double offset = std::ldexp(1., bytes.ConsumeIntegralInRange<int>(0, 80));
    for(Raw_point& p : raw)
      p = {p.x + offset, p.y - offset, p.z + offset / 2};
  }
  if(flags & 4) // a grid of 2^-k: coincident, coplanar and collinear points
  {
    const double cell = std::ldexp(1., -bytes.ConsumeIntegralInRange<int>(0, 12));
    for(Raw_point& p : raw)
      p = {std::round(p.x / cell) * cell, std::round(p.y / cell) * cell, std::round(p.z / cell) * cell};
  }
  if(flags & 8) // every point repeated
  {
    const std::size_t copies = bytes.ConsumeIntegralInRange<std::size_t>(2, 16);
    std::vector<Raw_point> repeated;
    for(const Raw_point& p : raw)
      for(std::size_t c = 0; c < copies && repeated.size() < largest_cloud; ++c)
        repeated.push_back(p);
    raw.swap(repeated);
  }
  if(flags & 16) // a cluster of coincident points, like a scanner's no-return rays at the origin
  {
    const std::size_t cluster = bytes.ConsumeIntegralInRange<std::size_t>(1, largest_cloud);
    const Raw_point at = raw.empty() ? Raw_point{0, 0, 0} : raw[cluster % raw.size()];
    raw.insert(raw.end(), cluster, at);
  }

  Decoded_input cloud;
  if(bytes.ConsumeBool())
  {
    cloud.candidate_neighbors = bytes.ConsumeIntegralInRange<std::size_t>(0, 64);
    cloud.rmls_neighbors = bytes.ConsumeIntegralInRange<std::size_t>(0, 128);
    cloud.sharpness_angle = bytes.ConsumeFloatingPointInRange<double>(1, 89);
  }
  for(const Raw_point& p : raw)
    cloud.points.emplace_back(p.x, p.y, p.z);
  while(bytes.remaining_bytes() >= 3 * sizeof(double))
  {
    double xyz[3];
    for(double& c : xyz)
    {
      const std::uint64_t bits = bytes.ConsumeIntegral<std::uint64_t>();
      std::memcpy(&c, &bits, sizeof(double));
    }
    cloud.points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for(const Point_3& p : cloud.points)
    cloud.finite = cloud.finite && std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
  return cloud;
}

bool finite(const Point_3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

void check_network(const CGAL::Feature_curve_network<K>& network)
{
  for(const auto& curve : network.polylines)
  {
    SFE_FUZZ_CHECK(curve.points.size() >= 2);
    SFE_FUZZ_CHECK(curve.normals.size() == curve.points.size());
    for(const Point_3& p : curve.points)
      SFE_FUZZ_CHECK(finite(p));
    for(const std::size_t corner : {curve.front_corner, curve.back_corner})
      SFE_FUZZ_CHECK(corner == curve.no_corner || corner < network.corners.size());
    if(curve.front_corner != curve.no_corner)
      SFE_FUZZ_CHECK(network.corners[curve.front_corner].point == curve.points.front());
    if(curve.back_corner != curve.no_corner)
      SFE_FUZZ_CHECK(network.corners[curve.back_corner].point == curve.points.back());
  }
  for(const auto& corner : network.corners)
  {
    SFE_FUZZ_CHECK(finite(corner.point));
    for(const std::size_t c : corner.incident_polylines)
      SFE_FUZZ_CHECK(c < network.polylines.size());
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider bytes(data, size);
  const Decoded_input cloud = decode(bytes);

  CGAL::Sharp_features<K> result;
  try
  {
    CGAL::extract_sharp_features<CGAL::Sequential_tag>(
      cloud.points, result,
      sfe::candidate_neighbors(cloud.candidate_neighbors, sfe::rmls_neighbors(cloud.rmls_neighbors))
        .sharpness_angle(cloud.sharpness_angle));
  }
  catch(const std::invalid_argument&)
  {
    SFE_FUZZ_CHECK(!cloud.finite); // documented: thrown for a non-finite coordinate only
    return 0;
  }
  SFE_FUZZ_CHECK(cloud.finite);
  check_network(result.network);
  return 0;
}
