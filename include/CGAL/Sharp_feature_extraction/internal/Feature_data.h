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

/// The angle (degrees) between two nonzero vectors, from the sine and cosine (exact also near
/// 0 and 180).
inline double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)) * 180. / pi; }

/// Noise-to-spacing ratio above which the surfaces of stage 2 are planes: a quadric fitted to
/// noisy points bends towards the other side of a crease.
constexpr double noise_ratio_for_planes = 0.05;

/// Whether the noise dominates the sampling (see `noise_ratio_for_planes`).
inline bool noise_dominates(const Scales& scales)
{
  return scales.noise > noise_ratio_for_planes * scales.spacing;
}

/// The traits the stages compute with: double precision, with Eigen vectors for points and
/// normals. The stages work on the public result types (`Edge_point`, `Feature_polyline`, ...)
/// instantiated with these traits; the public functions give them to the user in the user's
/// kernel (see `Kernel_conversion.h`).
struct Working_traits
{
  typedef double FT;
  typedef Vec3 Point_3;
  typedef Vec3 Vector_3;
};

typedef Edge_point<Working_traits> Working_edge_point;
typedef Corner_point<Working_traits> Working_corner_point;
typedef Feature_point_set<Working_traits> Working_feature_points;
typedef Feature_polyline<Working_traits> Working_polyline;
typedef Feature_corner<Working_traits> Working_corner;
typedef Feature_curve_network<Working_traits> Working_network;
typedef Surface_patches<Working_traits> Working_patches;

/// Whether `curve` is a loop that passes through no corner: it has no ends at all. (A loop
/// through a corner starts and ends there: completion treats its two ends like any others.)
inline bool is_loop_without_corner(const Working_polyline& curve)
{
  return curve.is_closed() && curve.front_corner == no_index;
}

/// Fills `Feature_corner::incident_polylines` from the curves' corner indices (the stages
/// renumber curves and corners freely and index the incidences once, at their end).
template <typename GT>
void index_incident_polylines(Feature_curve_network<GT>& network)
{
  for(Feature_corner<GT>& corner : network.corners)
    corner.incident_polylines.clear();
  for(std::size_t c = 0; c < network.polylines.size(); ++c)
  {
    const Feature_polyline<GT>& curve = network.polylines[c];
    if(curve.front_corner != no_index)
      network.corners[curve.front_corner].incident_polylines.push_back(c);
    if(curve.back_corner != no_index && curve.back_corner != curve.front_corner)
      network.corners[curve.back_corner].incident_polylines.push_back(c);
  }
}

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

/// Whether the normal pairs `a` and `b` match in one order or the other, orientation included:
/// one normal within `cos_near` of its partner, the other within `cos_far` (a looser
/// `match_normal_pairs()`, for pairs where one normal may be badly estimated).
inline bool match_normal_pairs_unevenly(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b, double cos_near,
                                        double cos_far)
{
  auto matches = [&](double first, double second) {
    return (std::max)(first, second) >= cos_near && (std::min)(first, second) >= cos_far;
  };
  return matches(a[0].dot(b[0]), a[1].dot(b[1])) || matches(a[0].dot(b[1]), a[1].dot(b[0]));
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
