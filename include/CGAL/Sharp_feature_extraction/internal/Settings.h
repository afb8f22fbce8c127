// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SETTINGS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_SETTINGS_H

#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Every knob of the pipeline, read once from the named parameters. A scale left at its
/// "derive" value (0) is computed from the data by `derive_scales()`.
struct Settings
{
  // Stage 1.
  std::size_t candidate_neighbors = 0;   // 0: derived from the noise
  int degree_fitting = 2;
  double residual_threshold = -1;       // < 0: mean residual (the paper's automatic tau)
  // Stage 2.
  std::size_t rmls_neighbors = 0;        // 0: twice candidate_neighbors
  double rmls_tolerance = 0;             // 0: derived from the noise
  double corner_radius = 0;              // 0: median stage-2 neighbourhood radius
  double sharpness_angle = 25;           // degrees between the normals of two distinct surfaces
  // Stage 3.
  unsigned int smoothing_passes = 3;
  // Stage 4.
  double growth_radius = 0;              // 0: median stage-1 neighbourhood radius
  // Stage 5.
  double completion_distance = 0;        // 0: derived from spacing and growth radius
  double completion_aperture = 30;       // degrees, half-angle of the search cone
  unsigned int laplacian_passes = 2;

  std::function<bool(double)> callback;
};

template <typename NamedParameters>
Settings read_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace sfe_np = CGAL::Sharp_feature_extraction::internal_np;
  Settings s;
  s.candidate_neighbors = choose_parameter(get_parameter(np, sfe_np::candidate_neighbors), std::size_t(0));
  s.degree_fitting = choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), 2);
  s.residual_threshold = choose_parameter(get_parameter(np, CGAL::internal_np::threshold_distance), -1.);
  s.rmls_neighbors = choose_parameter(get_parameter(np, sfe_np::rmls_neighbors), std::size_t(0));
  s.rmls_tolerance = choose_parameter(get_parameter(np, sfe_np::rmls_tolerance), 0.);
  s.corner_radius = choose_parameter(get_parameter(np, sfe_np::corner_radius), 0.);
  s.sharpness_angle = choose_parameter(get_parameter(np, CGAL::internal_np::sharpness_angle), 25.);
  s.smoothing_passes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 3u);
  s.growth_radius = choose_parameter(get_parameter(np, sfe_np::growth_radius), 0.);
  s.completion_distance = choose_parameter(get_parameter(np, sfe_np::completion_distance), 0.);
  s.completion_aperture = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_angle), 30.);
  s.laplacian_passes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxation_steps), 2u);
  s.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  if(s.degree_fitting < 1 || s.degree_fitting > 2)
    throw std::invalid_argument("Sharp feature extraction: degree_fitting must be 1 or 2");
  if(!(s.sharpness_angle > 0 && s.sharpness_angle < 90))
    throw std::invalid_argument("Sharp feature extraction: sharpness_angle must be in (0, 90) degrees");
  if(!(s.completion_aperture > 0 && s.completion_aperture < 90))
    throw std::invalid_argument("Sharp feature extraction: maximum_angle must be in (0, 90) degrees");
  for(double v : {s.rmls_tolerance, s.corner_radius, s.growth_radius, s.completion_distance})
    if(!(v >= 0) || !std::isfinite(v))
      throw std::invalid_argument("Sharp feature extraction: distances must be finite and non-negative");
  return s;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
