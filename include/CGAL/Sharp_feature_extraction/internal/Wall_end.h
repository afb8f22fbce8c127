// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 2 under noise: where a thin wall ends. The two sides of a wall a few noise widths thick
// (the rims of rotor and spool) are two parallel planes, or two planes in a narrow wedge, and
// the face that closes the wall is too narrow to hold a plane of its own: the forward search
// finds the two sides and no crease between them. Its two creases are where the sides end,
// and a side ends where its points stop: the centroid of the points of a disc cut by a line
// tells how far from the centre the cut lies.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_WALL_END_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_WALL_END_H

#include <CGAL/Sharp_feature_extraction/internal/Height_field_fit.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

struct Wall_end_constants
{
  /// Two parallel planes whose centroids lie farther than this from each other's plane
  /// (relative to the RMLS tolerance) are the two sides of a wall. Nearer, they are one surface
  /// that the noise split: its points spread over the tolerance on both sides of its plane.
  static constexpr double min_thickness = 1.0;
  /// Where the search also found a third surface (the face a wall stands on), two parallel
  /// planes are taken as the two sides of the wall, rather than one surface split by the noise,
  /// only farther apart than this (relative to the RMLS tolerance): a noisy surface that the
  /// first plane leaves points of beyond the tolerance can give a second plane about one
  /// tolerance off. Spool's F1 at 100k points and 0.5% noise, seeds 1 and 2: 0.974 and 0.957
  /// with 1, 0.972 and 0.971 with 2 (0.973 and 0.970 before); rotor's 0.93 and 0.94 with both.
  static constexpr double min_side_separation = 2.0;
  /// Two planes whose normals lie within this angle (degrees) of each other are parallel
  /// sides, whose distance `min_side_separation` measures. Planes further apart form a wedge, whose
  /// centroids lie off each other's plane by the spread of their members as much as by the
  /// wall (see `narrow_wedge()`). Under 0.5% noise the normals of rotor's concentric sides come
  /// out more than 5 degrees apart: rotor's F1 at 100k points 0.90 with 5, 0.93 with 10; with no
  /// bound, spool's sides 22 degrees apart count too and its F1 falls from 0.973 to 0.963.
  static constexpr double max_side_angle = 10;
  /// A side ends near the candidate if the centroid of its points lies at least this far
  /// (relative to the radius of the disc that the neighbourhood cuts out of its plane) behind
  /// the candidate: the end then lies within 0.45 of that radius (`cut_disc_centroid()`). A
  /// side that goes on has its centroid at the candidate, up to the noise of the centroid of
  /// some 50 points, 0.07 of the radius.
  static constexpr double min_centroid_offset = 0.2;
  /// The plane of a side is refitted over its points at least this far (relative to the RMLS
  /// tolerance) behind the first estimate of its end. The points of the closing face within
  /// the tolerance of the side belong to it and tilt its plane towards the other side near the
  /// end; the selection of the points behind that plane then takes more of them near the end
  /// and fewer far from it, and the end moves out. Rotor's F1 at 100k points and 0.5% noise
  /// (its rim 1.5% dB thick): 0.80 without the refit, 0.85 with a margin of 1, 0.90 with 2.
  static constexpr double refit_margin = 2.0;
  /// Bisection steps that invert `cut_disc_centroid()`: below 1e-15 of the radius.
  static constexpr int bisection_steps = 52;
};

/// The centroid along u of the part u <= t of the unit disc, t in [-1, 1]: its first moment
/// -(2/3) (1 - t^2)^(3/2) over its area acos(-t) + t sqrt(1 - t^2). It rises from -1 (t = -1)
/// through -4 / (3 pi) (half the disc, t = 0) to 0 (the whole disc, t = 1).
inline double cut_disc_centroid(double t)
{
  const double w = std::sqrt((std::max)(0., 1 - t * t));
  const double area = std::acos(-t) + t * w;
  return area > 0 ? -(2. / 3.) * w * w * w / area : -1.;
}

/// The cut t in [-1, 1] of the unit disc whose part u <= t has its centroid at `centroid`
/// (clamped to [-1, 0]): the inverse of `cut_disc_centroid()`, by bisection.
inline double cut_of_disc_centroid(double centroid)
{
  double low = -1, high = 1;
  for(int step = 0; step < Wall_end_constants::bisection_steps; ++step)
  {
    const double middle = 0.5 * (low + high);
    (cut_disc_centroid(middle) < centroid ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

/// The mean of `points[members]` relative to the foot of `p` on `plane`, in that plane.
template <typename IndexRange>
Vec3 in_plane_mean(const std::vector<Vec3>& points, const IndexRange& members, const Height_field& plane, const Vec3& p)
{
  const Vec3 n = plane.normal(p), foot = plane.foot(p);
  Vec3 sum = Vec3::Zero();
  for(std::size_t i : members)
  {
    const Vec3 q = points[i] - foot;
    sum += q - q.dot(n) * n;
  }
  return sum / double((std::max<std::size_t>)(1, members.size()));
}

/// The end of one side of a wall near a candidate.
struct Wall_end
{
  Vec3 point = Vec3::Zero();   ///< where the side ends, on its plane, nearest the candidate
  Vec3 normal = Vec3::Zero();  ///< of the side's plane
  Vec3 outward = Vec3::Zero(); ///< in that plane, away from its points: the closing face's normal
};

/// Where the side of a wall (the points `members` of `points`, with their plane `plane`) ends
/// near the candidate `p`, whose neighbourhood is the ball of radius `radius` about it, along
/// `outward` (projected into the plane). `other_centroid` is the centroid of the other side.
/// Only the points behind the plane (away from the other side) count: those in front of it
/// include the closing face. Returns false if the side does not end near `p` (see
/// `Wall_end_constants::min_centroid_offset`).
class Wall_end_estimate
{
  typedef Wall_end_constants Constants;

public:
  Wall_end_estimate(const std::vector<Vec3>& points, const Vec3& p, double radius, double tolerance)
    : m_points(points), m_p(p), m_radius(radius), m_tolerance(tolerance)
  {}

  template <typename IndexRange>
  bool operator()(const IndexRange& members, const Height_field& plane, const Vec3& other_centroid,
                  const Vec3& outward, Wall_end& end)
  {
    double centroid = 0;
    if(!estimate(members, plane, other_centroid, outward, end, centroid))
      return false;
    // Refit the plane behind the end, out of the reach of the closing face.
    m_inner.clear();
    for(std::size_t i : members)
      if((m_points[i] - end.point).dot(end.outward) <= -Constants::refit_margin * m_tolerance)
        m_inner.push_back(i);
    Local_frame frame;
    Vec3 spread;
    if(!principal_frame(m_points, m_inner, frame, spread))
      return false;
    Height_field refitted;
    refitted.set_plane(frame);
    return estimate(members, refitted, other_centroid, outward, end, centroid)
      && -centroid >= Constants::min_centroid_offset;
  }

private:
  const std::vector<Vec3>& m_points;
  const Vec3 m_p;
  const double m_radius, m_tolerance;
  std::vector<std::size_t> m_inner;

  template <typename IndexRange>
  bool estimate(const IndexRange& members, const Height_field& plane, const Vec3& other_centroid,
                const Vec3& outward, Wall_end& end, double& centroid) const
  {
    end.normal = plane.normal(m_p);
    end.outward = outward - outward.dot(end.normal) * end.normal;
    const double height = plane.height(m_p);
    if(!(end.outward.norm() > 0) || !(m_radius > std::abs(height)))
      return false;
    end.outward.normalize();
    // The ball cuts the plane in a disc about the foot of p.
    const Vec3 foot = plane.foot(m_p);
    const double disc = std::sqrt(m_radius * m_radius - height * height);
    const double front = plane.height(other_centroid) > 0 ? 1. : -1.;
    double sum = 0;
    std::size_t count = 0;
    for(std::size_t i : members)
      if(front * plane.height(m_points[i]) <= 0)
      {
        sum += (m_points[i] - foot).dot(end.outward);
        ++count;
      }
    if(count == 0)
      return false;
    centroid = sum / double(count) / disc;
    end.point = foot + cut_of_disc_centroid(centroid) * disc * end.outward;
    return end.point.allFinite();
  }
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
