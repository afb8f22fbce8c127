// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 1 (paper 3.2): jet-fit residuals, the candidate threshold, and the data-derived scales.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_CANDIDATE_POINTS_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_CANDIDATE_POINTS_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/All_nearest_neighbors.h>
#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Height_field_fit.h>
#include <CGAL/Sharp_feature_extraction/internal/Indexed_input.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Fewer input points than this cannot define a feature: the result is empty.
constexpr std::size_t minimum_number_of_points = 20;
/// Neighbourhood size of a stage-1 fit on noise-free data (the 2006 code's value).
constexpr std::size_t base_candidate_neighbors = 36;
/// Most sampled points in the radius of a stage-1 neighbourhood. Where the noise calls for
/// more (it then spans a spacing or more), the cloud is thinned (see `estimate_scales()`), so
/// that this many sampled points span the radius that the noise calls for: the fits of stage 2,
/// on the sampled points, keep the width that averages the noise out at any density, and
/// their cost (the number of candidates times the size of a neighbourhood) stops growing with
/// the density.
constexpr std::size_t maximum_candidate_neighbors = 400;
/// Largest automatic stage-1 neighbourhood of the points that stage 1 and the forward search
/// of stage 2 run on. Where the noise calls for more points, the sampled cloud (see
/// `maximum_candidate_neighbors`) is thinned further, so that this many span the radius that
/// the noise calls for, and each point kept moves to the mean of the sampled points it
/// represents; stage 2 refines the surfaces it finds on the means on the sampled points (see
/// `Sharp_feature_scales::search_fraction`). The search then costs a fixed number of points
/// per neighbourhood at any density, and the fits keep every sampled point. Measured on the 9
/// benchmark parts (mean F1 at eps 0.5% dB; sum of the stage-2 times with one thread) against
/// the search on the sampled points, at 1% noise: 100k points seed 1 0.820 -> 0.824 (76.7 ->
/// 43.7 s), seed 2 0.816 -> 0.823, 200k points seed 3 0.836 -> 0.837 (208.7 -> 54.0 s); at 0.5%
/// noise 0.978 -> 0.978, 0.976 -> 0.977 and 0.979 -> 0.980. Means of fewer points are cheaper
/// and lose: with 70, 1% noise at 200k points gave 0.823 (pinion and rotor lose their small
/// creases), with 50, 0.810 at 100k. Without the refinement on the sampled points, 100 means
/// gave 0.811 at 100k points.
constexpr std::size_t maximum_search_neighbors = 100;
/// A thinning keeps at least this many stage-2 neighbourhoods' worth of points (else the
/// neighbourhoods are capped instead).
constexpr std::size_t minimum_thinned_neighborhoods = 10;
/// Noise-to-spacing ratio above which neighbourhoods grow (quadratically with the ratio), for
/// the noise measured over the 36 nearest points (the sizes were chosen on it at noise up to
/// 1% dB)...
constexpr double noise_ratio_for_growth = 0.25;
/// ... and for the widened estimate (see `noise_fit_radius_per_noise`), which reads about 1.2
/// times more at 1% dB noise (0.84 to 0.98 of the true noise against 0.69 to 0.86 on the 9
/// benchmark parts): the sizes follow whichever of the two asks for more, so that they stay
/// those of the narrow estimate up to 1% dB (sizes from the widened estimate alone: mean F1 at
/// 1% dB 0.779 -> 0.768 on the 9 parts) and keep growing with the noise where the narrow
/// estimate saturates (0.47 to 0.65 of the true noise at 2% dB).
constexpr double widened_noise_ratio_for_growth = 0.3;
/// The two ratios above were chosen on the spacing in space, which the noise inflates: the
/// distance to the 6th neighbour of a point in a noise band adds their offsets along the
/// normal. The inflation grows with the noise-to-spacing ratio, and so with the density at a
/// fixed noise, so that neighbourhoods grown on it shrink as the density grows: at 500k points
/// and 0.5% dB noise the stage-1 radius was 0.66 of that at 100k on CGAL's pinion, whose tooth
/// creases were then lost (F1 0.960 at 100k, 0.871 at 500k). The inflation is therefore capped
/// at this factor: the spacing the neighbourhoods grow on is at most this many times the
/// spacing in the tangent plane (`Scale_samples::tangent_spacing`), which the noise does not
/// inflate. Over the 9 benchmark parts at 100k points, where the ratios were chosen, the
/// inflation was 1.19 to 1.31 at 0.5% dB noise (unchanged by the cap) and 1.48 to 1.50 at 1%.
/// Uncapped, with the ratios taken against 1.35 tangent spacings, the neighbourhoods of sparse
/// clouds shrank instead (a cube of 30k points at 1% dB noise: 59 -> 43 points, 12 -> 14 to 18
/// curves). Mean F1 on the 9 parts (eps 0.5% dB), before -> after: 0.5% noise 500k points
/// 0.968 -> 0.980 (pinion 0.871 -> 0.949), 100k identical (seeds 1, 2); 1% noise 500k 0.831 ->
/// 0.848, 100k 0.826 -> 0.822 and 0.821 -> 0.814; 2% noise 100k at eps 1% dB 0.534 -> 0.563.
constexpr double maximum_spacing_inflation = 1.35;
/// The noise is measured over neighbourhoods at least this many noise scales wide. Once the
/// noise spans about a spacing, the 36 nearest points of a point lie inside its slab of the
/// noise band, and their jet follows the noise: that estimate fell to 0.75 of the true RMS of
/// the noise along the normal at 1% dB noise and to 0.52 at 2% (fandisk, 100k points), so
/// that neighbourhoods and tolerances stopped growing with the noise. A neighbourhood 5 noise
/// scales wide holds the band (uniform noise in a ball reaches 2.2 RMS on each side).
constexpr double noise_fit_radius_per_noise = 5;
/// Quantile of the RMS residuals of the widened fits taken as the noise: a wide neighbourhood
/// of a thin wall or a tight bend holds curvature that a jet cannot follow, which raises its
/// residual (the median rose to 1.28 times the true noise on CGAL's rotor at 1% dB noise), and
/// the lower quartile leaves those neighbourhoods out (0.84 to 1.03 of the true noise on the 9
/// benchmark parts at 1% and 2% dB).
constexpr double widened_noise_quantile = 0.25;
/// The widened fits hold at most as many points as the largest stage-1 neighbourhood: a
/// wider neighbourhood is fitted on every m-th of its points in the order of distance, which
/// keeps its radius and its noise at a bounded cost.
constexpr std::size_t maximum_noise_fit_neighbors = maximum_candidate_neighbors;
/// On the points, the widened neighbourhoods hold at most this many points. This bound was once
/// `maximum_noise_fit_neighbors`, chosen at 100k points, where it bounded the radius: wider
/// neighbourhoods reached the geometry of the small parts (4 times as many read 2.0, 1.15 and
/// 1.24 times the true noise on CGAL's pinion, rotor and spool at 2% dB noise; beyond
/// `maximum_noise_fit_neighbors` points, the rule of `widen_noise_estimate()` on widenings that
/// raise the estimate by growing factors now stops that). At 5 times the density, 400 points spanned 0.6 of
/// the radius the noise asked for, the estimate saturated low (fandisk, 500k points, 2% dB
/// noise: 0.0089 for a true 0.0130), and so did the stage-1 neighbourhoods (1,099 points where
/// 5 x 692 kept the radius of 100k points): F1 at eps 1% dB 0.16, against 0.69 at 100k. With
/// this bound: 0.0126 and 0.61; fandisk, pinion, rotor and spool at 500k points, seed 4: 2%
/// noise 0.188 -> 0.358, 1% noise 0.7346 -> 0.7356; the 9 parts at 100k points, seeds 1 and 2:
/// 2% noise 0.5742 -> 0.5830, 0.5% and 1% noise identical.
constexpr std::size_t maximum_noise_search_neighbors = 10 * maximum_noise_fit_neighbors;
/// The widened fits are made around every this-many-th sample: their lower quartile needs no
/// more than the 2,000 or so that remain, and a widened fit costs up to 45 times a fit of the
/// 36 nearest points.
constexpr std::size_t widened_sample_stride = 10;
/// The widening repeats while the neighbourhood grows by more than this factor.
constexpr double widening_growth_to_repeat = 1.1;
/// At most this many widenings (a bound of the loop: each widening raises the estimate less
/// than the one before, else curvature raised it, and the size bound stops it).
constexpr int maximum_widenings = 8;
/// RMLS tolerance relative to the noise scale (the RMS residual underestimates the noise a little:
/// 2.25 of it covers uniform noise in a ball, whose normal component reaches 2.2 of its RMS).
constexpr double rmls_tolerance_per_noise = 2.25;
/// Smallest RMLS tolerance, relative to the spacing, for noise-free data.
constexpr double rmls_tolerance_per_spacing = 0.05;
/// Spacing is the mean distance to this neighbour (see `Sharp_feature_scales::spacing`).
constexpr std::size_t spacing_neighbor = 6;
/// At most this many points are used to estimate spacing, noise and neighbourhood radii.
constexpr std::size_t scale_sample_size = 20000;
/// The stride of the regular sample of at most about `scale_sample_size` of `n` values: the
/// scale samples, the tiled threshold's residuals and the median of the threshold all take every
/// this-many-th point in the spatial order, so they sample the same points.
inline std::size_t scale_sample_stride(std::size_t n) { return (std::max<std::size_t>)(1, n / scale_sample_size); }
/// Smallest neighbourhood size: a quadric jet has 6 coefficients, and a fit needs more points.
constexpr std::size_t minimum_neighbors = 7;
/// Stage-2 neighbourhoods hold this many times the points of stage-1 ones: the forward search
/// splits them into two or three surfaces, each of which needs about a stage-1 neighbourhood.
constexpr std::size_t rmls_neighbors_per_candidate_neighbors = 2;
/// Completion bridges gaps up to this many spacings (gaps of a few missing samples along a
/// crease, from the paper's examples)...
constexpr double completion_distance_per_spacing = 7;
/// ... and at least this many growth radii: stage 4 stops where the next edge point is more
/// than a growth radius away, so gaps are at least that wide.
constexpr double completion_distance_per_growth_radius = 3;

struct Local_fit_statistics
{
  double max_residual = 0;
  double rms_residual = 0;
};

/// Jet fit of `points[neighbors]` over `frame`: the paper's residual r(p) (largest distance to
/// the fit along the frame normal) and the RMS residual.
template <typename IndexRange>
Local_fit_statistics fit_residuals(const std::vector<Vec3>& points, const IndexRange& neighbors,
                                   const Local_frame& frame, int degree)
{
  Local_fit_statistics stats;
  Height_field fit;
  if(!fit.fit(points, neighbors, frame, degree))
    return stats;
  double sum = 0;
  std::size_t count = 0;
  for(std::size_t j : neighbors)
  {
    const double r = fit.residual(points[j]);
    stats.max_residual = (std::max)(stats.max_residual, r);
    sum += r * r;
    ++count;
  }
  stats.rms_residual = std::sqrt(sum / double(count));
  return stats;
}

/// The same over the principal plane of `points[neighbors]`.
template <typename IndexRange>
Local_fit_statistics fit_residuals(const std::vector<Vec3>& points, const IndexRange& neighbors, int degree)
{
  Local_frame frame;
  Vec3 spread;
  if(!principal_frame(points, neighbors, frame, spread))
    return Local_fit_statistics();
  return fit_residuals(points, neighbors, frame, degree);
}

/// Distance from `p` to the `rank`-th nearest of `points[neighbors]` (0 being the nearest) in
/// the plane of `frame`, the heights along its normal left out; `distances` is a workspace.
inline double tangent_distance(const std::vector<Vec3>& points, const Vec3& p, const std::vector<std::size_t>& neighbors,
                               const Local_frame& frame, std::size_t rank, std::vector<double>& distances)
{
  distances.clear();
  for(std::size_t j : neighbors)
  {
    const Vec3 d = points[j] - p;
    distances.push_back(std::hypot(d.dot(frame.u), d.dot(frame.v)));
  }
  std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(rank), distances.end());
  return distances[rank];
}

/// The value at `fraction` (in [0, 1)) of the sorted `values`; 0 if there is none.
inline double quantile(std::vector<double> values, double fraction)
{
  if(values.empty())
    return 0;
  const auto at = values.begin() + std::ptrdiff_t(fraction * double(values.size()));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

inline double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

/// The mean of the finite `values`; 0 if there is none.
inline double finite_mean(const std::vector<double>& values)
{
  double sum = 0;
  std::size_t count = 0;
  for(double d : values)
    if(std::isfinite(d))
    {
      sum += d;
      ++count;
    }
  return count > 0 ? sum / double(count) : 0.;
}

/// The measurements of the regular subsample (regular in the spatial order of the points)
/// from which the scales are derived, one value per sample.
struct Scale_samples
{
  std::size_t stride = 1;
  /// Distance to the `spacing_neighbor`-th neighbour.
  std::vector<double> spacing;
  /// The same in the tangent plane (of the jet fit below): noise along the normal inflates the
  /// distances in space, the more so the denser the cloud, but not these.
  std::vector<double> tangent_spacing;
  /// RMS residual of the jet fitted to the `base_candidate_neighbors` nearest points.
  std::vector<double> rms_residual;
  /// Distances to the `candidate_neighbors`-th and `rmls_neighbors`-th neighbours.
  std::vector<double> candidate_radius, rmls_radius;
};

/// First pass over the samples: spacing, noise, and the neighbourhood radii of the default
/// sizes on data without noise (`base_candidate_neighbors` and twice as many), which then need
/// no second pass. Returns false if cancelled.
template <typename ConcurrencyTag>
bool measure_samples(const std::vector<Vec3>& points, const Point_index& index, int degree, Progress progress,
                     Scale_samples& samples)
{
  const std::size_t n = points.size();
  samples.stride = scale_sample_stride(n);
  const std::size_t count = (n + samples.stride - 1) / samples.stride;
  for(std::vector<double>* v :
      {&samples.spacing, &samples.tangent_spacing, &samples.rms_residual, &samples.candidate_radius, &samples.rmls_radius})
    v->assign(count, 0.);
  const std::size_t fit_size = (std::min)(base_candidate_neighbors, n);
  const std::size_t searched = (std::min)(rmls_neighbors_per_candidate_neighbors * base_candidate_neighbors, n);
  return parallel_blocks<ConcurrencyTag>(count, progress, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> neighbors, fitted;
    std::vector<double> distances;
    for(std::size_t s = first; s < last; ++s)
    {
      const Vec3& p = points[s * samples.stride];
      index.nearest(p, searched, neighbors);
      const std::size_t spacing_rank = (std::min)(spacing_neighbor, neighbors.size() - 1);
      samples.spacing[s] = (points[neighbors[spacing_rank]] - p).norm();
      samples.candidate_radius[s] = (points[neighbors[fit_size - 1]] - p).norm();
      samples.rmls_radius[s] = (points[neighbors.back()] - p).norm();
      fitted.assign(neighbors.begin(), neighbors.begin() + std::ptrdiff_t(fit_size));
      Local_frame frame;
      Vec3 spread;
      if(!principal_frame(points, fitted, frame, spread))
      {
        samples.tangent_spacing[s] = samples.spacing[s];
        continue;
      }
      samples.tangent_spacing[s] = tangent_distance(points, p, neighbors, frame, spacing_rank, distances);
      samples.rms_residual[s] = fit_residuals(points, fitted, frame, degree).rms_residual;
    }
  });
}

/// The noise measured over neighbourhoods at least `noise_fit_radius_per_noise` noise scales
/// wide (see there), starting from `scales.noise` measured over `fit_size` points whose median
/// radius is `fit_radius`: the neighbourhoods widen until their median radius reaches that
/// width (or they stop growing, or hold `maximum_noise_search_neighbors` points; on means,
/// `maximum_noise_fit_neighbors`, which span twice the radius the noise asked for). With
/// `on_means` (the points are the means of a thinned cloud, see `estimate_scales()`), or once
/// the neighbourhoods hold more than `maximum_noise_fit_neighbors` points, a widening that
/// raises the estimate by a larger factor than the widening before it is not kept, and the
/// widening stops there.
///
/// Why: the means are thinned so that their neighbourhoods already span the radius that the
/// noise measured on the points asked for, and there a widening that reaches deeper into the
/// noise band raises the estimate less than the one before. Curvature that a jet cannot follow
/// does the opposite: its residual grows faster than the radius, and the radius follows the
/// estimate, so the loop feeds on itself. A rod whose radius is 1.5 times the noise radius, at
/// 2% dB noise and 30,000 points, read 2.2 times the noise along the normal (1.05 with this
/// rule); CGAL's pinion at 2% dB noise, whose means read 0.0252, 0.0274, 0.0305, ... up to
/// 0.0696 (factors 1.09, 1.11, 1.14, 1.16, 1.21, 1.28; the points' own estimate was 0.0274),
/// took whole teeth into the RMLS tolerance and lost every curve (F1 0 at eps 1% dB, 0.05 with
/// the rule). On the points themselves the first widenings may raise the estimate by growing
/// factors, from the 36 nearest points deep inside a noise band several spacings thick (a
/// cubic sheet at 3% dB noise and 100k points: 1.235 then 1.244; stopping there left stage-1
/// neighbourhoods 2.4 times smaller), so there the rule applies only beyond the size at which
/// the points' neighbourhoods held the band at 100k points (without it, pinion's points read
/// 0.0274 at 373 points, then factors 1.13, 1.15, 1.18, 1.23, 1.30 up to 2,602 points, and
/// pinion lost every curve at 2% noise and 100k points again; spool, whose widening it also
/// stops, went 0.539 -> 0.428).
template <typename ConcurrencyTag>
bool widen_noise_estimate(const std::vector<Vec3>& points, const Point_index& index, int degree,
                          std::size_t fit_size, double fit_radius, bool on_means, const Scale_samples& samples,
                          Progress progress, Scales& scales)
{
  const std::size_t largest_fit = (std::min)(points.size(), maximum_noise_fit_neighbors);
  const std::size_t largest =
    (std::min)(points.size(), on_means ? maximum_noise_fit_neighbors : maximum_noise_search_neighbors);
  const std::size_t stride = samples.stride * widened_sample_stride;
  const std::size_t count = (samples.spacing.size() + widened_sample_stride - 1) / widened_sample_stride;
  std::vector<double> rms_residual(count), radius(count);
  std::size_t k = fit_size;
  double last_growth = std::numeric_limits<double>::infinity(); // factor of the last widening
  for(int widening = 0; widening < maximum_widenings; ++widening)
  {
    const double wanted_radius = noise_fit_radius_per_noise * scales.noise;
    if(fit_radius >= wanted_radius)
      break;
    // A neighbourhood's radius grows with the square root of its size on a surface, and more
    // slowly inside a noise band thicker than it (the loop then widens it again).
    const std::size_t wider = std::size_t((std::min)(double(largest), std::ceil(double(k) * std::pow(wanted_radius / fit_radius, 2))));
    if(double(wider) < widening_growth_to_repeat * double(k))
      break;
    k = wider;
    Progress step = progress.sub(double(widening) / maximum_widenings, double(widening + 1) / maximum_widenings);
    if(!parallel_blocks<ConcurrencyTag>(count, step, [&](std::size_t first, std::size_t last) {
         std::vector<std::size_t> neighbors, fitted(largest_fit);
         for(std::size_t s = first; s < last; ++s)
         {
           const Vec3& p = points[s * stride];
           index.nearest(p, k, neighbors);
           radius[s] = (points[neighbors.back()] - p).norm();
           if(neighbors.size() > largest_fit)
           {
             for(std::size_t j = 0; j < largest_fit; ++j)
               fitted[j] = neighbors[j * neighbors.size() / largest_fit];
             rms_residual[s] = fit_residuals(points, fitted, degree).rms_residual;
           }
           else
             rms_residual[s] = fit_residuals(points, neighbors, degree).rms_residual;
         }
       }))
      return false;
    const double widened_noise = quantile(rms_residual, widened_noise_quantile);
    const double growth = widened_noise / scales.noise;
    if((on_means || k > largest_fit) && growth > last_growth)
      break;
    last_growth = growth;
    scales.noise = widened_noise;
    fit_radius = median(radius);
  }
  return true;
}

/// Second pass, when the neighbourhood sizes are not those of the first: their radii. Returns
/// false if cancelled.
template <typename ConcurrencyTag>
bool measure_radii(const std::vector<Vec3>& points, const Point_index& index, const Scales& scales,
                   Progress progress, Scale_samples& samples)
{
  return parallel_blocks<ConcurrencyTag>(samples.spacing.size(), progress, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> neighbors;
    for(std::size_t s = first; s < last; ++s)
    {
      const Vec3& p = points[s * samples.stride];
      index.nearest(p, scales.rmls_neighbors, neighbors);
      samples.candidate_radius[s] = (points[neighbors[(std::min)(scales.candidate_neighbors, neighbors.size()) - 1]] - p).norm();
      samples.rmls_radius[s] = (points[neighbors.back()] - p).norm();
    }
  });
}

/// The automatic stage-1 neighbourhood size: grown with the square of the noise-to-spacing
/// ratio (above `noise_ratio_for_growth` for `narrow_noise`, the noise over the 36 nearest
/// points, and above `widened_noise_ratio_for_growth` for `noise`, the widened estimate) so
/// that fits average the noise out. The spacing is `spacing`, at most
/// `maximum_spacing_inflation` times `tangent_spacing` (see there; 0 when unknown).
inline double noise_grown_candidate_neighbors(double narrow_noise, double noise, double spacing, double tangent_spacing)
{
  const double growth_spacing = tangent_spacing > 0
    ? (std::min)(spacing, maximum_spacing_inflation * tangent_spacing) : spacing;
  // The noise-to-spacing ratio in units of its growth threshold, the larger of the two estimates'.
  const double ratio_over_threshold =
    (std::max)(narrow_noise / noise_ratio_for_growth, noise / widened_noise_ratio_for_growth) / growth_spacing;
  return double(base_candidate_neighbors) * (std::max)(1., ratio_over_threshold * ratio_over_threshold);
}

/// The neighbourhood sizes: `grown_candidate_neighbors` (see `noise_grown_candidate_neighbors()`),
/// or as given; within [`minimum_neighbors`, n].
inline void choose_neighborhood_sizes(const Scale_parameters& parameters, std::size_t n,
                                      double grown_candidate_neighbors, Scales& scales)
{
  auto within_bounds = [n](std::size_t k) { return (std::max<std::size_t>)(minimum_neighbors, (std::min)(k, n)); };
  scales.candidate_neighbors = within_bounds(parameters.candidate_neighbors > 0
    ? parameters.candidate_neighbors
    : std::size_t((std::min)(double(maximum_candidate_neighbors), grown_candidate_neighbors)));
  scales.rmls_neighbors = within_bounds(parameters.rmls_neighbors > 0
    ? parameters.rmls_neighbors : rmls_neighbors_per_candidate_neighbors * scales.candidate_neighbors);
}

/// The distances derived from the spacing, the noise and the neighbourhood radii, or as given.
inline void choose_distances(const Scale_parameters& parameters, const Scale_samples& samples, Scales& scales)
{
  // The RMLS tolerance must admit the noise but never fall to 0 on exact data.
  scales.rmls_tolerance = parameters.rmls_tolerance > 0
    ? parameters.rmls_tolerance
    : (std::max)(rmls_tolerance_per_noise * scales.noise, rmls_tolerance_per_spacing * scales.spacing);
  scales.corner_radius = parameters.corner_radius > 0 ? parameters.corner_radius : median(samples.rmls_radius);
  scales.candidate_radius = median(samples.candidate_radius);
  scales.growth_radius = parameters.growth_radius > 0 ? parameters.growth_radius : scales.candidate_radius;
  scales.completion_distance = parameters.completion_distance > 0
    ? parameters.completion_distance
    : (std::max)(completion_distance_per_spacing * scales.spacing,
                 completion_distance_per_growth_radius * scales.growth_radius);
}

/// Spacing and noise, from a regular subsample of the cloud (`samples`), and the automatic
/// stage-1 size that the noise calls for (`grown_candidate_neighbors`, before the bounds).
/// `on_means`: the points are the means of a thinned cloud (see `widen_noise_estimate()`).
/// Returns false when the cloud has no extent (all points identical, or so far apart that their
/// distances overflow) or when cancelled (then `progress` is cancelled).
template <typename ConcurrencyTag>
bool measure_spacing_and_noise(const std::vector<Vec3>& points, const Point_index& index,
                               const Scale_parameters& parameters, bool on_means, Progress progress,
                               Scale_samples& samples, Scales& scales, double& grown_candidate_neighbors)
{
  constexpr double samples_share = 4. / 7.; // of the progress: the widened fits take the rest
  if(!measure_samples<ConcurrencyTag>(points, index, parameters.degree_fitting, progress.sub(0, samples_share),
                                      samples))
    return false;
  // A distance between points more than about 1e154 apart overflows to infinity (its square
  // does): a far outlier among ordinary coordinates. It says nothing of the sampling, so its
  // samples are left out; a cloud that has no other is refused like one without extent.
  scales.spacing = finite_mean(samples.spacing);
  if(!(scales.spacing > 0))
    return false;
  const double narrow_noise = median(samples.rms_residual);
  scales.noise = narrow_noise;
  if(!widen_noise_estimate<ConcurrencyTag>(points, index, parameters.degree_fitting,
                                           (std::min)(base_candidate_neighbors, points.size()),
                                           median(samples.candidate_radius), on_means, samples,
                                           progress.sub(samples_share, 1), scales))
    return false;
  grown_candidate_neighbors = noise_grown_candidate_neighbors(narrow_noise, scales.noise, scales.spacing,
                                                              finite_mean(samples.tangent_spacing));
  return true;
}

/// The neighbourhood sizes and distances, with the user's choices, from the spacing and noise
/// of `scales` and the `samples` that `measure_spacing_and_noise()` measured them on (whose
/// radii are measured again when the sizes are not those of its fits). Returns false if
/// cancelled.
template <typename ConcurrencyTag>
bool choose_sizes_and_distances(const std::vector<Vec3>& points, const Point_index& index,
                                const Scale_parameters& parameters, double grown_candidate_neighbors,
                                Progress progress, Scale_samples& samples, Scales& scales)
{
  choose_neighborhood_sizes(parameters, points.size(), grown_candidate_neighbors, scales);
  const bool first_pass_radii = scales.candidate_neighbors == (std::min)(base_candidate_neighbors, points.size())
    && scales.rmls_neighbors == (std::min)(rmls_neighbors_per_candidate_neighbors * base_candidate_neighbors, points.size());
  if(!first_pass_radii && !measure_radii<ConcurrencyTag>(points, index, scales, progress, samples))
    return false;
  choose_distances(parameters, samples, scales);
  return progress.report(1.);
}

/// The paper's automatic threshold, the mean residual, over the fits that a surface can
/// explain. A crease gives residuals of the order of `radius` (the radius of the stage-1
/// neighbourhoods) times the sine of its angle; a residual above `radius` means a neighbour
/// lies farther from the fit than the neighbourhood is wide, which only an outlier (the point
/// itself or one of its neighbours) causes. Such fits still make candidates, but they are left
/// out of the mean: far outliers would dominate it (with 5% of the points uniform in the
/// bounding box, the mean rose enough to lose 60% of the creases of CGAL's pinion) and put the
/// creases of small features and shallow angles below the threshold.
inline double mean_residual_of_surface_fits(const std::vector<double>& residuals, double radius)
{
  double sum = 0;
  std::size_t count = 0;
  for(double r : residuals)
    if(r <= radius)
    {
      sum += r;
      ++count;
    }
  return count > 0 ? sum / double(count) : 0.;
}

/// Under noise (see `noise_dominates()`), the automatic candidate threshold is at most this many
/// times the median residual. Most points lie off the creases, so the median residual is that
/// of the fits of smooth surfaces, which the noise sets; the mean also holds the fits that a jet
/// cannot follow. Where the smooth surfaces bend within a neighbourhood (thin walls, tight
/// bends), those raise the mean above the residuals of the creases: on CGAL's rotor at 0.25% dB
/// noise, whose stage-1 neighbourhoods are the 36 nearest points and span 12 noise scales, the
/// mean was 1.85 times the median, and a third of the crease length had no candidate (F1 0.93).
/// On the 9 benchmark parts at 0.25% to 1% dB noise the mean is otherwise 1.06 to 1.25 times the
/// median, which this bound leaves as it is: a bound of 1.1 also lowered the threshold of those
/// parts and lost 1 to 2.5 of pinion's 80 corners at 0.5% noise. Without noise the median
/// residual is that of exact surfaces, near 0, and only the mean (the paper's threshold) holds.
constexpr double maximum_threshold_per_median_residual = 1.3;

/// The median of `values`, over a regular sample of at most about `scale_sample_size` of them
/// (the threshold needs no more, and the sample keeps the cost of a large cloud small).
inline double sampled_median(const std::vector<double>& values)
{
  const std::size_t stride = scale_sample_stride(values.size());
  std::vector<double> sample;
  sample.reserve(values.size() / stride + 1);
  for(std::size_t i = 0; i < values.size(); i += stride)
    sample.push_back(values[i]);
  return median(std::move(sample));
}

/// The automatic candidate threshold for the stage-1 `residuals` of a cloud of these `scales`:
/// the mean residual of the surface fits (see `mean_residual_of_surface_fits()`), under noise at
/// most `maximum_threshold_per_median_residual` times the median residual.
inline double automatic_residual_threshold(const std::vector<double>& residuals, const Scales& scales)
{
  const double mean = mean_residual_of_surface_fits(residuals, scales.candidate_radius);
  if(!noise_dominates(scales))
    return mean;
  return (std::min)(mean, maximum_threshold_per_median_residual * sampled_median(residuals));
}

/// The end of `estimate_scales()` when the scales could not be measured: false if cancelled,
/// else all scales zero.
inline bool without_scales(Progress& progress, Scales& scales)
{
  if(progress.cancelled())
    return false;
  scales = Scales();
  return progress.report(1.);
}

/// The scales of `input` (see `Sharp_feature_scales`): all zero when the cloud has fewer than
/// `minimum_number_of_points` distinct points or no extent. When the noise calls for automatic
/// stage-1 neighbourhoods of more than `maximum_search_neighbors` points, `input` is thinned
/// (see `sample_input()`): to the fraction that leaves `maximum_candidate_neighbors` in the
/// same radius (if fewer), then to the fraction that leaves `maximum_search_neighbors` there,
/// as means; and the scales are measured again on the means, with neighbourhoods of that many.
/// Returns false if cancelled.
template <typename ConcurrencyTag>
bool estimate_scales(Indexed_input& input, const Scale_parameters& parameters, Progress progress,
                     Scales& scales)
{
  scales = Scales();
  if(input.points.size() < minimum_number_of_points)
    return progress.report(1.);
  Scale_samples samples;
  double grown = 0;
  constexpr bool on_means = true;
  if(!measure_spacing_and_noise<ConcurrencyTag>(input.points, input.index, parameters, !on_means, progress.sub(0, 0.3),
                                                samples, scales, grown))
    return without_scales(progress, scales);
  const double search_fraction = double(maximum_search_neighbors) / grown;
  const std::size_t smallest_kept =
    minimum_thinned_neighborhoods * rmls_neighbors_per_candidate_neighbors * maximum_search_neighbors;
  const bool automatic_sizes = parameters.candidate_neighbors == 0 && parameters.rmls_neighbors == 0;
  if(!automatic_sizes || search_fraction >= 1 || double(input.points.size()) * search_fraction < double(smallest_kept))
    return choose_sizes_and_distances<ConcurrencyTag>(input.points, input.index, parameters, grown,
                                                      progress.sub(0.3, 1), samples, scales)
           || without_scales(progress, scales);
  // The sizes and distances of the points are not chosen: those of the means replace them. (The
  // radii of the sizes that the noise calls for, up to 800 points, took 0.74 s of the 1.95 s of
  // the context on fandisk at 100k points and 1% noise, with one thread.)
  Scales fractions;
  fractions.sampled_fraction = (std::min)(1., double(maximum_candidate_neighbors) / grown);
  fractions.search_fraction = search_fraction;
  sample_input<ConcurrencyTag>(fractions, input);
  // Neighbourhoods of `maximum_search_neighbors` means span the radius the noise called for.
  Scale_parameters thinned = parameters;
  thinned.candidate_neighbors = maximum_search_neighbors;
  samples = Scale_samples();
  if(!measure_spacing_and_noise<ConcurrencyTag>(input.points, input.index, thinned, on_means, progress.sub(0.3, 0.7),
                                                samples, scales, grown)
     || !choose_sizes_and_distances<ConcurrencyTag>(input.points, input.index, thinned, grown, progress.sub(0.7, 1),
                                                    samples, scales))
    return without_scales(progress, scales);
  scales.sampled_fraction = fractions.sampled_fraction;
  scales.search_fraction = fractions.search_fraction;
  return progress.report(1.);
}

/// Stage-1 results in the spatial order of `Indexed_input::points`.
struct Candidate_output
{
  /// The residual of every distinct point.
  std::vector<double> residuals;
  /// The positions of the candidates, ascending.
  std::vector<std::size_t> candidates;
  /// The scales, with the threshold used.
  Scales scales;
};

/// Stage 1 on every point, with the scales of the extraction context. Returns false if
/// cancelled.
template <typename ConcurrencyTag>
bool compute_candidates(const Indexed_input& input, const Scales& scales, const Candidate_parameters& parameters,
                        Progress progress, Candidate_output& out)
{
  const std::vector<Vec3>& points = input.points;
  const std::size_t n = points.size();
  out = Candidate_output();
  out.residuals.assign(n, 0.);
  out.scales = scales;
  if(!(scales.spacing > 0) || scales.candidate_neighbors == 0)
    return progress.report(1.);

  const std::size_t k = scales.candidate_neighbors;
  const int degree = parameters.degree_fitting;
  std::vector<double>& residuals = out.residuals;
  if(!for_each_neighborhood<ConcurrencyTag>(points, input.index, k, neighborhood_cell_per_radius * scales.candidate_radius,
                                            progress,
       [&](std::size_t i, const std::vector<std::size_t>& neighbors) {
         residuals[i] = fit_residuals(points, neighbors, degree).max_residual;
       }))
    return false;

  out.scales.residual_threshold = parameters.residual_threshold >= 0
    ? parameters.residual_threshold
    : automatic_residual_threshold(residuals, scales);
  for(std::size_t i = 0; i < n; ++i)
    if(residuals[i] > out.scales.residual_threshold)
      out.candidates.push_back(i);
  return true;
}

/// The public form of `out`: residuals and candidate indices in input order.
template <typename GT>
Candidate_points<GT> to_input_order(const Indexed_input& input, const Candidate_output& out)
{
  Candidate_points<GT> candidates;
  candidates.residuals = input.in_input_order<typename GT::FT>(out.residuals);
  candidates.indices = input.input_indices(out.candidates);
  candidates.scales = convert_scales<typename GT::FT>(out.scales);
  return candidates;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
