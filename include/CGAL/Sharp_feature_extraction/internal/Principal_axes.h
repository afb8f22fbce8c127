// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The principal axes of a point set: the one covariance analysis behind the fit frames of
// stages 1 and 2 and the lines of stages 3 to 5.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_PRINCIPAL_AXES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_PRINCIPAL_AXES_H

#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>

#include <Eigen/Dense>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Centroid and principal axes of a point set.
struct Principal_axes
{
  Vec3 centroid = Vec3::Zero();
  /// Unit axes, by ascending variance: `axes.col(0)` is the normal of the best plane,
  /// `axes.col(2)` the direction of the best line.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  /// The variances along the axes (eigenvalues of the covariance divided by the count),
  /// ascending, clamped to 0.
  Vec3 variances = Vec3::Zero();

  /// The share of the largest variance in their sum: 1 for points on a line, 0 when all
  /// coincide.
  double linearity() const
  {
    const double total = variances.sum();
    return total > 0 ? variances[2] / total : 0;
  }
};

/// Running sums of the first and second moments of a point set about a fixed reference
/// point, to which points are added and from which they are removed one at a time: the
/// principal axes of a set that changes by a few points at a time, without a pass over it.
/// The reference should lie close to the points, so that the covariance suffers no
/// cancellation.
class Moment_sums
{
public:
  explicit Moment_sums(const Vec3& reference) : m_reference(reference) {}

  void add(const Vec3& p)
  {
    const Vec3 d = p - m_reference;
    ++m_count;
    m_sum += d;
    m_second_moment.noalias() += d * d.transpose();
  }

  void remove(const Vec3& p)
  {
    const Vec3 d = p - m_reference;
    --m_count;
    m_sum -= d;
    m_second_moment.noalias() -= d * d.transpose();
  }

  std::size_t count() const { return m_count; }

  /// The principal axes of the points added and not removed; false for an empty set.
  bool principal_axes(Principal_axes& out) const
  {
    if(m_count == 0)
      return false;
    const Vec3 mean = m_sum / double(m_count);
    const Eigen::Matrix3d covariance = m_second_moment / double(m_count) - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    out.centroid = m_reference + mean;
    for(int i = 0; i < 3; ++i)
      out.axes.col(i) = solver.eigenvectors().col(i).normalized();
    out.variances = solver.eigenvalues().cwiseMax(0.);
    return true;
  }

private:
  Vec3 m_reference;
  std::size_t m_count = 0;
  Vec3 m_sum = Vec3::Zero();
  Eigen::Matrix3d m_second_moment = Eigen::Matrix3d::Zero();
};

/// The principal axes of `count` points, `point(j)` for `j` in [0, count). One pass: the
/// moments are taken about the first point, which lies close to all the others in a
/// neighbourhood. Returns false for an empty set.
template <typename PointAt>
bool compute_principal_axes(std::size_t count, const PointAt& point, Principal_axes& out)
{
  if(count == 0)
    return false;
  Moment_sums sums(point(0));
  for(std::size_t j = 0; j < count; ++j)
    sums.add(point(j));
  return sums.principal_axes(out);
}

/// The least-squares line through `count` points: their centroid and unit direction; returns
/// its `linearity()`. The direction is not finite when it is undefined (coincident points).
template <typename PointAt>
double fit_principal_line(std::size_t count, const PointAt& point, Vec3& centroid, Vec3& direction)
{
  Principal_axes axes;
  if(!compute_principal_axes(count, point, axes))
  {
    direction = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    return 0;
  }
  centroid = axes.centroid;
  direction = axes.axes.col(2);
  return axes.linearity();
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
