// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_FEATURE_DATA_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_FEATURE_DATA_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

typedef Sharp_feature_scales<double> Scales;
constexpr std::size_t no_index = (std::numeric_limits<std::size_t>::max)();
constexpr double pi = 3.14159265358979323846;
inline double radians(double degrees) { return degrees * pi / 180.; }

/// The pipeline's working copies of the public result types, in double precision.
struct Edge_sample
{
  Vec3 point;
  std::array<Vec3, 2> normals;
  std::size_t source = 0;
};

struct Corner_sample
{
  Vec3 point;
  std::array<Vec3, 3> normals;
  double weight = 0;
  std::size_t source = 0;
};

struct Feature_samples
{
  std::vector<Edge_sample> edges;
  std::vector<Corner_sample> corners;
};

struct Curve
{
  std::vector<Vec3> points;
  std::vector<std::array<Vec3, 2>> normals;
  std::size_t front_corner = no_index, back_corner = no_index;
  bool closed = false;
};

struct Corner_node
{
  Vec3 point;
  std::vector<Vec3> normals;
};

struct Curve_network
{
  std::vector<Curve> curves;
  std::vector<Corner_node> corners;
};

/// How the normal pair `b` matches the pair `a` up to order: 0 no match, 1 same order,
/// 2 swapped. Two normals match when they are within `cos_tolerance`, orientation included:
/// edge normals point away from the other surface, so a convex crease never matches a concave
/// one with parallel faces (the two edges of a step).
inline int match_normal_pairs(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b,
                              double cos_tolerance)
{
  const double same = (std::min)(a[0].dot(b[0]), a[1].dot(b[1]));
  const double swapped = (std::min)(a[0].dot(b[1]), a[1].dot(b[0]));
  if((std::max)(same, swapped) < cos_tolerance)
    return 0;
  return same >= swapped ? 1 : 2;
}

/// `b` reordered and flipped so that it follows `a` (for consistent normals along a curve).
inline std::array<Vec3, 2> align_normal_pair(const std::array<Vec3, 2>& a, std::array<Vec3, 2> b)
{
  const double same = std::abs(a[0].dot(b[0])) + std::abs(a[1].dot(b[1]));
  const double swapped = std::abs(a[0].dot(b[1])) + std::abs(a[1].dot(b[0]));
  if(swapped > same)
    std::swap(b[0], b[1]);
  for(int i = 0; i < 2; ++i)
    if(a[i].dot(b[i]) < 0)
      b[i] = -b[i];
  return b;
}

/// Normal pairs of two surfaces that belong to one crease differ by at most this angle
/// (degrees); larger differences mean two different creases (e.g. on both sides of a corner).
constexpr double same_crease_normal_angle = 25;

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
