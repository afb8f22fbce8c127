// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A local model of the two surfaces meeting along each feature curve.
//
// Poisson reconstruction (like any smooth implicit fit) rounds creases: its normals come from
// neighbourhoods that straddle the crease, and its function is smooth. The extracted curves
// know better: every vertex carries the normals of the two surfaces that meet there. This
// model turns them into two small quadric patches per curve sample, fitted to the input points
// of each side, and uses them twice:
//  - normal correction: a point near a crease gets the normal of the patch of its own side
//    instead of the jet normal averaged across the crease;
//  - crease sharpening: near a curve, the implicit function becomes max (convex crease) or min
//    (concave crease) of the two patches' signed distances, so that its zero set has the true
//    crease, and the protected curve vertices lie on it.
// Far from the curves the model says nothing and the smooth function is used unchanged; in
// between, the two are blended.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_CREASE_MODEL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_CREASE_MODEL_H

#include <CGAL/Sharp_feature_extraction/internal/Spatial_grid.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace reconstruction {

/// Radii of the crease model, as absolute distances. `for_spacing()` gives the defaults as
/// multiples of the sampling spacing s (mean distance to the 6th nearest neighbour).
struct Crease_model_options
{
  /// Curves are resampled at most this far apart (default s/2).
  double sample_step = 0;
  /// Input points within this distance of a curve sample are fitted to its two patches (5 s:
  /// about 40 points per side, enough for a quadric, small enough for a quadric to be right).
  double fit_radius = 0;
  /// Points closer than this to a curve get the normal of their side (2.5 s: the radius of
  /// an 18-point jet neighbourhood, i.e. the points whose jet fit straddles the crease).
  double normal_radius = 0;
  /// Within this distance of a curve the implicit function is the crease model alone (3 s).
  double blend_inner = 0;
  /// Beyond this distance it is the smooth function alone (5 s).
  double blend_outer = 0;

  static Crease_model_options for_spacing(double s)
  {
    Crease_model_options o;
    o.sample_step = 0.5 * s;
    o.fit_radius = 5 * s;
    o.normal_radius = 2.5 * s;
    o.blend_inner = 3 * s;
    o.blend_outer = 5 * s;
    return o;
  }
};

template <typename GeomTraits>
class Crease_model
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  /// One side of a crease at a curve sample: the surface n.(x - c) = q(u, v) in the frame
  /// (t, d, n), with u = t.(x - c) along the crease and v = d.(x - c) > 0 into the side.
  struct Side
  {
    Vector_3 n, d;
    std::array<double, 6> q{{0, 0, 0, 0, 0, 0}}; // coefficients of u^2, uv, v^2, u, v, 1
    double rms = 0;                          // residual of the fit
    std::size_t support = 0;                 // number of points fitted
  };

  struct Sample
  {
    Point_3 c;
    Vector_3 t;
    std::array<Side, 2> sides;
    std::size_t curve = 0;
    /// Both sides fitted to enough points. A side without them keeps the plane through the
    /// curve point normal to the curve's own normal: no model of the data (on a spurious curve
    /// across a smooth surface one side may find no points of its own).
    bool fitted = false;
    /// Near the end of an open curve: the end and the tangent pointing out of the curve.
    /// The two-surface model does not hold beyond the end (at a corner a third surface
    /// takes over), so points on the far side of the plane through the end, normal to the
    /// tangent, are not modelled.
    bool near_end = false;
    Point_3 end;
    Vector_3 out;

    bool is_beyond_end(const Point_3& x) const
    {
      return near_end && CGAL::to_double((x - end) * out) > 0;
    }

    /// 1 up to the plane through the end (or away from any end), 0 from `width` beyond it,
    /// smooth in between. The end itself keeps the full model: it is a protected vertex, and
    /// the implicit surface must pass through it (a protected vertex off the surface by more
    /// than the facet distance makes Mesh_3 refine onto its protecting ball without end).
    double before_end(const Point_3& x, double width) const
    {
      if(!near_end)
        return 1;
      const double r = 1 - CGAL::to_double((x - end) * out) / width;
      return r >= 1 ? 1. : (r <= 0 ? 0. : r * r * (3 - 2 * r));
    }
  };

  /// fits the patches of every curve that has normals to `points` (curves without normals
  /// are ignored). Normal orientation is the curves' own until `orient()` is called.
  Crease_model(const std::vector<CGAL::Feature_polyline<GeomTraits>>& curves,
               const std::vector<Point_3>& points, const Crease_model_options& options)
    : m_options(options), m_kernel_radius(options.blend_outer + options.sample_step),
      m_samples_grid(m_kernel_radius), m_number_of_curves(curves.size()),
      m_convex(curves.size(), true)
  {
    resample(curves);
    Spatial_grid<Point_3> point_grid(m_options.fit_radius);
    for(std::size_t i = 0; i < points.size(); ++i)
      point_grid.insert(points[i], i);
    for(Sample& s : m_samples)
      fit(s, points, point_grid);
    for(std::size_t i = 0; i < m_samples.size(); ++i)
      m_samples_grid.insert(m_samples[i].c, i);
  }

  const std::vector<Sample>& samples() const { return m_samples; }
  const Crease_model_options& options() const { return m_options; }
  bool is_convex(std::size_t curve) const { return m_convex[curve]; }

  /// The normal of the side `p` lies on, if `p` is within `normal_radius` of a curve and
  /// clearly on one of its two sides; unoriented until `orient()` has been called.
  bool side_normal(const Point_3& p, Vector_3& normal) const
  {
    int side = 0;
    const Sample* s = side_of(p, m_options.normal_radius, side);
    if(s == nullptr)
      return false;
    normal = patch_normal(*s, side, p);
    return true;
  }

  /// moves `p` (a point on or near a curve) onto the intersection of the two patches of the
  /// nearest curve sample: the crease of the implicit surface. Returns false, leaving `p`, if
  /// there is no usable sample, if the patches are nearly parallel (a fading crease), or if the
  /// move would exceed `max_move`.
  bool project_onto_crease(Point_3& p, double max_move) const
  {
    const std::size_t i = m_samples_grid.nearest_within(p, m_options.blend_outer);
    if(i == Spatial_grid<Point_3>::none)
      return false;
    const Sample& s = m_samples[i];
    if(!s.fitted)
      return false;
    Point_3 x = p;
    for(int iteration = 0; iteration < 20; ++iteration) {
      // minimal step solving the linearised g0 = g1 = 0
      const Vector_3 a = patch_gradient(s, 0, x), b = patch_gradient(s, 1, x);
      const double g0 = signed_distance(s, 0, x), g1 = signed_distance(s, 1, x);
      const double aa = CGAL::to_double(a * a), ab = CGAL::to_double(a * b), bb = CGAL::to_double(b * b);
      const double det = aa * bb - ab * ab;
      if(det < 1e-4 * aa * bb) // normals within about half a degree
        return false;
      const double la = (-g0 * bb + g1 * ab) / det, lb = (-g1 * aa + g0 * ab) / det;
      const Vector_3 step = la * a + lb * b;
      x = x + step;
      if(CGAL::to_double(step.squared_length()) < CGAL::square(1e-6 * m_options.sample_step))
        break;
    }
    if(CGAL::to_double(CGAL::squared_distance(x, p)) > CGAL::square(max_move))
      return false;
    p = x;
    return true;
  }

  /// flips the sides of each curve so that their normals point outward, by majority vote of
  /// the oriented `normals` of the points near the curve, then decides per curve whether the
  /// crease is convex (the solid is the intersection of the two sides' inner half-spaces) or
  /// concave (their union).
  void orient(const std::vector<Point_3>& points, const std::vector<Vector_3>& normals)
  {
    std::vector<std::array<double, 2>> votes(m_number_of_curves, {{0., 0.}});
    std::vector<std::pair<const Sample*, int>> located(points.size(), {nullptr, 0});
    for(std::size_t i = 0; i < points.size(); ++i) {
      int side = 0;
      const Sample* s = side_of(points[i], m_options.normal_radius, side);
      if(s == nullptr)
        continue;
      located[i] = std::make_pair(s, side);
      votes[s->curve][side] += CGAL::to_double(normals[i] * s->sides[side].n) > 0 ? 1 : -1;
    }
    for(Sample& s : m_samples)
      for(int k = 0; k < 2; ++k)
        if(votes[s.curve][k] < 0) {
          s.sides[k].n = -s.sides[k].n;
          for(double& c : s.sides[k].q)
            c = -c;
        }
    // convex if the points of each side are inside the other side's surface
    std::vector<double> convexity(m_number_of_curves, 0.);
    for(std::size_t i = 0; i < points.size(); ++i)
      if(located[i].first != nullptr) {
        const Sample& s = *located[i].first;
        const int other = 1 - located[i].second;
        convexity[s.curve] += signed_distance(s, other, points[i]) < 0 ? 1 : -1;
      }
    for(std::size_t c = 0; c < m_number_of_curves; ++c)
      m_convex[c] = convexity[c] >= 0;
  }

  /// The crease model's signed distance at `x` (negative inside) and its weight in the blend
  /// with the smooth function: 1 within `blend_inner` of a curve, 0 beyond `blend_outer`, and
  /// fading to 0 past an open end. Both are continuous in `x`: the signed distance is the
  /// average of the samples' two-patch models, each weighted by a kernel that vanishes a little
  /// beyond `blend_outer`. (The model of the nearest sample alone jumps where the nearest sample
  /// changes, by the difference between two noisy fits; where such jumps of either sign meet,
  /// the zero set pinches into a point that is not a manifold, and Mesh_3's manifold
  /// refinement converges onto it with ever smaller facets.)
  double value(const Point_3& x, double& weight) const
  {
    weight = 0;
    const double radius2 = CGAL::square(m_kernel_radius);
    double nearest2 = radius2, mass = 0, kept_mass = 0, sum = 0;
    m_samples_grid.for_each_within(x, m_kernel_radius, [&](std::size_t i, double d2) {
      const Sample& s = m_samples[i];
      nearest2 = (std::min)(nearest2, d2);
      const double k = CGAL::square(1 - d2 / radius2);
      mass += k;
      // an unfitted sample counts in the mass only: the model fades where it has no data
      const double kept = s.fitted ? k * s.before_end(x, m_options.sample_step) : 0.;
      if(kept <= 0)
        return;
      const double g0 = signed_distance(s, 0, x), g1 = signed_distance(s, 1, x);
      sum += kept * (m_convex[s.curve] ? (std::max)(g0, g1) : (std::min)(g0, g1));
      kept_mass += kept;
    });
    if(kept_mass <= 0)
      return 0;
    const double r = (std::sqrt(nearest2) - m_options.blend_inner) / (m_options.blend_outer - m_options.blend_inner);
    weight = (r <= 0 ? 1. : (r >= 1 ? 0. : 1. - r * r * (3 - 2 * r))) * kept_mass / mass;
    return sum / kept_mass;
  }

  /// signed distance (approximately: the height above the patch) from `x` to side `k` of `s`.
  static double signed_distance(const Sample& s, int k, const Point_3& x)
  {
    const Side& side = s.sides[k];
    const Vector_3 w = x - s.c;
    const double u = CGAL::to_double(w * s.t), v = CGAL::to_double(w * side.d);
    const double h = CGAL::to_double(w * side.n);
    const std::array<double, 6>& q = side.q;
    return h - (q[0] * u * u + q[1] * u * v + q[2] * v * v + q[3] * u + q[4] * v + q[5]);
  }

private:
  static Vector_3 unit(const Vector_3& v)
  {
    const double l = std::sqrt(CGAL::to_double(v.squared_length()));
    return l > 0 ? v / l : v;
  }

  void resample(const std::vector<CGAL::Feature_polyline<GeomTraits>>& curves)
  {
    for(std::size_t c = 0; c < curves.size(); ++c) {
      const auto& curve = curves[c];
      if(curve.normals.size() != curve.points.size() || curve.points.size() < 2)
        continue;
      for(std::size_t i = 0; i + 1 < curve.points.size(); ++i) {
        const Point_3& a = curve.points[i];
        const Point_3& b = curve.points[i + 1];
        const Vector_3 ab = b - a;
        const double length = std::sqrt(CGAL::to_double(ab.squared_length()));
        if(length == 0)
          continue;
        const std::size_t steps = (std::max)(std::size_t(1),
          static_cast<std::size_t>(std::ceil(length / m_options.sample_step)));
        for(std::size_t j = 0; j < steps; ++j) {
          const double lambda = (j + 0.5) / steps;
          Sample s;
          s.c = a + lambda * ab;
          s.t = ab / length;
          s.curve = c;
          for(int k = 0; k < 2; ++k) {
            // normals are consistent along a curve: interpolate, then make them normal to t
            Vector_3 n = (1 - lambda) * curve.normals[i][k] + lambda * curve.normals[i + 1][k];
            n = unit(n - (n * s.t) * s.t);
            s.sides[k].n = n;
            s.sides[k].d = unit(CGAL::cross_product(s.t, n));
          }
          m_samples.push_back(s);
        }
      }
      mark_ends(curve, c);
    }
  }

  /// flags the samples of `curve` (the last ones pushed) within `blend_outer` of an open end.
  void mark_ends(const CGAL::Feature_polyline<GeomTraits>& curve, std::size_t c)
  {
    if(curve.points.front() == curve.points.back())
      return;
    const Point_3& front = curve.points.front();
    const Point_3& back = curve.points.back();
    const Vector_3 front_out = unit(curve.points[0] - curve.points[1]);
    const Vector_3 back_out = unit(curve.points.back() - curve.points[curve.points.size() - 2]);
    const double reach2 = CGAL::square(2 * m_options.blend_outer);
    for(std::size_t i = m_samples.size(); i-- > 0 && m_samples[i].curve == c;) {
      Sample& s = m_samples[i];
      const double df = CGAL::to_double(CGAL::squared_distance(s.c, front));
      const double db = CGAL::to_double(CGAL::squared_distance(s.c, back));
      if((std::min)(df, db) > reach2)
        continue;
      s.near_end = true;
      s.end = df < db ? front : back;
      s.out = df < db ? front_out : back_out;
    }
  }

  /// assigns the points around `s` to the side whose plane they are clearly closer to, fits a
  /// quadric to each side, and refits once without the points the first fit calls outliers
  /// (points of a third surface near a corner, or beyond the next crease).
  void fit(Sample& s, const std::vector<Point_3>& points, const Spatial_grid<Point_3>& grid) const
  {
    std::array<std::vector<Vector_3>, 2> offsets;
    grid.for_each_within(s.c, m_options.fit_radius, [&](std::size_t i, double) {
      if(s.is_beyond_end(points[i]))
        return;
      const Vector_3 w = points[i] - s.c;
      const double r0 = std::abs(CGAL::to_double(w * s.sides[0].n));
      const double r1 = std::abs(CGAL::to_double(w * s.sides[1].n));
      // a point must be at least twice closer to its side's plane than to the other one
      if(r0 < 0.5 * r1)
        offsets[0].push_back(w);
      else if(r1 < 0.5 * r0)
        offsets[1].push_back(w);
    });
    for(int k = 0; k < 2; ++k) {
      Side& side = s.sides[k];
      double mean_v = 0;
      for(const Vector_3& w : offsets[k])
        mean_v += CGAL::to_double(w * side.d);
      if(mean_v < 0)
        side.d = -side.d;
      std::vector<Vector_3> kept;
      for(const Vector_3& w : offsets[k])
        if(CGAL::to_double(w * side.d) > 0)
          kept.push_back(w);
      fit_side(s.t, side, kept);
      // refit without the outliers of the first fit (3 robust standard deviations)
      std::vector<double> residuals;
      for(const Vector_3& w : kept)
        residuals.push_back(std::abs(height_residual(s.t, side, w)));
      if(residuals.size() < minimum_support)
        continue;
      std::vector<double> sorted = residuals;
      std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
      const double limit = 3 * 1.4826 * sorted[sorted.size() / 2] + 1e-3 * m_options.sample_step;
      std::vector<Vector_3> inliers;
      for(std::size_t i = 0; i < kept.size(); ++i)
        if(residuals[i] <= limit)
          inliers.push_back(kept[i]);
      fit_side(s.t, side, inliers);
    }
    s.fitted = s.sides[0].support >= minimum_support && s.sides[1].support >= minimum_support;
  }

  static double height_residual(const Vector_3& t, const Side& side, const Vector_3& w)
  {
    const double u = CGAL::to_double(w * t), v = CGAL::to_double(w * side.d);
    const std::array<double, 6>& q = side.q;
    return CGAL::to_double(w * side.n) - (q[0] * u * u + q[1] * u * v + q[2] * v * v + q[3] * u + q[4] * v + q[5]);
  }

  /// least-squares quadric height field over the side's frame. The constant term is free: the
  /// curve point need not lie on the true crease; `project_onto_crease()` then moves it there.
  static void fit_side(const Vector_3& t, Side& side, const std::vector<Vector_3>& offsets)
  {
    side.q = {{0, 0, 0, 0, 0, 0}};
    side.support = offsets.size();
    if(offsets.size() < minimum_support) {
      side.rms = 0;
      return;
    }
    Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    for(const Vector_3& w : offsets) {
      const double u = CGAL::to_double(w * t), v = CGAL::to_double(w * side.d);
      const double h = CGAL::to_double(w * side.n);
      Eigen::Matrix<double, 6, 1> row;
      row << u * u, u * v, v * v, u, v, 1;
      normal_matrix += row * row.transpose();
      rhs += h * row;
    }
    const Eigen::Matrix<double, 6, 1> x = normal_matrix.ldlt().solve(rhs);
    if(!x.allFinite())
      return;
    for(int i = 0; i < 6; ++i)
      side.q[i] = x(i);
    double sum = 0;
    for(const Vector_3& w : offsets)
      sum += std::pow(height_residual(t, side, w), 2);
    side.rms = std::sqrt(sum / offsets.size());
  }

  /// the nearest sample within `radius` and the side `p` is on; null if none or ambiguous.
  const Sample* side_of(const Point_3& p, double radius, int& side) const
  {
    const std::size_t i = m_samples_grid.nearest_within(p, (std::min)(radius, m_options.blend_outer));
    if(i == Spatial_grid<Point_3>::none)
      return nullptr;
    const Sample& s = m_samples[i];
    if(s.is_beyond_end(p))
      return nullptr;
    if(!s.fitted)
      return nullptr;
    const double g0 = std::abs(signed_distance(s, 0, p)), g1 = std::abs(signed_distance(s, 1, p));
    side = g0 <= g1 ? 0 : 1;
    // a point far from both patches is on a third surface (near a corner): leave it alone
    const double tolerance = 4 * s.sides[side].rms + 0.1 * m_options.sample_step;
    if((std::min)(g0, g1) > tolerance)
      return nullptr;
    return &s;
  }

  static Vector_3 patch_normal(const Sample& s, int k, const Point_3& p)
  {
    return unit(patch_gradient(s, k, p));
  }

  /// gradient of `signed_distance(s, k, .)` at `p`.
  static Vector_3 patch_gradient(const Sample& s, int k, const Point_3& p)
  {
    const Side& side = s.sides[k];
    const Vector_3 w = p - s.c;
    const double u = CGAL::to_double(w * s.t), v = CGAL::to_double(w * side.d);
    const std::array<double, 6>& q = side.q;
    const double dq_du = 2 * q[0] * u + q[1] * v + q[3];
    const double dq_dv = q[1] * u + 2 * q[2] * v + q[4];
    return side.n - dq_du * s.t - dq_dv * side.d;
  }

  // a quadric has 6 coefficients; ask for about twice as many points
  static constexpr std::size_t minimum_support = 10;

  Crease_model_options m_options;
  /// Samples within this distance of a point take part in its crease value: `blend_outer`
  /// plus one sample step, so that wherever the weight is positive (the nearest sample within
  /// `blend_outer`) at least one sample has a positive kernel.
  double m_kernel_radius;
  std::vector<Sample> m_samples;
  Spatial_grid<Point_3> m_samples_grid;
  std::size_t m_number_of_curves;
  std::vector<bool> m_convex;
};

/// The implicit function the mesher sees: the smooth function `Base` (scaled to a distance by
/// `base_scale`, the reciprocal of its gradient norm near the surface), replaced near the
/// curves by the crease model. Negative inside. With no crease model it is `Base` alone.
template <typename GeomTraits, typename Base>
struct Crease_sharpened_function
{
  const Base* base = nullptr;
  const Crease_model<GeomTraits>* creases = nullptr;
  double base_scale = 1;

  double operator()(const typename GeomTraits::Point_3& x) const
  {
    double weight = 0;
    const double crease = creases != nullptr ? creases->value(x, weight) : 0.;
    if(weight >= 1)
      return crease;
    const double smooth = base_scale * CGAL::to_double((*base)(x));
    return weight * crease + (1 - weight) * smooth;
  }
};

} // namespace reconstruction
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_CREASE_MODEL_H
