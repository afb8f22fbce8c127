// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Stage 1 (paper 3.2): jet-fit residuals, the candidate threshold, and the data-derived scales.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_CANDIDATE_POINTS_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_CANDIDATE_POINTS_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/All_nearest_neighbors.h>
#include <CGAL/Sharp_feature_extraction/internal/conversions.h>
#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Height_field_fit.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Settings.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Fewer input points than this cannot define a feature: the result is empty.
constexpr std::size_t minimum_number_of_points = 20;
/// Neighbourhood size of a stage-1 fit on noise-free data (the 2006 code's value).
constexpr std::size_t base_candidate_neighbors = 36;
/// Upper bound of the noise-grown stage-1 neighbourhood.
constexpr std::size_t maximum_candidate_neighbors = 400;
/// Noise-to-spacing ratio above which neighbourhoods grow (quadratically with the ratio).
constexpr double noise_ratio_for_growth = 0.25;
/// Noise-to-spacing ratio above which the surfaces of stage 2 are planes: a quadric fitted to
/// noisy points bends towards the other side of a crease.
constexpr double noise_ratio_for_planes = 0.05;
/// RMLS tolerance relative to the noise scale (the RMS residual underestimates the noise a little:
/// 2.25 of it covers uniform noise in a ball, whose normal component reaches 2.2 of its RMS).
constexpr double rmls_tolerance_per_noise = 2.25;
/// Smallest RMLS tolerance, relative to the spacing, for noise-free data.
constexpr double rmls_tolerance_per_spacing = 0.05;
/// Spacing is the mean distance to this neighbour (CGAL's compute_average_spacing convention).
constexpr std::size_t spacing_neighbor = 6;
/// At most this many points are used to estimate spacing, noise and neighbourhood radii.
constexpr std::size_t scale_sample_size = 20000;

/// Whether the noise dominates the sampling (see `noise_ratio_for_planes`).
inline bool noise_dominates(const Scales& scales)
{
  return scales.noise > noise_ratio_for_planes * scales.spacing;
}

/// Stage-1 results, indexed like `Indexed_input::points` (spatial order).
struct Candidate_output
{
  std::vector<double> residuals;
  std::vector<std::size_t> candidates; // ascending positions
  Scales scales;
};

struct Local_fit_statistics
{
  double max_residual = 0;
  double rms_residual = 0;
};

/// Jet fit of `points[neighbors]` over its principal plane: the paper's residual r(p) (largest
/// distance to the fit along the plane normal) and the RMS residual.
template <typename IndexRange>
Local_fit_statistics fit_residuals(const std::vector<Vec3>& points, const IndexRange& neighbors, int degree)
{
  Local_fit_statistics stats;
  Local_frame frame;
  Vec3 spread;
  if(!principal_frame(points, neighbors, frame, spread))
    return stats;
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

inline double median(std::vector<double> values)
{
  if(values.empty())
    return 0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

/// Spacing, noise and neighbourhood sizes from a regular subsample of the cloud (regular in
/// the spatial order of `points`), then the user's overrides. `candidate_radius` receives the
/// median distance to the `scales.candidate_neighbors`-th neighbour (the default growth
/// radius, whatever the user's). Returns false when the cloud has no extent (all points
/// identical) or when cancelled (then `progress` is cancelled).
template <typename ConcurrencyTag>
bool derive_scales(const std::vector<Vec3>& points, const Point_index& index,
                   const Settings& settings, Progress progress, Scales& scales, double& candidate_radius)
{
  const std::size_t n = points.size();
  const std::size_t stride = (std::max<std::size_t>)(1, n / scale_sample_size);
  const std::size_t samples = (n + stride - 1) / stride;
  const std::size_t k0 = (std::min)(base_candidate_neighbors, n);
  // The first pass also searches 2 k0 neighbours: the radii of the default neighbourhood sizes
  // on data without noise, which then need no second pass.
  const std::size_t k_first = (std::min)(2 * base_candidate_neighbors, n);
  std::vector<double> spacing(samples), rms(samples), r1(samples), r2(samples);
  Progress first_half = progress.sub(0, 0.5), second_half = progress.sub(0.5, 1);
  if(!parallel_blocks<ConcurrencyTag>(samples, first_half, [&](std::size_t first, std::size_t last) {
       std::vector<std::size_t> neighbors;
       for(std::size_t s = first; s < last; ++s)
       {
         const Vec3& p = points[s * stride];
         index.nearest(p, k_first, neighbors);
         spacing[s] = (points[neighbors[(std::min)(spacing_neighbor, neighbors.size() - 1)]] - p).norm();
         r1[s] = (points[neighbors[k0 - 1]] - p).norm();
         r2[s] = (points[neighbors.back()] - p).norm();
         neighbors.resize(k0);
         rms[s] = fit_residuals(points, neighbors, settings.degree_fitting).rms_residual;
       }
     }))
    return false;
  scales.spacing = std::accumulate(spacing.begin(), spacing.end(), 0.) / double(spacing.size());
  if(!(scales.spacing > 0))
    return false;
  scales.noise = median(rms);

  const double noise_ratio = scales.noise / scales.spacing;
  const double growth = (std::max)(1., std::pow(noise_ratio / noise_ratio_for_growth, 2));
  scales.candidate_neighbors = settings.candidate_neighbors > 0
    ? settings.candidate_neighbors
    : (std::min)(maximum_candidate_neighbors, std::size_t(double(base_candidate_neighbors) * growth));
  scales.candidate_neighbors = (std::max<std::size_t>)(7, (std::min)(scales.candidate_neighbors, n));
  scales.rmls_neighbors = settings.rmls_neighbors > 0 ? settings.rmls_neighbors : 2 * scales.candidate_neighbors;
  scales.rmls_neighbors = (std::max<std::size_t>)(7, (std::min)(scales.rmls_neighbors, n));

  // Neighbourhood radii: the median distance to the k-th neighbour.
  if((scales.candidate_neighbors != k0 || scales.rmls_neighbors != k_first)
     && !parallel_blocks<ConcurrencyTag>(samples, second_half, [&](std::size_t first, std::size_t last) {
          std::vector<std::size_t> neighbors;
          for(std::size_t s = first; s < last; ++s)
          {
            const Vec3& p = points[s * stride];
            index.nearest(p, scales.rmls_neighbors, neighbors);
            r1[s] = (points[neighbors[(std::min)(scales.candidate_neighbors, neighbors.size()) - 1]] - p).norm();
            r2[s] = (points[neighbors.back()] - p).norm();
          }
        }))
    return false;
  // The RMLS tolerance must admit the noise but never fall to 0 on exact data.
  scales.rmls_tolerance = settings.rmls_tolerance > 0
    ? settings.rmls_tolerance
    : (std::max)(rmls_tolerance_per_noise * scales.noise, rmls_tolerance_per_spacing * scales.spacing);
  scales.corner_radius = settings.corner_radius > 0 ? settings.corner_radius : median(r2);
  candidate_radius = median(r1);
  scales.growth_radius = settings.growth_radius > 0 ? settings.growth_radius : candidate_radius;
  scales.completion_distance = settings.completion_distance > 0
    ? settings.completion_distance : (std::max)(7 * scales.spacing, 3 * scales.growth_radius);
  return true;
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

/// Stage 1 on every point. Returns false if cancelled.
template <typename ConcurrencyTag>
bool compute_candidates(const Indexed_input& input, const Settings& settings, Progress progress,
                        Candidate_output& out)
{
  const std::vector<Vec3>& points = input.points;
  const Point_index& index = input.index;
  const std::size_t n = points.size();
  out = Candidate_output();
  out.residuals.assign(n, 0.);
  Progress scale_progress = progress.sub(0, 0.05);
  double candidate_radius = 0;
  if(n < minimum_number_of_points
     || !derive_scales<ConcurrencyTag>(points, index, settings, scale_progress, out.scales, candidate_radius))
    return !scale_progress.cancelled() && progress.report(1.);

  const std::size_t k = out.scales.candidate_neighbors;
  const int degree = settings.degree_fitting;
  std::vector<double>& residuals = out.residuals;
  Progress fit_progress = progress.sub(0.05, 1);
  if(!for_each_neighborhood<ConcurrencyTag>(points, index, k, neighborhood_cell_per_radius * candidate_radius,
                                            fit_progress,
       [&](std::size_t i, const std::vector<std::size_t>& neighbors) {
         residuals[i] = fit_residuals(points, neighbors, degree).max_residual;
       }))
    return false;

  out.scales.residual_threshold = settings.residual_threshold >= 0
    ? settings.residual_threshold
    : mean_residual_of_surface_fits(residuals, candidate_radius);
  for(std::size_t i = 0; i < n; ++i)
    if(residuals[i] > out.scales.residual_threshold)
      out.candidates.push_back(i);
  return true;
}

/// The public form of `out`: residuals and candidate indices in input order.
template <typename GT>
Candidate_points<GT> to_public(const Indexed_input& input, const Candidate_output& out)
{
  Candidate_points<GT> candidates;
  candidates.residuals = input.in_input_order<typename GT::FT>(out.residuals);
  candidates.indices = input.input_indices(out.candidates);
  candidates.scales = to_public<typename GT::FT>(out.scales);
  return candidates;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
