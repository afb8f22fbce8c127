// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_HEIGHT_FIELD_FIT_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_HEIGHT_FIELD_FIT_H

#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// An orthonormal frame: `n` is the normal of the reference plane through `origin`.
struct Local_frame
{
  Vec3 origin = Vec3::Zero(), u = Vec3::UnitX(), v = Vec3::UnitY(), n = Vec3::UnitZ();
};

/// The frame of principal axes `axes`: origin at the centroid, n along the smallest variance,
/// u along the largest.
inline Local_frame principal_frame(const Principal_axes& axes)
{
  Local_frame frame;
  frame.origin = axes.centroid;
  frame.n = axes.axes.col(0);
  frame.u = axes.axes.col(2);
  frame.v = frame.n.cross(frame.u).normalized();
  return frame;
}

/// Principal component frame of `points[indices]`: n along the smallest variance.
/// `spread` receives the variances (ascending). Returns false for fewer than 3 points.
template <typename IndexRange>
bool principal_frame(const std::vector<Vec3>& points, const IndexRange& indices,
                     Local_frame& frame, Vec3& spread)
{
  Principal_axes axes;
  if(indices.size() < 3
     || !compute_principal_axes(indices.size(), [&](std::size_t j) -> const Vec3& { return points[indices[j]]; }, axes))
    return false;
  frame = principal_frame(axes);
  spread = axes.variances;
  return true;
}

/// The weight of a point at `p` in a moving least-squares fit centred at `center`:
/// exp(-|p - center|^2 / bandwidth^2), or 1 (no window) when `bandwidth` is 0.
inline double gaussian_weight(const Vec3& p, const Vec3& center, double bandwidth)
{
  return bandwidth > 0 ? std::exp(-(p - center).squaredNorm() * (1. / (bandwidth * bandwidth))) : 1.;
}

/// A polynomial height field z = f(x, y) of degree 1 or 2 over a local frame: the jet of
/// Monge_via_jet_fitting restricted to what the pipeline needs (residuals, feet, normals),
/// solved in fixed-size storage so that the fits inside the forward search never allocate.
class Height_field
{
public:
  Local_frame frame;
  /// x and y are divided by `scale` before evaluation, to keep the normal equations conditioned.
  double scale = 1;
  /// Coefficients of 1, X, Y, X^2, XY, Y^2 with X = x/scale, Y = y/scale.
  Eigen::Matrix<double, 6, 1> coefficients = Eigen::Matrix<double, 6, 1>::Zero();

  /// Signed distance from `q` to the graph, measured along the frame normal.
  double height(const Vec3& q) const
  {
    const Vec3 d = q - frame.origin;
    // A plane (set_plane(), or a fit of degree 1): one dot product (see `m_plane_gradient`).
    if(m_plane)
      return d.dot(m_plane_gradient) - coefficients[0];
    return d.dot(frame.n) - value(d.dot(frame.u) / scale, d.dot(frame.v) / scale);
  }

  double residual(const Vec3& q) const { return std::abs(height(q)); }

  /// The point of the graph above or below `q` (projection along the frame normal).
  Vec3 foot(const Vec3& q) const
  {
    const Vec3 d = q - frame.origin;
    const double x = d.dot(frame.u), y = d.dot(frame.v);
    return frame.origin + x * frame.u + y * frame.v + value(x / scale, y / scale) * frame.n;
  }

  /// Unit normal of the graph at the foot of `q`, on the side of the frame normal.
  Vec3 normal(const Vec3& q) const
  {
    const Vec3 d = q - frame.origin;
    const double X = d.dot(frame.u) / scale, Y = d.dot(frame.v) / scale;
    const Eigen::Matrix<double, 6, 1>& c = coefficients;
    const double fx = (c[1] + 2 * c[3] * X + c[4] * Y) / scale;
    const double fy = (c[2] + c[4] * X + 2 * c[5] * Y) / scale;
    return (frame.n - fx * frame.u - fy * frame.v).normalized();
  }

  /// The plane of `reference` itself (z = 0). It is the least-squares plane of points whose
  /// principal frame `reference` is (see `principal_frame()`): in that frame their heights
  /// have no mean and no covariance with x and y, so `fit()` of degree 1 would give it too,
  /// up to rounding, at the cost of two passes over the points.
  void set_plane(const Local_frame& reference)
  {
    frame = reference;
    scale = 1;
    coefficients.setZero();
    m_plane = true;
    m_plane_gradient = frame.n;
  }

  /// Least-squares fit of degree `degree` (1 or 2) to `points[indices]` over `reference`.
  /// Falls back to degree 1 when there are too few points for a quadric. Returns false
  /// when there are fewer than 3 points.
  template <typename IndexRange>
  bool fit(const std::vector<Vec3>& points, const IndexRange& indices, const Local_frame& reference,
           int degree)
  {
    return fit(points, indices, reference, degree, [](std::size_t) { return 1.; });
  }

  /// Same, point `points[i]` weighted by `weight(i)` (moving least squares: see
  /// `gaussian_weight()`).
  template <typename IndexRange, typename Weight>
  bool fit(const std::vector<Vec3>& points, const IndexRange& indices, const Local_frame& reference,
           int degree, const Weight& weight)
  {
    frame = reference;
    m_plane = false;
    std::size_t count = 0;
    double extent = 0;
    for(std::size_t i : indices)
    {
      const Vec3 d = points[i] - frame.origin;
      extent = (std::max)(extent, d.dot(frame.u) * d.dot(frame.u) + d.dot(frame.v) * d.dot(frame.v));
      ++count;
    }
    if(count < 3)
      return false;
    scale = extent > 0 ? std::sqrt(extent) : 1.;
    const int unknowns = (degree >= 2 && count >= minimum_points_for_quadric) ? 6 : 3;

    // The normal matrix of the monomials 1, X, Y, X^2, XY, Y^2 only holds the 15 moments
    // sum w X^a Y^b (a + b <= 4): accumulate those and the 6 right-hand sides, then assemble.
    double moment[15] = {0};     // 1 X Y XX XY YY XXX XXY XYY YYY XXXX XXXY XXYY XYYY YYYY
    double weighted_z[6] = {0}; // z, X z, Y z, XX z, XY z, YY z
    const double inverse_scale = 1. / scale;
    for(std::size_t i : indices)
    {
      const Vec3 d = points[i] - frame.origin;
      const double X = d.dot(frame.u) * inverse_scale, Y = d.dot(frame.v) * inverse_scale;
      const double z = d.dot(frame.n);
      const double w = weight(i);
      const double wX = w * X, wY = w * Y;
      moment[0] += w; moment[1] += wX; moment[2] += wY;
      moment[3] += wX * X; moment[4] += wX * Y; moment[5] += wY * Y;
      weighted_z[0] += w * z; weighted_z[1] += wX * z; weighted_z[2] += wY * z;
      if(unknowns == 6)
      {
        const double XX = X * X, XY = X * Y, YY = Y * Y;
        moment[6] += wX * XX; moment[7] += wX * XY; moment[8] += wX * YY; moment[9] += wY * YY;
        moment[10] += wX * X * XX; moment[11] += wX * X * XY; moment[12] += wX * X * YY; moment[13] += wX * Y * YY;
        moment[14] += wY * Y * YY;
        weighted_z[3] += w * XX * z; weighted_z[4] += w * XY * z; weighted_z[5] += w * YY * z;
      }
    }
    // moment index of the product of monomials a and b (a, b in 0..5)
    static constexpr int product_moment[6][6] = {{0, 1, 2, 3, 4, 5},     {1, 3, 4, 6, 7, 8},
                                                 {2, 4, 5, 7, 8, 9},     {3, 6, 7, 10, 11, 12},
                                                 {4, 7, 8, 11, 12, 13},  {5, 8, 9, 12, 13, 14}};
    Eigen::Matrix<double, 6, 6> normal_matrix;
    Eigen::Matrix<double, 6, 1> rhs;
    for(int a = 0; a < 6; ++a)
    {
      rhs[a] = weighted_z[a];
      for(int b = 0; b < 6; ++b)
        normal_matrix(a, b) = moment[product_moment[a][b]];
    }
    // Ridge term relative to the matrix size: keeps nearly collinear neighbourhoods solvable,
    // and is negligible (1e-9 of the unit-scaled moments) on well spread ones.
    const double ridge = 1e-9 * double(count);
    coefficients.setZero();
    if(unknowns == 6)
    {
      normal_matrix.diagonal().array() += ridge;
      coefficients = solve_normal_equations(normal_matrix, rhs);
    }
    else
    {
      Eigen::Matrix3d m = normal_matrix.topLeftCorner<3, 3>();
      m.diagonal().array() += ridge;
      coefficients.head<3>() = solve_normal_equations(m, Eigen::Vector3d(rhs.head<3>()));
    }
    if(!coefficients.allFinite())
    {
      coefficients.setZero();
      return false;
    }
    if(unknowns == 3)
    {
      m_plane = true;
      m_plane_gradient = frame.n - (coefficients[1] * frame.u + coefficients[2] * frame.v) * inverse_scale;
    }
    return true;
  }

  static constexpr std::size_t minimum_points_for_quadric = 10;

private:
  /// Whether the graph is a plane (`set_plane()`, or `fit()` of degree 1): its height is then
  /// the linear function (q - origin) . `m_plane_gradient` - c0, with the gradient
  /// n - (c1 u + c2 v) / scale, which `height()` evaluates in one dot product instead of three
  /// and a polynomial. The refinement of stage 2 under noise evaluates the heights of its
  /// planes four times per point and round: fandisk at 500k points and 0.5% noise, stage 2
  /// 5.05 -> 4.61 s with 2 threads (same F1, curves equal up to rounding).
  bool m_plane = false;
  Vec3 m_plane_gradient = Vec3::UnitZ();

  /// Cholesky factorization of the (symmetric, positive semi-definite) normal matrix; the
  /// pivoting LDLT factorization when it is not numerically positive definite.
  template <typename Matrix, typename Vector>
  static Vector solve_normal_equations(const Matrix& normal_matrix, const Vector& rhs)
  {
    Eigen::LLT<Matrix> cholesky(normal_matrix);
    if(cholesky.info() == Eigen::Success)
      return cholesky.solve(rhs);
    return normal_matrix.ldlt().solve(rhs);
  }

  double value(double X, double Y) const
  {
    const Eigen::Matrix<double, 6, 1>& c = coefficients;
    return c[0] + c[1] * X + c[2] * Y + c[3] * X * X + c[4] * X * Y + c[5] * Y * Y;
  }
};

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
