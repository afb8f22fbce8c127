// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 2 (paper 3.3): robust moving least squares. A forward search splits the neighbourhood
// of each candidate into the smooth surfaces that meet there; the candidate is then projected
// onto the intersection of the two closest surfaces (edge point) and of three (corner point).

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RMLS_PROJECTION_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RMLS_PROJECTION_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/All_nearest_neighbors.h>
#include <CGAL/Sharp_feature_extraction/internal/Indexed_input.h>
#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Height_field_fit.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Wall_end.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Forward search constants (counts of points unless stated).
struct Forward_search_constants
{
  // Points in a seed subset: on clean data (quadric surfaces) just enough for a quadric and
  // small enough to fit between the two sides of a thin wall; on noisy data (planes) more
  // points average the noise out.
  static constexpr std::size_t quadric_seed_size = 12;
  static constexpr std::size_t plane_seed_size = 20;
  static constexpr std::size_t seed_trials = 8;         // seed subsets tried per surface
  static constexpr double batch_fraction = 0.2;         // largest batch added, relative to the set
  static constexpr std::size_t max_growth_steps = 60;
  static constexpr std::size_t max_surfaces = 3;
  static constexpr double min_surface_fraction = 0.1;   // of the neighbourhood
  static constexpr std::size_t min_surface_points = 8;
  static constexpr double max_support_gap = 0.5;        // member-to-e distance, relative to the radius
  static constexpr std::size_t max_newton_steps = 50;
  static constexpr double newton_step_tolerance = 1e-4; // relative to the sampling spacing
  /// Rounds of the competitive refinement, at most: it stops when no point changes surface.
  /// Exact quadrics settle in one or two rounds. Under noise each round moves the planes a
  /// little as the crease band is reassigned: measured on fandisk at 1% noise, the share of
  /// projected points farther than 1% dB from the true crease falls from 8% after 3 rounds to
  /// 2.5% after 8 and stays there.
  static constexpr std::size_t quadric_refinement_rounds = 3;
  static constexpr std::size_t plane_refinement_rounds = 16;
  /// Gaussian weights of the refined fits, centred at the candidate (moving least squares):
  /// bandwidth relative to the neighbourhood radius. The planes of noisy data use the larger
  /// neighbourhoods of the noise, and a narrower window keeps the curvature of the faces and
  /// the neighbouring creases out of them (bandwidth 0.5 against 0.8: mean F1 over the nine
  /// benchmark parts at 1% noise 0.78 against 0.74).
  static constexpr double quadric_fit_bandwidth = 0.8;
  static constexpr double plane_fit_bandwidth = 0.5;
  /// In every round of the refinement, two noisy half-planes whose normals are more than 60
  /// degrees apart (|cos| below this) share the points near their crease line (see
  /// `Forward_search::share_between_halves()`). Given to the nearer half-plane alone, those
  /// points bias both planes away from the side where the noise of the two faces overlaps:
  /// measured on the edge points of CGAL's fandisk, pinion and rotor at 100k points and 1%
  /// noise, 0.11, 0.25 and 0.23% dB along the bisector of the normals; shared at every
  /// crease, -0.02, 0.11 and 0.19. Across a shallower crease the two planes nearly coincide, a
  /// point near the crease is about as likely under either, and sharing blurs one plane into
  /// the other: shared at every crease, the mean F1 of the nine benchmark parts at 0.5% noise
  /// fell from 0.978 to 0.976 (rotor 0.945 -> 0.912); across steep creases only, it rose to
  /// 0.979 (seeds 1 and 2, 100k points).
  static constexpr double max_shared_crease_cos = 0.5;
  /// The noise deviation of those shares, relative to the tolerance: 1/3, that is 0.75 times
  /// the measured noise (the tolerance is 2.25 times it). Bias along the bisector on fandisk,
  /// pinion and rotor at 1% noise, shared at every crease (see `max_shared_crease_cos`): 0.075,
  /// 0.207, 0.224% dB with a deviation of 0.22 times the tolerance, -0.024, 0.107, 0.191 with
  /// 1/3, -0.133, -0.005, 0.127 with 0.44 (fandisk overcorrected, its F1 0.936 -> 0.906).
  static constexpr double shared_noise_per_tolerance = 1. / 3;
  /// A point whose log-likelihood under one half-plane exceeds its other one by more than this
  /// goes to the first alone (the other's share is below 1e-5).
  static constexpr double unshared_log_likelihood_gap = 12;
  /// Nor does a point this many noise deviations outside the other half-plane, beyond its
  /// crease line, share it: the tolerance gave it to its own, and the other's share is below
  /// 1e-6.
  static constexpr double unshared_deviations_past_line = 6;
  /// A plane split along a crease (`Forward_search::split_across_crease()`) stands only if its
  /// two sides' planes leave at most this share of its sum of squared heights: the crease must
  /// stand out of the noise. Over n points of noise variance s^2 on a crease whose tilted plane
  /// misfits by m^2 on average, the plane leaves n (s^2 + m^2) and the sides n s^2: the split
  /// needs m^2 >= 0.43 s^2. Without this bound, the split took the mean F1 of the nine benchmark
  /// parts at 200k points and 1% noise from 0.816 to 0.779 (2 to 4 times as many edge points,
  /// less precise); with it, to 0.817.
  static constexpr double split_residual_ratio = 0.7;
  /// A crease split off one plane (see `find_surfaces()`) stands only if the points nearest the
  /// candidate, this many times as many as its stage-2 neighbourhood (twice its radius), split
  /// too, along a line that passes within the candidate's stage-1 radius. Across a shallow
  /// crease a quadric bends and fits nearly as well as the two planes, and on a surface curved
  /// at about twice the radius two planes fit about as well as a quadric: at 0.5% dB noise and
  /// 30,000 points the sides' planes beat the quadric by 5 to 40 noise variances (sums of
  /// squared heights) across creases of 30 and 35 degrees and by 0 to 20 inside a cylinder of
  /// 6% dB radius, which then gave 12 to 24 curves. Twice as wide, the quadric's misfit across
  /// the crease grows as the fourth power of the radius (times the points), the planes' misfit
  /// on the cylinder as the sixth: the wider split rejected 98% of the cylinder's splits and
  /// none of the creases'. Where the wider neighbourhood reaches across a bore, its two planes
  /// are the bore's opposite walls and meet far from the candidate: without the line's bound,
  /// CGAL's joint at 1% dB noise had curves inside its bore (F1 0.970 -> 0.933; with it, 0.963).
  static constexpr std::size_t split_confirmation_neighbors_factor = 4;
};

/// One smooth surface found by the forward search.
struct Rmls_surface
{
  Height_field height_field;
  std::vector<std::size_t> members; // local indices into the neighbourhood
  Vec3 centroid = Vec3::Zero();
};

/// Two planes whose normals make an angle with a squared sine below this (0.006 degrees) are
/// parallel: their line of intersection is undefined.
constexpr double parallel_planes_squared_sine = 1e-8;

/// Closest point to `q` on the line where the planes (a, na) and (b, nb) meet.
/// Returns false if the planes are nearly parallel.
inline bool closest_on_plane_intersection(const Vec3& q, const Vec3& a, const Vec3& na,
                                          const Vec3& b, const Vec3& nb, Vec3& out)
{
  // x = q + la * na + lb * nb with na.x = na.a and nb.x = nb.b.
  const double c = na.dot(nb);
  const double det = 1 - c * c;
  if(det < parallel_planes_squared_sine)
    return false;
  const double ra = na.dot(a - q), rb = nb.dot(b - q);
  const double la = (ra - c * rb) / det, lb = (rb - c * ra) / det;
  out = q + la * na + lb * nb;
  return out.allFinite();
}

/// The line where the planes `a` and `b` meet, at its point nearest `center`, and in each plane
/// the direction from that line towards the plane's centroid (not normalized). Returns false if
/// the planes are nearly parallel.
inline bool directions_from_crease_line(const Rmls_surface& a, const Rmls_surface& b, const Vec3& center,
                                        Vec3& line_point, std::array<Vec3, 2>& towards)
{
  const Vec3 na = a.height_field.normal(center), nb = b.height_field.normal(center);
  if(!closest_on_plane_intersection(center, a.height_field.foot(center), na, b.height_field.foot(center), nb, line_point))
    return false;
  const Vec3 t = na.cross(nb).normalized();
  const Rmls_surface* s[2] = {&a, &b};
  const Vec3 n[2] = {na, nb};
  for(int k = 0; k < 2; ++k)
  {
    const Vec3 d = s[k]->centroid - line_point;
    towards[k] = d - d.dot(t) * t - d.dot(n[k]) * n[k];
  }
  return true;
}

/// The per-thread workspace and algorithm of the forward search.
class Forward_search
{
  typedef Forward_search_constants Constants;

public:
  std::vector<Vec3> local;          // the neighbourhood, nearest to the candidate first
  std::vector<Rmls_surface> surfaces;
  /// How many points of `local` stand in its radius for one point counted by the neighbourhood
  /// sizes of the scales: 1, or `sampled_fraction / search_fraction` once `local` holds the
  /// sampled points that the means stand for (see `refine_on_sampled_points()`).
  double points_per_counted_point = 1;
  /// Whether the last `find_surfaces()` on this search split its two planes off one plane (see
  /// `split_across_crease()`): such a crease must stand in a wider neighbourhood too (see
  /// `Forward_search_constants::split_confirmation_neighbors_factor`).
  bool split_off_crease = false;

  /// The centre of the neighbourhood: its point nearest to the candidate (the candidate itself,
  /// unless `local` holds the sampled points that the means stand for).
  const Vec3& center() const { return local.front(); }
  /// The radius of the neighbourhood: the distance from its centre to its farthest point.
  double radius() const { return (local.back() - local.front()).norm(); }

  /// The fewest members of a surface that the search accepts in a neighbourhood of `n` points.
  static std::size_t smallest_surface(std::size_t n)
  {
    return (std::max)(Constants::min_surface_points, std::size_t(Constants::min_surface_fraction * double(n)));
  }

  /// Splits `local` into at most three smooth surfaces with tolerance `tolerance`. The search
  /// grows planes (`degree` 1): a quadric can bend across a shallow crease while it grows.
  void run(double tolerance, int degree)
  {
    surfaces.clear();
    const std::size_t n = local.size();
    m_assigned.assign(n, false);
    const std::size_t min_size = smallest_surface(n);
    while(surfaces.size() < Constants::max_surfaces)
    {
      std::size_t remaining = std::count(m_assigned.begin(), m_assigned.end(), false);
      if(remaining < min_size)
        break;
      Rmls_surface surface;
      if(!find_seed(tolerance, degree, surface.members))
        break;
      grow(tolerance, degree, surface);
      if(surface.members.size() < min_size)
        break;
      for(std::size_t i : surface.members)
        m_assigned[i] = true;
      surface.centroid = centroid_of(surface.members);
      surfaces.push_back(std::move(surface));
    }
  }

  /// Competitive refinement of the surfaces in `set`: every point goes to the surface it fits
  /// best (if within the tolerance) and each surface is refitted. This undoes the greed of the
  /// forward search, where the first surface also takes the points of the next one that lie
  /// within the tolerance near the crease and is biased towards it. Two planes (noisy data)
  /// compete as half-planes, each bounded by their intersection line (see `half_residual()`).
  /// The fits are weighted around `center` with a window relative to the neighbourhood radius,
  /// and the refinement stops when no point changed surface (at most a number of rounds), both
  /// set by the degree (see `Forward_search_constants`). Two half-planes across a steep crease
  /// are fitted with the points near their crease shared (see `share_between_halves()`).
  void refine(std::vector<Rmls_surface*>& set, double tolerance, int degree, const Vec3& center)
  {
    const bool planes = degree == 1;
    const std::size_t rounds = planes ? Constants::plane_refinement_rounds : Constants::quadric_refinement_rounds;
    const double bandwidth = (planes ? Constants::plane_fit_bandwidth : Constants::quadric_fit_bandwidth) * radius();
    // The weights stay the same through the rounds.
    m_weight.resize(local.size());
    for(std::size_t i = 0; i < local.size(); ++i)
      m_weight[i] = gaussian_weight(local[i], center, bandwidth);
    for(std::size_t round = 0; round < rounds; ++round)
    {
      const bool halves = planes && set.size() == 2 && set_halves(*set[0], *set[1], center);
      m_previous.swap(m_owner);
      m_owner.assign(local.size(), no_surface);
      for(Rmls_surface* s : set)
        s->members.clear();
      for(std::size_t i = 0; i < local.size(); ++i)
      {
        double best_residual = tolerance;
        for(std::size_t k = 0; k < set.size(); ++k)
        {
          const double r = halves ? half_residual(*set[k], k, local[i]) : set[k]->height_field.residual(local[i]);
          if(r <= best_residual)
          {
            best_residual = r;
            m_owner[i] = k;
          }
        }
        if(m_owner[i] != no_surface)
          set[m_owner[i]]->members.push_back(i);
      }
      if(round > 0 && m_owner == m_previous)
        break;
      const bool share = halves && tolerance > 0
                         && std::abs(set[0]->height_field.normal(center).dot(set[1]->height_field.normal(center)))
                              < Constants::max_shared_crease_cos;
      if(share)
        share_between_halves(*set[0], *set[1], tolerance);
      for(std::size_t k = 0; k < set.size(); ++k)
      {
        Rmls_surface* s = set[k];
        if(s->members.size() >= 3)
        {
          Local_frame frame;
          Vec3 spread;
          if(principal_frame(local, s->members, frame, spread))
          {
            if(share)
              s->height_field.fit(local, m_sharing[k], frame, degree,
                                  [this, k](std::size_t i) { return m_weight[i] * (k == 0 ? m_share[i] : 1 - m_share[i]); });
            else
              s->height_field.fit(local, s->members, frame, degree, [this](std::size_t i) { return m_weight[i]; });
          }
        }
        s->centroid = centroid_of(s->members);
      }
    }
  }

  /// The members of `kept`, one of `surfaces`, and the points of `local` that no surface took,
  /// with their least-squares plane, in `spanning`; false if they determine no plane. Across a
  /// crease that the search did not part, the far parts of its sides lie beyond the tolerance
  /// of the plane it grew (the points of the other surfaces, parallel to `kept`, may be the
  /// other side of a thin wall and are left out).
  bool with_free_points(const Rmls_surface& kept, Rmls_surface& spanning) const
  {
    spanning.members = kept.members;
    for(std::size_t i = 0; i < local.size(); ++i)
      if(!m_assigned[i])
        spanning.members.push_back(i);
    std::sort(spanning.members.begin(), spanning.members.end());
    return refit(spanning.members, 1, spanning.height_field);
  }

  /// Every point of `local`, with their least-squares plane, in `all`; false if they determine
  /// no plane.
  bool all_points(Rmls_surface& all) const
  {
    all.members.resize(local.size());
    std::iota(all.members.begin(), all.members.end(), std::size_t(0));
    return refit(all.members, 1, all.height_field);
  }

  /// Splits the members of `s`, a plane (noisy data) that may span a crease, into the two sides
  /// of that crease, each with a plane fitted to it, in `a` and `b`; false if they do not split.
  ///
  /// Under noise, the first plane that the search grows around a candidate on a crease often
  /// takes both sides: tilted halfway between the two faces, it holds most points of the
  /// neighbourhood within the tolerance, and what it leaves is a thin slab parallel to it. The
  /// crease then shows in the heights over that plane as a V: a quadric fitted to them bends
  /// most across the crease, and its vertex line along that direction parts the sides. Measured
  /// on fandisk at 100k points and 1% noise: 63% of the candidates within 0.5% dB of a crease
  /// ended that way (first plane 77% of the points, the slab 16% at 6 degrees to it) and gave
  /// no edge point. With the split, 49% of them give one instead of 24%, and the edge points
  /// within 0.5% dB of a crease go from 11,332 to 13,545 (85% of all edge points, as before).
  ///
  /// Each side must hold `min_size` members, and the two planes must fit their sides (sum of
  /// squared heights) better than the quadric fits them all, and markedly better than the plane
  /// `s` (see `Forward_search_constants::split_residual_ratio`). On a smooth curved surface the
  /// quadric fits better, and two planes would draw a crease where there is none.
  bool split_across_crease(const Rmls_surface& s, std::size_t min_size, Rmls_surface& a, Rmls_surface& b) const
  {
    Local_frame frame;
    Vec3 spread;
    Height_field quadric;
    if(!principal_frame(local, s.members, frame, spread) || !quadric.fit(local, s.members, frame, 2))
      return false;
    // Heights c0 + c1 X + c2 Y + c3 X^2 + c4 XY + c5 Y^2: along the eigenvector d of their
    // Hessian whose eigenvalue lambda is the largest in absolute value, they vary as
    // c0 + g t + lambda t^2 / 2 with g = (c1, c2).d, and the vertex is at t = -g / lambda.
    const Eigen::Matrix<double, 6, 1>& c = quadric.coefficients;
    Eigen::Matrix2d hessian;
    hessian << 2 * c[3], c[4], c[4], 2 * c[5];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(hessian);
    const int k = std::abs(eigen.eigenvalues()[0]) > std::abs(eigen.eigenvalues()[1]) ? 0 : 1;
    const Eigen::Vector2d d = eigen.eigenvectors().col(k);
    const double lambda = eigen.eigenvalues()[k];
    if(!(std::abs(lambda) > 0))
      return false;
    const double vertex = -(c[1] * d[0] + c[2] * d[1]) / lambda;
    a.members.clear();
    b.members.clear();
    for(std::size_t i : s.members)
    {
      const Vec3 offset = local[i] - frame.origin;
      const double t = (offset.dot(frame.u) * d[0] + offset.dot(frame.v) * d[1]) / quadric.scale;
      (t < vertex ? a : b).members.push_back(i);
    }
    if(a.members.size() < min_size || b.members.size() < min_size)
      return false;
    double sides = 0, curved = 0, flat = 0;
    for(Rmls_surface* side : {&a, &b})
    {
      if(!refit(side->members, 1, side->height_field))
        return false;
      side->centroid = centroid_of(side->members);
      for(std::size_t i : side->members)
        sides += square(side->height_field.height(local[i]));
    }
    for(std::size_t i : s.members)
    {
      curved += square(quadric.height(local[i]));
      flat += square(s.height_field.height(local[i]));
    }
    return sides < curved && sides < Constants::split_residual_ratio * flat;
  }

private:
  static constexpr std::size_t no_surface = std::numeric_limits<std::size_t>::max();
  static double square(double x) { return x * x; }
  // The surface of each point of `local` in the current and the previous refinement round.
  std::vector<std::size_t> m_owner, m_previous;
  std::vector<bool> m_assigned, m_member;
  std::vector<std::size_t> m_free, m_centers, m_seed;
  std::vector<double> m_distance, m_center_distance, m_selection, m_weight;
  std::vector<std::pair<double, std::size_t>> m_ranked;
  // The share of each point of `local` that goes to the first of two half-planes, and the
  // points that each of them fits (see `share_between_halves()`).
  std::vector<double> m_share;
  std::array<std::vector<std::size_t>, 2> m_sharing;
  // A point of the crease line of two planes and, in each plane, the unit direction from the
  // line towards that plane's members: each surface is then a half-plane.
  Vec3 m_line_point = Vec3::Zero();
  std::array<Vec3, 2> m_half_direction;

  // Sets the half-planes of the planes `a` and `b` about their intersection line nearest to
  // `center`; false if the planes are nearly parallel or a centroid lies on the line.
  bool set_halves(const Rmls_surface& a, const Rmls_surface& b, const Vec3& center)
  {
    if(!directions_from_crease_line(a, b, center, m_line_point, m_half_direction))
      return false;
    for(Vec3& u : m_half_direction)
    {
      if(!(u.norm() > 0))
        return false;
      u.normalize();
    }
    return true;
  }

  // Distance from `x` to the half-plane of surface `k` (set by `set_halves()`): its height
  // over the plane on the members' side of the crease line, the distance to the line beyond.
  // Across a shallow crease this separates the sides better than the heights over the whole
  // planes, which meet at a small angle: a point of one side at distance d from the crease
  // lies d sin(angle) from the other plane but d from its half.
  double half_residual(const Rmls_surface& s, std::size_t k, const Vec3& x) const
  {
    const double h = s.height_field.residual(x);
    const double beyond = (x - m_line_point).dot(m_half_direction[k]);
    return beyond >= 0 ? h : std::sqrt(h * h + beyond * beyond);
  }

  // Shares the points of `local` that went to `a` or `b` (see `m_owner`), two half-planes set
  // by `set_halves()`, between them by their likelihoods under noise of deviation `sigma` (see
  // `Forward_search_constants::shared_noise_per_tolerance`): a half-plane's density at x is
  // the noise density of x's height over its plane, times the probability that the noise
  // carried a point of the half-plane as far as x past the crease line. Near the crease, the
  // two faces' noise overlaps on one side and thins out on the other: a point there on the
  // overlapping side, nearer to the other plane than to its own, may be either face's, and
  // giving it wholly to the nearer plane takes the deepest points from each face and biases
  // both planes away from that side. Fills `m_share` (the share of `a`) and `m_sharing`.
  void share_between_halves(const Rmls_surface& a, const Rmls_surface& b, double tolerance)
  {
    // exp() of at most this stays finite.
    static constexpr double max_exponent = 700;
    const double sigma = Constants::shared_noise_per_tolerance * tolerance;
    const std::array<const Rmls_surface*, 2> halves = {{&a, &b}};
    m_share.assign(local.size(), 0.);
    for(std::vector<std::size_t>& sharing : m_sharing)
      sharing.clear();
    for(std::size_t i = 0; i < local.size(); ++i)
    {
      if(m_owner[i] == no_surface)
        continue;
      double share = m_owner[i] == 0 ? 1. : 0.;
      const std::size_t own = m_owner[i], other = 1 - own;
      // How far past the crease line x lies into each half-plane, in noise deviations.
      std::array<double, 2> past_line, exponent, past;
      for(std::size_t k = 0; k < 2; ++k)
        past_line[k] = (local[i] - m_line_point).dot(m_half_direction[k]) / sigma;
      for(std::size_t k = 0; k < 2; ++k)
        exponent[k] = 0.5 * square(halves[k]->height_field.height(local[i]) / sigma);
      if(past_line[other] > -Constants::unshared_deviations_past_line
         && exponent[other] - exponent[own] < Constants::unshared_log_likelihood_gap)
      {
        for(std::size_t k = 0; k < 2; ++k)
          past[k] = 0.5 * std::erfc(-past_line[k] / std::sqrt(2.));
        // share = L_a / (L_a + L_b), with the ratio L_b / L_a kept finite.
        if(!(past[0] > 0))
          share = 0;
        else if(!(past[1] > 0))
          share = 1;
        else
          share = 1. / (1. + past[1] / past[0] * std::exp((std::min)(exponent[0] - exponent[1], max_exponent)));
      }
      m_share[i] = share;
      if(share > 0)
        m_sharing[0].push_back(i);
      if(share < 1)
        m_sharing[1].push_back(i);
    }
  }

  // Least-residual seed: planes through small subsets around a few well spread centres.
  bool find_seed(double tolerance, int degree, std::vector<std::size_t>& seed)
  {
    m_free.clear();
    for(std::size_t i = 0; i < local.size(); ++i)
      if(!m_assigned[i])
        m_free.push_back(i);
    // Smaller seeds when what is left may hold two small surfaces (near corners), but enough
    // points to determine the fit.
    const std::size_t smallest = degree >= 2 ? Height_field::minimum_points_for_quadric : Constants::min_surface_points;
    // Plane seeds (noisy data) hold at least the smallest surface the search accepts: the
    // neighbourhood grows with the noise, and so must the seed for its plane to tilt no more
    // than the noise allows (the tilt error of a plane fit falls as 1/sqrt(points)).
    const std::size_t seed_size = degree >= 2
      ? Constants::quadric_seed_size
      : (std::max)(Constants::plane_seed_size, std::size_t(Constants::min_surface_fraction * double(local.size())));
    const std::size_t size = (std::min)(m_free.size(), (std::max)(smallest, (std::min)(seed_size, m_free.size() / 3)));
    // Farthest point sampling of the centres, starting from the free point nearest the candidate;
    // the distances of the free points to each centre are kept for the seed selection below.
    const std::size_t free_count = m_free.size();
    const std::size_t center_count = (std::min)(Constants::seed_trials, free_count);
    m_centers.assign(1, 0);
    m_distance.assign(free_count, std::numeric_limits<double>::infinity());
    m_center_distance.resize(center_count * free_count);
    for(std::size_t c = 0; c < center_count; ++c)
    {
      const Vec3& center = local[m_free[m_centers[c]]];
      double* row = &m_center_distance[c * free_count];
      std::size_t farthest = 0;
      for(std::size_t j = 0; j < free_count; ++j)
      {
        row[j] = (local[m_free[j]] - center).squaredNorm();
        m_distance[j] = (std::min)(m_distance[j], row[j]);
        if(m_distance[j] > m_distance[farthest])
          farthest = j;
      }
      if(c + 1 < center_count)
        m_centers.push_back(farthest);
    }
    double best_score = std::numeric_limits<double>::infinity();
    for(std::size_t c = 0; c < center_count; ++c)
    {
      // The seed: the `size` free points nearest the centre (ties go to the first in `m_free`).
      const double* row = &m_center_distance[c * free_count];
      m_selection.assign(row, row + free_count);
      std::nth_element(m_selection.begin(), m_selection.begin() + (size - 1), m_selection.end());
      const double limit = m_selection[size - 1];
      std::size_t below = 0;
      for(std::size_t j = 0; j < free_count; ++j)
        below += row[j] < limit ? 1 : 0;
      std::size_t at_limit = size - below;
      m_seed.clear();
      for(std::size_t j = 0; j < free_count; ++j)
        if(row[j] < limit || (row[j] == limit && at_limit > 0 && at_limit--))
          m_seed.push_back(m_free[j]);
      Local_frame frame;
      Vec3 spread;
      Height_field plane;
      if(!principal_frame(local, m_seed, frame, spread))
        continue;
      if(degree == 1)
        plane.set_plane(frame);
      else if(!plane.fit(local, m_seed, frame, degree))
        continue;
      double score = 0;
      for(std::size_t j : m_seed)
        score = (std::max)(score, plane.residual(local[j]));
      if(score < best_score)
      {
        best_score = score;
        seed = m_seed;
      }
    }
    return best_score <= tolerance;
  }

  // The centroid of the points `members` of `local` (the origin if there are none).
  Vec3 centroid_of(const std::vector<std::size_t>& members) const
  {
    Vec3 sum = Vec3::Zero();
    for(std::size_t i : members)
      sum += local[i];
    return sum / double((std::max<std::size_t>)(1, members.size()));
  }

  bool refit(const std::vector<std::size_t>& members, int degree, Height_field& height_field) const
  {
    Local_frame frame;
    Vec3 spread;
    return principal_frame(local, members, frame, spread) && height_field.fit(local, members, frame, degree);
  }

  // The least-squares plane of the points summed in `sums` (set_plane() of their principal
  // frame); false for fewer than 3 points.
  static bool plane_of(const Moment_sums& sums, Height_field& height_field)
  {
    Principal_axes axes;
    if(sums.count() < 3 || !sums.principal_axes(axes))
      return false;
    height_field.set_plane(principal_frame(axes));
    return true;
  }

  // Grows the seed by batches of the best-fitting free points while they fit within the
  // tolerance, and releases members that no longer fit. A plane (`degree` 1) keeps the
  // moments of its members up to date instead of refitting them at each step: a step then
  // costs one pass over the free points, not two more over the members (fandisk at 100k
  // points and 1% noise, one thread: stage 2 11.3 s -> 9.8 s, the same curves).
  void grow(double tolerance, int degree, Rmls_surface& surface)
  {
    std::vector<std::size_t>& members = surface.members;
    const bool planes = degree == 1;
    Moment_sums sums(center());
    m_member.assign(local.size(), false);
    for(std::size_t i : members)
    {
      m_member[i] = true;
      if(planes)
        sums.add(local[i]);
    }
    for(std::size_t step = 0; step < Constants::max_growth_steps; ++step)
    {
      if(!(planes ? plane_of(sums, surface.height_field) : refit(members, degree, surface.height_field)))
        break;
      bool changed = false;
      // Release members that the refit left out of the tolerance.
      std::size_t kept = 0;
      for(std::size_t i : members)
        if(surface.height_field.residual(local[i]) <= tolerance)
          members[kept++] = i;
        else
        {
          m_member[i] = false, changed = true;
          if(planes)
            sums.remove(local[i]);
        }
      members.resize(kept);
      if(members.size() < 3)
        break;
      // Add the best free points, at most a fraction of the current set.
      m_ranked.clear();
      for(std::size_t j = 0; j < local.size(); ++j)
        if(!m_assigned[j] && !m_member[j])
        {
          const double r = surface.height_field.residual(local[j]);
          if(r <= tolerance)
            m_ranked.emplace_back(r, j);
        }
      const std::size_t batch = (std::min)(m_ranked.size(),
        (std::max<std::size_t>)(1, std::size_t(Constants::batch_fraction * double(members.size()))));
      if(batch > 0)
      {
        // The batch is the `batch` best-fitting points, in any order: the members are sorted
        // when the growth ends.
        if(batch < m_ranked.size())
          std::nth_element(m_ranked.begin(), m_ranked.begin() + std::ptrdiff_t(batch - 1), m_ranked.end());
        for(std::size_t j = 0; j < batch; ++j)
        {
          members.push_back(m_ranked[j].second);
          m_member[m_ranked[j].second] = true;
          if(planes)
            sums.add(local[m_ranked[j].second]);
        }
        changed = true;
      }
      if(!changed)
        break;
    }
    std::sort(members.begin(), members.end());
    refit(members, degree, surface.height_field);
  }
};

struct Projection
{
  bool has_edge = false, has_corner = false;
  Working_edge_point edge;
  Working_corner_point corner;
};

/// Newton-like projection of `start` onto the intersection of surfaces `a` and `b`: project onto
/// each surface, intersect the two tangent planes, move to the closest point of that line.
inline bool project_on_edge(const Rmls_surface& a, const Rmls_surface& b, const Vec3& start,
                            double step_tolerance, Vec3& e, std::array<Vec3, 2>& normals)
{
  e = start;
  for(std::size_t it = 0; it < Forward_search_constants::max_newton_steps; ++it)
  {
    const Vec3 fa = a.height_field.foot(e), fb = b.height_field.foot(e);
    const Vec3 na = a.height_field.normal(e), nb = b.height_field.normal(e);
    Vec3 next;
    if(!closest_on_plane_intersection(e, fa, na, fb, nb, next))
      return false;
    const double step = (next - e).norm();
    e = next;
    if(step < step_tolerance)
    {
      normals = {{a.height_field.normal(e), b.height_field.normal(e)}};
      return true;
    }
  }
  return false;
}

/// Same with three surfaces: the common point of the three tangent planes.
inline bool project_on_corner(const Rmls_surface* const s[3], const Vec3& start, double step_tolerance,
                              Vec3& c, std::array<Vec3, 3>& normals)
{
  c = start;
  for(std::size_t it = 0; it < Forward_search_constants::max_newton_steps; ++it)
  {
    Eigen::Matrix3d m;
    Vec3 rhs;
    for(int i = 0; i < 3; ++i)
    {
      const Vec3 n = s[i]->height_field.normal(c);
      m.row(i) = n.transpose();
      rhs[i] = n.dot(s[i]->height_field.foot(c));
    }
    if(std::abs(m.determinant()) < 1e-3)
      return false;
    const Vec3 next = m.partialPivLu().solve(rhs);
    if(!next.allFinite())
      return false;
    const double step = (next - c).norm();
    c = next;
    if(step < step_tolerance)
    {
      for(int i = 0; i < 3; ++i)
        normals[i] = s[i]->height_field.normal(c);
      return true;
    }
  }
  return false;
}

/// Orients `n`, the normal of a surface at `at`, away from the points of the other surfaces.
inline Vec3 orient_away(const Vec3& n, const Vec3& at, const Vec3& other_centroid)
{
  return (other_centroid - at).dot(n) > 0 ? Vec3(-n) : n;
}

inline double distance_to_members(const Forward_search& search, const Rmls_surface& s, const Vec3& q)
{
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t i : s.members)
    best = (std::min)(best, (search.local[i] - q).squaredNorm());
  return std::sqrt(best);
}

/// How far apart the planes `a` and `b` stand: the distance from the centroid of either to the
/// plane of the other, the smaller.
inline double separation(const Rmls_surface& a, const Rmls_surface& b)
{
  return (std::min)(a.height_field.residual(b.centroid), b.height_field.residual(a.centroid));
}

/// Whether the planes `a` and `b` are the two sides of a wall: parallel (their normals at `p`
/// within `Wall_end_constants::max_side_angle`) and farther apart than the noise
/// (`Wall_end_constants::min_side_separation` tolerances).
inline bool wall_sides(const Rmls_surface& a, const Rmls_surface& b, const Vec3& p, double tolerance)
{
  return std::abs(a.height_field.normal(p).dot(b.height_field.normal(p)))
           >= std::cos(radians(Wall_end_constants::max_side_angle))
    && separation(a, b) > Wall_end_constants::min_side_separation * tolerance;
}

/// Degree of the final surface fits: the user's jet degree, but planes when the noise dominates
/// the sampling (a quadric then fits the noise and bends across the crease).
inline int surface_degree(const Scales& scales, const Projection_parameters& parameters)
{
  return noise_dominates(scales) ? 1 : parameters.degree_fitting;
}

/// Those of `surfaces` with enough members to be a surface, if at least two; none otherwise.
inline std::vector<Rmls_surface*> supported_surfaces(const std::vector<Rmls_surface*>& surfaces)
{
  std::vector<Rmls_surface*> kept;
  for(Rmls_surface* s : surfaces)
    if(s->members.size() >= Forward_search_constants::min_surface_points)
      kept.push_back(s);
  if(kept.size() < 2)
    kept.clear();
  return kept;
}

/// The distinct smooth surfaces around the candidate `p`, whose neighbourhood is in
/// `search.local`: the forward search, nearly parallel surfaces merged, and the competitive
/// refinement. Fewer than two surfaces means no feature at `p`.
inline std::vector<Rmls_surface*> find_surfaces(Forward_search& search, const Vec3& p,
                                                      const Scales& scales, const Projection_parameters& parameters)
{
  const int degree = surface_degree(scales, parameters);
  search.run(scales.rmls_tolerance, degree);
  const double cos_sharp = std::cos(radians(parameters.sharpness_angle));
  // Nearly parallel surfaces are one surface split by noise: keep the larger (found first).
  // Under noise, parallel planes well apart are the two sides of a thin wall instead (see
  // `wall_sides()`): keep the side that `p` lies on, the nearer.
  std::vector<Rmls_surface*> distinct;
  for(Rmls_surface& s : search.surfaces)
  {
    const Vec3 n = s.height_field.normal(p);
    const auto parallel = std::find_if(distinct.begin(), distinct.end(), [&](const Rmls_surface* d) {
      return std::abs(d->height_field.normal(p).dot(n)) > cos_sharp;
    });
    if(parallel == distinct.end())
      distinct.push_back(&s);
    else if(degree == 1 && wall_sides(**parallel, s, p, scales.rmls_tolerance)
            && s.height_field.residual(p) < (*parallel)->height_field.residual(p))
      *parallel = &s;
  }
  // One distinct plane under noise: with the points beyond its tolerance, it may span a crease.
  // Split alone, its members hold little of the crease (the tolerance kept them for fitting it):
  // at 0.5% dB noise, the rim of a sphere cut at 30 degrees gave no curve, a 30-degree crease
  // between planes 0 and 19% of its length (two samples); with the free points, 33-50% and 51-83%,
  // once the wider split confirms them (see `Cell_projector::split_stands_wider()`).
  search.split_off_crease = false;
  if(degree == 1 && distinct.size() == 1)
  {
    Rmls_surface spanning, a, b;
    if(search.with_free_points(*distinct.front(), spanning)
       && search.split_across_crease(spanning, Forward_search::smallest_surface(search.local.size()), a, b))
    {
      search.surfaces.push_back(std::move(a));
      search.surfaces.push_back(std::move(b));
      distinct.assign({&search.surfaces[search.surfaces.size() - 2], &search.surfaces.back()});
      search.split_off_crease = true;
    }
  }
  if(distinct.size() >= 2)
  {
    search.refine(distinct, scales.rmls_tolerance, degree, p);
    // The split's planes, each fitted to a few points of the other side along the vertex line,
    // lie closer together than the faces (30-degree creases at 0.5% dB noise gave 20 to 25
    // degrees): only the refined planes tell whether the crease is sharp.
    if(search.split_off_crease
       && std::abs(distinct[0]->height_field.normal(p).dot(distinct[1]->height_field.normal(p))) > cos_sharp)
      distinct.clear();
  }
  return supported_surfaces(distinct);
}

/// Fills `search.local` with the `k` points of `indexed` nearest `p`, nearest first (`query`
/// and `nearest` are the caller's workspace).
inline void load_nearest(const Indexed_points& indexed, const Vec3& p, std::size_t k, Point_index::Ranked_query& query,
                         std::vector<std::size_t>& nearest, Forward_search& search)
{
  indexed.index.nearest_ranked(p, k, query, nearest);
  search.local.clear();
  for(std::size_t j : nearest)
    search.local.push_back(indexed.points[j]);
}

/// Refines `found`, the surfaces that `find_surfaces()` found around `p` on the means of the
/// sampled points (see `Sharp_feature_scales::search_fraction`), on the sampled points nearest
/// `p` that span the radius of a stage-2 neighbourhood of means, which replace the means in
/// `search.local`: the search sees the means, whose noise averages out, and the fits see every
/// sampled point, also near the crease, where a mean of points from both sides lies on
/// neither. Fewer than two surfaces means no feature.
inline std::vector<Rmls_surface*> refine_on_sampled_points(Forward_search& search, std::vector<Rmls_surface*> found,
                                                           const Indexed_points& sampled, const Vec3& p,
                                                           const Scales& scales, const Projection_parameters& parameters,
                                                           Point_index::Ranked_query& query,
                                                           std::vector<std::size_t>& nearest)
{
  load_nearest(sampled, p, scales_of_sampled_points(scales).rmls_neighbors, query, nearest, search);
  search.points_per_counted_point = sampled_points_per_mean(scales);
  search.refine(found, scales.rmls_tolerance, surface_degree(scales, parameters), p);
  return supported_surfaces(found);
}

/// The centroid of the members of the surfaces `set[0..count)` other than `self`, weighted by
/// their member counts: the side that the normal of `self` points away from.
inline Vec3 centroid_of_others(const Rmls_surface* self, const Rmls_surface* const* set, int count)
{
  Vec3 sum = Vec3::Zero();
  double weight = 0;
  for(int i = 0; i < count; ++i)
    if(set[i] != self)
    {
      sum += double(set[i]->members.size()) * set[i]->centroid;
      weight += double(set[i]->members.size());
    }
  return Vec3(sum / weight);
}

/// What a projected point must satisfy to be kept: close to its candidate, between surfaces
/// that are distinct, and supported by the members of each surface.
struct Surface_checks
{
  typedef Forward_search_constants Constants;

  Surface_checks(const Forward_search& search, const Scales& scales, const Projection_parameters& parameters)
    : search(search), radius(search.radius()), max_offset(largest_offset(search, scales)),
      cos_sharp(std::cos(radians(parameters.sharpness_angle))),
      step_tolerance(Constants::newton_step_tolerance * scales.spacing),
      coincident(corner_weight_floor * scales.spacing)
  {}

  /// How far a projection may move from its candidate. On noisy data: the radius of the
  /// candidate's stage-1 neighbourhood (`candidate_neighbors` points). Stage 1 chose the
  /// candidate because that neighbourhood straddles a crease, so the crease passes within its
  /// radius. A projection farther away lies on a crease that the candidate's test did not see,
  /// one that only the rim of the larger stage-2 ball reaches, where the forward search splits
  /// off a sliver of points as the second surface (across a thin wall, say: the bottom of a cup
  /// extended through its side). Measured over the nine benchmark parts at 100k points (seeds
  /// 1 and 2; the whole stage-2 radius before): mean F1 at 0.5% noise 0.927 -> 0.930 and 0.922
  /// -> 0.932 (rotor 0.64 -> 0.69 and 0.63 -> 0.71), pieces per found curve 1.40 -> 1.26 and
  /// 1.34 -> 1.29; at 1% noise F1 0.786 -> 0.792 and 0.786 -> 0.789, pieces 1.86 -> 1.63 and
  /// 1.59 -> 1.46. On noise-free data the whole stage-2 radius: the candidates of a cell share
  /// the neighbourhood of its first one (see `Candidate_cells`), whose stage-1 radius is not
  /// theirs, and the bound cost spool 0.954 -> 0.951 there (0.962 -> 0.956 with 5% outliers).
  static double largest_offset(const Forward_search& search, const Scales& scales)
  {
    const std::size_t k = std::size_t(std::lround(double(scales.candidate_neighbors) * search.points_per_counted_point));
    if(!noise_dominates(scales) || k == 0 || k > search.local.size())
      return search.radius();
    return (search.local[k - 1] - search.center()).norm();
  }

  bool near_candidate(const Vec3& x, const Vec3& p) const { return (x - p).norm() <= max_offset; }
  bool distinct(const Vec3& na, const Vec3& nb) const { return std::abs(na.dot(nb)) <= cos_sharp; }
  bool supported(const Rmls_surface& s, const Vec3& x) const
  {
    return distance_to_members(search, s, x) <= Constants::max_support_gap * radius;
  }

  const Forward_search& search;
  /// The support gaps are relative to the radius of the neighbourhood, the offsets of the
  /// projections bounded by `max_offset` (see `largest_offset()`).
  double radius, max_offset, cos_sharp, step_tolerance;
  /// Corner-to-edge distances below this count as 0 in the corner weight 1/|c - e|.
  double coincident;
  /// `coincident` relative to the spacing.
  static constexpr double corner_weight_floor = 1e-12;
};

/// The edge point of candidate `p` on the surfaces `pair`, if it passes the checks.
inline bool project_edge_point(const Rmls_surface* const pair[2], const Vec3& p, std::size_t source,
                               const Surface_checks& checks, Working_edge_point& edge)
{
  Vec3 e;
  std::array<Vec3, 2> en;
  if(!project_on_edge(*pair[0], *pair[1], p, checks.step_tolerance, e, en) || !checks.near_candidate(e, p)
     || !checks.distinct(en[0], en[1]) || !checks.supported(*pair[0], e) || !checks.supported(*pair[1], e))
    return false;
  edge.point = e;
  edge.source = source;
  for(int i = 0; i < 2; ++i)
    edge.normals[i] = orient_away(en[i], e, centroid_of_others(pair[i], pair, 2));
  return true;
}

/// The corner point of candidate `p` on the surfaces `triple`, whose first two gave the edge
/// point `e`, if it passes the checks.
inline bool project_corner_point(const Rmls_surface* const triple[3], const Vec3& p, std::size_t source,
                                 const Vec3& e, const Surface_checks& checks, Working_corner_point& corner)
{
  Vec3 c;
  std::array<Vec3, 3> cn;
  if(!project_on_corner(triple, p, checks.step_tolerance, c, cn) || !checks.near_candidate(c, p)
     || !checks.distinct(cn[0], cn[2]) || !checks.distinct(cn[1], cn[2])
     || !checks.supported(*triple[0], c) || !checks.supported(*triple[1], c) || !checks.supported(*triple[2], c))
    return false;
  corner.point = c;
  corner.source = source;
  corner.weight = 1. / (std::max)((c - e).norm(), checks.coincident);
  for(int i = 0; i < 3; ++i)
    corner.normals[i] = orient_away(cn[i], c, centroid_of_others(triple[i], triple, 3));
  return true;
}

/// Two planes in a wedge narrower than this (degrees) are the two sides of a wall, its end
/// cut off or not: both their members lie on the same side of the line where they meet. Under
/// noise, the sides of a thin rim between faces 22 degrees apart (spool) come out 25 to 35
/// degrees apart, and their planes meet beyond the rim (1.5% dB on spool).
constexpr double thin_wall_wedge_angle = 45;

/// Whether the members of the planes `a` and `b` lie on the same side of the line where they
/// meet (nearest `p`), in a wedge narrower than `thin_wall_wedge_angle`.
inline bool narrow_wedge(const Rmls_surface& a, const Rmls_surface& b, const Vec3& p)
{
  Vec3 line;
  std::array<Vec3, 2> towards;
  return directions_from_crease_line(a, b, p, line, towards)
    && towards[0].dot(towards[1]) > std::cos(radians(thin_wall_wedge_angle)) * towards[0].norm() * towards[1].norm();
}

/// The edge point of candidate `p` where the thin wall whose sides are the planes `a` and `b`
/// ends (see `Wall_end.h`), on the side nearer `p`, if the two sides stand apart by more than
/// the noise, both end near `p` on the same side and the point passes the offset check. Its
/// normals: the side's, away from the other side, and the closing face's, outward.
inline bool project_on_wall_end(const Forward_search& search, const Rmls_surface& a, const Rmls_surface& b,
                                const Vec3& p, std::size_t source, const Surface_checks& checks, double tolerance,
                                Working_edge_point& edge)
{
  if(!(separation(a, b) > Wall_end_constants::min_thickness * tolerance))
    return false;
  // Both sides end the same way: the outward direction from both their centroids.
  const Vec3 mean_a = in_plane_mean(search.local, a.members, a.height_field, p);
  const Vec3 mean_b = in_plane_mean(search.local, b.members, b.height_field, p);
  if(!(mean_a.dot(mean_b) > 0))
    return false;
  const Vec3 outward = -(mean_a + mean_b);
  Wall_end_estimate estimate(search.local, p, search.radius(), tolerance);
  Wall_end ends[2];
  if(!estimate(a.members, a.height_field, b.centroid, outward, ends[0])
     || !estimate(b.members, b.height_field, a.centroid, outward, ends[1]))
    return false;
  const int near = a.height_field.residual(p) <= b.height_field.residual(p) ? 0 : 1;
  const Wall_end& end = ends[near];
  if(!checks.near_candidate(end.point, p))
    return false;
  edge.point = end.point;
  edge.source = source;
  edge.normals = {{orient_away(end.normal, end.point, (near == 0 ? b : a).centroid), end.outward}};
  return true;
}

/// The projection of `p` onto the intersections of `surfaces` (at least two, found by
/// `find_surfaces()` around a candidate at most a few spacings from `p`, whose neighbourhood
/// is in `search.local`): an edge point on the two surfaces closest to `p`, and a corner point
/// if a third one meets them.
inline Projection project_on_surfaces(const Forward_search& search, std::vector<const Rmls_surface*> distinct,
                                      const Vec3& p, std::size_t source, const Scales& scales,
                                      const Projection_parameters& parameters)
{
  const Surface_checks checks(search, scales, parameters);
  // The surfaces closest to the point define its edge (and corner).
  std::stable_sort(distinct.begin(), distinct.end(), [&](const Rmls_surface* a, const Rmls_surface* b) {
    return a->height_field.residual(p) < b->height_field.residual(p);
  });
  Projection result;
  const Rmls_surface* pair[2] = {distinct[0], distinct[1]};
  // Under noise, a narrow wedge is a wall whose closing face the search did not resolve.
  if(noise_dominates(scales) && narrow_wedge(*pair[0], *pair[1], p))
  {
    result.has_edge = project_on_wall_end(search, *pair[0], *pair[1], p, source, checks, scales.rmls_tolerance, result.edge);
    return result;
  }
  result.has_edge = project_edge_point(pair, p, source, checks, result.edge);
  if(result.has_edge && distinct.size() >= 3)
  {
    const Rmls_surface* triple[3] = {distinct[0], distinct[1], distinct[2]};
    result.has_corner = project_corner_point(triple, p, source, result.edge.point, checks, result.corner);
  }
  return result;
}

/// Groups corner points closer than the corner radius; in each group the member closest to the
/// weighted average survives (paper 3.3). Groups with fewer than `min_members` are dropped
/// as isolated three-surface splits.
inline std::vector<Working_corner_point> group_corner_points(std::vector<Working_corner_point> corners, double radius)
{
  const std::size_t min_members = 3;
  std::stable_sort(corners.begin(), corners.end(), [](const Working_corner_point& a, const Working_corner_point& b) {
    return a.weight > b.weight;
  });
  std::vector<Vec3> points;
  for(const Working_corner_point& c : corners)
    points.push_back(c.point);
  Point_index index;
  index.build<CGAL::Sequential_tag>(points);
  std::vector<bool> grouped(corners.size(), false);
  std::vector<std::size_t> group;
  std::vector<Working_corner_point> kept;
  for(std::size_t i = 0; i < corners.size(); ++i)
  {
    if(grouped[i])
      continue;
    index.within(corners[i].point, radius, group);
    std::sort(group.begin(), group.end());
    group.erase(std::remove_if(group.begin(), group.end(), [&](std::size_t j) { return grouped[j]; }), group.end());
    Vec3 average = Vec3::Zero();
    double weight = 0;
    for(std::size_t j : group)
    {
      grouped[j] = true;
      average += corners[j].weight * corners[j].point;
      weight += corners[j].weight;
    }
    if(group.size() < min_members)
      continue;
    average /= weight;
    std::size_t best = group.front();
    for(std::size_t j : group)
      if((corners[j].point - average).squaredNorm() < (corners[best].point - average).squaredNorm())
        best = j;
    kept.push_back(corners[best]);
  }
  return kept;
}

/// Whether `surfaces`, found around the first point of `search.local`, also explain the
/// neighbourhood of `q`, a point near it: `q` lies on one of them (within `tolerance`), and
/// fewer than a fraction `unexplained_fraction` (by default that of the smallest surface,
/// `Forward_search_constants::min_surface_fraction`) of the points of `search.local` in the
/// largest ball around `q` that this neighbourhood covers (at least
/// `Forward_search_constants::min_surface_points` of them) lie on none. The points
/// left over could form a surface that a search around `q` would find (the other side of a
/// thin wall, say): then `q` must search its own.
inline bool surfaces_explain(const Forward_search& search, const std::vector<const Rmls_surface*>& surfaces,
                             const Vec3& q, double tolerance,
                             double unexplained_fraction = Forward_search_constants::min_surface_fraction)
{
  auto explained = [&](const Vec3& x) {
    for(const Rmls_surface* s : surfaces)
      if(s->height_field.residual(x) <= tolerance)
        return true;
    return false;
  };
  const double reach = search.radius() - (q - search.center()).norm();
  if(!explained(q) || reach <= 0)
    return false;
  std::size_t inside = 0, unexplained = 0;
  for(const Vec3& x : search.local)
    if((x - q).squaredNorm() <= reach * reach)
    {
      ++inside;
      unexplained += explained(x) ? 0 : 1;
    }
  return inside >= Forward_search_constants::min_surface_points
    && double(unexplained) < unexplained_fraction * double(inside);
}

/// Side of the grid cells that group the candidates of noise-free data, relative to the
/// sampling spacing.
constexpr double candidate_cell_per_spacing = 1.5;
/// Side of the grid cells that group the candidates of noisy data, relative to the RMLS
/// tolerance (2.25 noise deviations). The stage-2 neighbourhoods span 4 to 5 tolerances, so
/// those of candidates within 1.5 tolerances of each other hold mostly the same points and
/// give edge points whose errors are nearly the same: one search per cell keeps one estimate
/// per 1.5 tolerances of crease, which the smoothing of stage 3 averages. Wider cells lose
/// accuracy at 1% noise: mean F1 over the 9 benchmark parts at 100k points, seeds 1 and 2,
/// 0.847 with a search per candidate, 0.846 with cells of 1.5 tolerances, 0.836 with cells of
/// 2 (at most 3 searches per cell in both).
constexpr double noisy_candidate_cell_per_tolerance = 1.5;
/// On noisy data, a search stands for its cell when its edge point lies within this many cell
/// sides (3 tolerances, about two thirds of a stage-2 neighbourhood radius) of its candidate.
/// A candidate farther from the crease sees it at the edge of its neighbourhood, where few of
/// its points lie: its edge point is a poorer estimate than that of a candidate on the crease,
/// not a repeat of it, and the next candidates of the cell search too. Under moderate noise the
/// candidates lie close to the crease and the first success nearly always stands (fandisk at
/// 500k points and 0.5% noise: F1 0.9808 and 21 corners as before, 807 curve vertices for 805,
/// in the same time); at 2% noise the candidate band is several cells wide. Mean F1 over the 9
/// benchmark parts at 100k points, seeds 1 to 4: at 2% noise (eps 1% dB) 0.545 with the first
/// success, 0.564 with this bound; at 1% (eps 0.5% dB) 0.8464 and 0.8461. Seeds 1 and 2 at 2%:
/// 0.549 with the first success, 0.563 with this bound, 0.577 with 1 cell side (but fandisk at
/// 500k and 0.5% noise 7.3 s -> 8.6 s), 0.592 with a search per candidate.
constexpr double max_edge_offset_per_cell = 2;

/// On noisy data, a candidate of a cell does not search when the lone plane that the previous
/// search of the cell found, and failed with, leaves at most this fraction of its neighbourhood
/// out of the tolerance (see `surfaces_explain()`): its own search would find that plane alone
/// too. Most searches under noise are of this kind: candidates that one noise sample lifted
/// over the stage-1 threshold, away from every crease, in cells that try every candidate for
/// want of an edge point (fandisk at 500k points and 0.5% noise: 22,830 of the 34,423 first-pass
/// searches are in the 11,924 cells that get none). The fraction is what the tail of the noise
/// alone leaves beyond the tolerance of 2.25 noise deviations (2.4% of Gaussian noise, none of
/// noise uniform in a ball), not the 10% of a surface: across a shallow crease, one plane tilted
/// between the two sides holds all but a few percent of the points, and the next candidates may
/// still find both (with 5%, the 30-degree crease of two planes at 0.5% noise lost its curve).
/// Measured on fandisk at 500k points and 0.5% noise with 2 threads, alternately, three runs
/// each (two series): stage 2 5.35, 5.26, 5.23 and 5.13, 4.57, 4.54 s -> 4.96, 4.94, 4.91 and
/// 4.47, 4.33, 4.21 s, the same F1 (0.9808) and corners (21); at 100k points and 1% noise no
/// change (1.94 s). Mean F1 over the 9 benchmark parts at 100k points, seeds 1 and 2: noise 0
/// unchanged, 0.5% 0.9791 -> 0.9792, 1% 0.8465 -> 0.8466, 2% (eps 1% dB) 0.5633 -> 0.5636.
constexpr double max_lone_plane_misfit = 0.03;

/// Side of the cells of noisy data (see `noisy_candidate_cell_per_tolerance`).
inline double noisy_cell_side(const Scales& scales)
{
  return noisy_candidate_cell_per_tolerance * scales.rmls_tolerance;
}
/// Candidates of a cell of noise-free data whose forward search is tried, in turn, until one
/// finds surfaces.
constexpr std::size_t surface_searches_per_cell = 3;

/// The candidates grouped by the cells of a grid. The candidates form a band several points
/// wide along each crease, and on noise-free data the surfaces that the forward search finds
/// around one of them serve its neighbours as well: stage 2 searches the surfaces around the
/// first candidate of a cell (the next one if it finds fewer than two, up to
/// `surface_searches_per_cell`) and projects every candidate of the cell onto them. Every
/// candidate still gives its own edge point, for about one forward search per cell. On noisy
/// data the cells are wider (see `noisy_candidate_cell_per_tolerance`) and the candidates
/// search in turn until one gives an edge point near it, except near corners and shallow
/// creases, where all do (see `Cell_projector::project_first()`).
struct Candidate_cells
{
  /// The candidates, cell by cell; in a cell by decreasing stage-1 residual (the best placed
  /// on the crease first), then by position.
  std::vector<std::size_t> members;
  /// Cell `c` holds `members[start[c]]` to `members[start[c + 1] - 1]`.
  std::vector<std::size_t> start;

  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
  std::size_t size(std::size_t c) const { return start[c + 1] - start[c]; }
  std::size_t member(std::size_t c, std::size_t rank) const { return members[start[c] + rank]; }
};

/// Groups `candidates` (positions in `points`) by cells of side `cell`, with the stage-1
/// `residuals` of every point; `cell` is positive.
inline Candidate_cells group_candidates(const std::vector<Vec3>& points, const std::vector<std::size_t>& candidates,
                                        const std::vector<double>& residuals, double cell)
{
  Candidate_cells cells;
  if(candidates.empty())
    return cells;
  Vec3 low = points[candidates.front()];
  for(std::size_t c : candidates)
    low = low.cwiseMin(points[c]);
  // Cells anchored at multiples of their side, not at the lowest candidate: a tile of the cloud
  // (see `extract_tile_features()`) then groups its candidates as the whole cloud does.
  low = (low / cell).array().floor().matrix() * cell;
  // A cloud wider than `Grid_key` holds (far outliers) aliases cells 2^21 cells apart.
  // Candidates far from the surfaces of their cell then search their own, or fail the support
  // test of the projection: aliasing costs time, never wrong edge points.
  auto key = [&](std::size_t c) { return Grid_key::of(points[c], low, cell); };
  struct Keyed { std::uint64_t key; double residual; std::size_t position; };
  std::vector<Keyed> keyed;
  keyed.reserve(candidates.size());
  for(std::size_t c : candidates)
    keyed.push_back(Keyed{key(c), residuals.empty() ? 0. : residuals[c], c});
  std::sort(keyed.begin(), keyed.end(), [&points](const Keyed& a, const Keyed& b) {
    if(a.key != b.key)
      return a.key < b.key;
    if(a.residual != b.residual)
      return a.residual > b.residual;
    // Neighbours with the same neighbourhood have the same residual: ties are common. Broken
    // by coordinates, not by position in the spatial order, so that a tile of the cloud picks
    // the same first candidate as the whole cloud.
    const Vec3& p = points[a.position];
    const Vec3& q = points[b.position];
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
  });
  for(std::size_t i = 0; i < keyed.size(); ++i)
  {
    if(i == 0 || keyed[i].key != keyed[i - 1].key)
      cells.start.push_back(i);
    cells.members.push_back(keyed[i].position);
  }
  cells.start.push_back(keyed.size());
  return cells;
}

/// Normals of a crease less than this many degrees apart mark a shallow crease. Under noise
/// the forward search there succeeds for few candidates (the first plane often takes both
/// sides: 2 of about 88 candidates succeed at 40 degrees and 1% noise, 11 at 50), so near one,
/// as near a corner, every candidate of a cell searches its own surfaces: the crease keeps the
/// edge point of each that succeeds. Measured on the analytic shapes of the tests at 0.5%
/// noise: without this, the 30-degree crease of two planes loses its only curve.
constexpr double shallow_crease_angle = 40;

/// What the first pass found in a cell of noisy data (see `Cell_projector::project_first()`).
struct First_search
{
  /// Candidates that the first pass went through: those of rank 0 to `searched - 1` in the
  /// cell, each searched or skipped (see `max_lone_plane_misfit`).
  std::size_t searched = 0;
  /// The rank of the last of them whose search found surfaces (meaningful if `corner_or_shallow`).
  std::size_t last_found = 0;
  /// Whether that search found three surfaces or more (the cell may be near a corner) or a
  /// shallow crease (see `shallow_crease_angle`): then every candidate near the cell searches
  /// its own surfaces.
  bool corner_or_shallow = false;
};

/// The projections of the candidates of the cells of one block, in the order of
/// `cells.members`; one per thread (it owns the forward search's workspace).
class Cell_projector
{
public:
  Cell_projector(const Indexed_input& input, const Candidate_cells& cells, const Scales& scales,
                 const Projection_parameters& parameters, std::vector<Projection>& projections)
    : m_input(input), m_cells(cells), m_scales(scales), m_parameters(parameters), m_projections(projections)
  {}

  /// Searches the surfaces around the first candidate of `cell` (the next ones if it finds
  /// fewer than two, up to `surface_searches_per_cell`); they serve the rest of the cell,
  /// except the candidates whose surroundings they do not explain (near a corner, say): those
  /// search their own.
  void project_cell(std::size_t cell)
  {
    const std::size_t size = m_cells.size(cell);
    for(std::size_t rank = 0; rank < (std::min)(size, surface_searches_per_cell); ++rank)
    {
      const std::vector<const Rmls_surface*> surfaces = surfaces_around(m_cells.member(cell, rank));
      if(surfaces.empty())
      {
        project_on_parallel_sides(cell, rank);
        continue;
      }
      m_own_search.clear();
      for(std::size_t other = rank; other < size; ++other)
      {
        if(other == rank || surfaces_explain(m_search, surfaces, point(cell, other), m_scales.rmls_tolerance))
          project(cell, other, surfaces);
        else
          m_own_search.push_back(other);
      }
      for(std::size_t other : m_own_search)
      {
        const std::vector<const Rmls_surface*> own = surfaces_around(m_cells.member(cell, other));
        if(!own.empty())
          project(cell, other, own);
      }
      return;
    }
  }

  /// Noisy data, first pass: the candidates of `cell` search their surfaces in turn, each that
  /// finds some is projected, until one gives an edge point within `max_edge_offset_per_cell`
  /// cell sides of its candidate. A search that finds fewer than two surfaces stops early
  /// (0.09 ms against 0.2 ms on fandisk at 500k points), and a cell without an edge point
  /// leaves a gap in its crease: every candidate may be tried, except those whose neighbourhood
  /// the lone plane of the previous failed search explains (see `max_lone_plane_misfit`).
  First_search project_first(std::size_t cell)
  {
    const double max_offset = max_edge_offset_per_cell * noisy_cell_side(m_scales);
    First_search first;
    m_lone_plane.clear();
    while(first.searched < m_cells.size(cell))
    {
      const std::size_t rank = first.searched++;
      if(!m_lone_plane.empty()
         && surfaces_explain(m_search, m_lone_plane, point(cell, rank), m_scales.rmls_tolerance, max_lone_plane_misfit))
        continue;
      const std::size_t found = search_and_project(cell, rank);
      m_lone_plane.clear();
      if(found == 0 && m_search.surfaces.size() == 1)
        m_lone_plane.push_back(&m_search.surfaces.front());
      if(found == 0)
        continue;
      const Projection& projection = m_projections[m_cells.start[cell] + rank];
      first.last_found = rank;
      first.corner_or_shallow = found >= 3
        || (projection.has_edge && angle_between(projection.edge.normals[0], projection.edge.normals[1]) < shallow_crease_angle);
      if(projection.has_edge && (projection.edge.point - point(cell, rank)).norm() <= max_offset)
        break;
    }
    return first;
  }

  /// Noisy data, second pass near a corner or a shallow crease: every candidate of `cell` that
  /// `first` did not go through (see `project_first()`; not those it skipped) searches its own
  /// surfaces and is projected, so that a corner gets the group of corner points that
  /// `group_corner_points()` asks for, and a shallow crease every edge point that its searches
  /// give.
  void project_rest(std::size_t cell, const First_search& first)
  {
    for(std::size_t rank = first.searched; rank < m_cells.size(cell); ++rank)
      search_and_project(cell, rank);
  }

private:
  const Indexed_input& m_input;
  const Candidate_cells& m_cells;
  const Scales& m_scales;
  const Projection_parameters& m_parameters;
  std::vector<Projection>& m_projections;
  Forward_search m_search;
  // The wider neighbourhood that confirms a split (see `split_stands_wider()`).
  Forward_search m_wide;
  // The queries of the neighbourhoods of the means, of the sampled points and of the wider
  // neighbourhoods, each of which starts from the radius of the previous one of its kind.
  Point_index::Ranked_query m_query, m_sampled_query, m_wide_query;
  std::vector<std::size_t> m_neighbors, m_own_search;
  // The lone plane of the last search in `project_first()`, if it failed with one (in
  // `m_search`, whose neighbourhood it was found in), for the next candidates of the cell.
  std::vector<const Rmls_surface*> m_lone_plane;

  const Vec3& point(std::size_t cell, std::size_t rank) const { return m_input.points[m_cells.member(cell, rank)]; }

  // The surfaces around the candidate at `position` (in `m_search`).
  std::vector<const Rmls_surface*> surfaces_around(std::size_t position)
  {
    const Vec3& p = m_input.points[position];
    load_nearest(m_input, p, m_scales.rmls_neighbors, m_query, m_neighbors, m_search);
    m_search.points_per_counted_point = 1;
    std::vector<Rmls_surface*> found = find_surfaces(m_search, p, m_scales, m_parameters);
    if(!found.empty() && m_search.split_off_crease && !split_stands_wider(p))
      found.clear();
    if(!found.empty() && m_input.refinement)
      found = refine_on_sampled_points(m_search, found, *m_input.refinement, p, m_scales, m_parameters,
                                       m_sampled_query, m_neighbors);
    return std::vector<const Rmls_surface*>(found.begin(), found.end());
  }

  // Whether the points nearest `p`, `split_confirmation_neighbors_factor` times as many as a
  // stage-2 neighbourhood, split across a crease too (see
  // `Forward_search_constants::split_confirmation_neighbors_factor`).
  bool split_stands_wider(const Vec3& p)
  {
    load_nearest(m_input, p, Forward_search_constants::split_confirmation_neighbors_factor * m_scales.rmls_neighbors,
                 m_wide_query, m_neighbors, m_wide);
    Rmls_surface all, a, b;
    Vec3 line_point;
    return m_wide.all_points(all)
      && m_wide.split_across_crease(all, Forward_search::smallest_surface(m_wide.local.size()), a, b)
      && closest_on_plane_intersection(p, a.height_field.foot(p), a.height_field.normal(p), b.height_field.foot(p),
                                       b.height_field.normal(p), line_point)
      && (line_point - p).norm() <= Surface_checks::largest_offset(m_search, m_scales);
  }

  // Under noise, the first two planes that the search around the candidate found, if parallel,
  // may be the two sides of a thin wall whose end is near it (see `project_on_wall_end()`).
  void project_on_parallel_sides(std::size_t cell, std::size_t rank)
  {
    const std::vector<Rmls_surface>& found = m_search.surfaces;
    const std::size_t q = m_cells.member(cell, rank);
    const Vec3& p = m_input.points[q];
    if(!noise_dominates(m_scales) || found.size() < 2
       || std::abs(found[0].height_field.normal(p).dot(found[1].height_field.normal(p)))
            <= std::cos(radians(m_parameters.sharpness_angle)))
      return;
    Projection& projection = m_projections[m_cells.start[cell] + rank];
    projection.has_edge = project_on_wall_end(m_search, found[0], found[1], p, m_input.input_index[q],
                                              Surface_checks(m_search, m_scales, m_parameters),
                                              m_scales.rmls_tolerance, projection.edge);
  }

  // The candidate of rank `rank` in `cell` searches its own surfaces and is projected (onto
  // the ends of parallel sides if it finds fewer than two). Returns the number of surfaces it
  // found (0 if fewer than two).
  std::size_t search_and_project(std::size_t cell, std::size_t rank)
  {
    const std::vector<const Rmls_surface*> surfaces = surfaces_around(m_cells.member(cell, rank));
    if(surfaces.empty())
      project_on_parallel_sides(cell, rank);
    else
      project(cell, rank, surfaces);
    return surfaces.size();
  }

  void project(std::size_t cell, std::size_t rank, const std::vector<const Rmls_surface*>& surfaces)
  {
    const std::size_t q = m_cells.member(cell, rank);
    m_projections[m_cells.start[cell] + rank] =
      project_on_surfaces(m_search, surfaces, m_input.points[q], m_input.input_index[q], m_scales, m_parameters);
  }
};

/// The edge points of `projections` (in the order of `cells.members`) and their grouped corner
/// points into `out`, in the order of their candidates.
inline void collect_projections(const Candidate_cells& cells, const std::vector<Projection>& projections,
                                const Scales& scales, Working_feature_points& out)
{
  std::vector<std::size_t> order(projections.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cells.members[a] < cells.members[b]; });
  std::vector<Working_corner_point> corners;
  for(std::size_t i : order)
  {
    const Projection& projection = projections[i];
    if(projection.has_edge)
      out.edge_points.push_back(projection.edge);
    if(projection.has_corner)
      corners.push_back(projection.corner);
  }
  out.corner_points = group_corner_points(std::move(corners), scales.corner_radius);
}

/// Share of the progress of stage 2 on noisy data given to the first search of every cell;
/// the searches of every candidate of the cells near corners and shallow creases take the rest.
constexpr double noisy_first_pass_share = 0.8;

/// The cells of noisy data near a corner or a shallow crease: those whose first candidate
/// lies within `radius` (the corner radius) of a candidate whose search found three surfaces
/// or more, or a shallow crease (see `First_search`), in increasing order.
inline std::vector<std::size_t> cells_near_corners_or_shallow_creases(const std::vector<Vec3>& points,
                                                                      const Candidate_cells& cells,
                                                                      const std::vector<First_search>& first_searches,
                                                                      double radius)
{
  std::vector<Vec3> marked;
  for(std::size_t cell = 0; cell < cells.size(); ++cell)
    if(first_searches[cell].corner_or_shallow)
      marked.push_back(points[cells.member(cell, first_searches[cell].last_found)]);
  std::vector<std::size_t> near;
  if(marked.empty())
    return near;
  Point_index index;
  index.build<CGAL::Sequential_tag>(marked);
  std::vector<std::size_t> nearest;
  for(std::size_t cell = 0; cell < cells.size(); ++cell)
  {
    const Vec3& p = points[cells.member(cell, 0)];
    index.nearest(p, 1, nearest);
    if((marked[nearest.front()] - p).norm() <= radius)
      near.push_back(cell);
  }
  return near;
}

/// Stage 2 on the cells of noisy data: the candidates of a cell search their own surfaces
/// until one gives an edge point near it, usually the first that finds surfaces (see
/// `noisy_candidate_cell_per_tolerance` and `max_edge_offset_per_cell`), except near corners
/// and shallow creases, where every candidate does. Returns false if cancelled.
template <typename ConcurrencyTag>
bool project_noisy_cells(const Indexed_input& input, const Candidate_cells& cells, const Scales& scales,
                         const Projection_parameters& parameters, Progress progress, std::vector<Projection>& projections)
{
  std::vector<First_search> first_searches(cells.size());
  Progress first_progress = progress.sub(0., noisy_first_pass_share);
  if(!parallel_blocks<ConcurrencyTag>(cells.size(), first_progress, [&](std::size_t first, std::size_t last) {
       Cell_projector projector(input, cells, scales, parameters, projections);
       for(std::size_t cell = first; cell < last; ++cell)
         first_searches[cell] = projector.project_first(cell);
     }))
    return false;
  const std::vector<std::size_t> marked =
    cells_near_corners_or_shallow_creases(input.points, cells, first_searches, scales.corner_radius);
  Progress rest_progress = progress.sub(noisy_first_pass_share, 1.);
  return parallel_blocks<ConcurrencyTag>(marked.size(), rest_progress, [&](std::size_t first, std::size_t last) {
    Cell_projector projector(input, cells, scales, parameters, projections);
    for(std::size_t k = first; k < last; ++k)
      projector.project_rest(marked[k], first_searches[marked[k]]);
  });
}

/// Stage 2 on the candidates (positions in `input.points`, with the stage-1 `residuals` of
/// every point in spatial order). Returns false if cancelled.
template <typename ConcurrencyTag>
bool rmls_project(const Indexed_input& input, const std::vector<std::size_t>& candidates,
                  const std::vector<double>& residuals, const Scales& scales, const Projection_parameters& parameters,
                  Progress progress, Working_feature_points& out)
{
  out = Working_feature_points();
  out.scales = scales;
  if(scales.rmls_neighbors == 0)
    return progress.report(1.);
  const bool noisy = noise_dominates(scales);
  const Candidate_cells cells =
    group_candidates(input.points, candidates, residuals,
                     noisy ? noisy_cell_side(scales) : candidate_cell_per_spacing * scales.spacing);
  std::vector<Projection> projections(cells.members.size());
  if(noisy)
  {
    if(!project_noisy_cells<ConcurrencyTag>(input, cells, scales, parameters, progress, projections))
      return false;
  }
  else if(!parallel_blocks<ConcurrencyTag>(cells.size(), progress, [&](std::size_t first, std::size_t last) {
            Cell_projector projector(input, cells, scales, parameters, projections);
            for(std::size_t cell = first; cell < last; ++cell)
              projector.project_cell(cell);
          }))
    return false;
  collect_projections(cells, projections, scales, out);
  return true;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
