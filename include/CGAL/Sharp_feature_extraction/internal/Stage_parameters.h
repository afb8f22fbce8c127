// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The named parameters, read into one struct per consumer: the scales (read where the
// extraction context is built) and each stage's own knobs. Every default is written once, as
// the initializer of its member; a reader starts from the values it is given (the defaults,
// or those the extraction context was built with) and takes what the named parameters hold.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_STAGE_PARAMETERS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_STAGE_PARAMETERS_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

typedef std::function<bool(double)> Progress_callback;

/// The user's choices among the scales (see `Sharp_feature_scales`); 0 means "derive from
/// the data".
struct Scale_parameters
{
  std::size_t candidate_neighbors = 0;
  std::size_t rmls_neighbors = 0;
  double rmls_tolerance = 0;
  double corner_radius = 0;
  double growth_radius = 0;
  double completion_distance = 0;
  /// Degree of the jets whose residuals measure the noise (the stage-1 fits).
  int degree_fitting = 2;
};

/// Stage 1.
struct Candidate_parameters
{
  int degree_fitting = 2;
  /// The candidate threshold tau; negative: the mean residual (the paper's automatic tau).
  double residual_threshold = -1;
};

/// Stage 2.
struct Projection_parameters
{
  int degree_fitting = 2;
  /// Degrees between the normals of two distinct surfaces.
  double sharpness_angle = 25;
};

/// Stage 3.
struct Smoothing_parameters
{
  unsigned int passes = 3;
};

/// Stage 5.
struct Completion_parameters
{
  /// Degrees, half-angle of the search cone at a free end.
  double aperture = 30;
  unsigned int laplacian_passes = 2;
};

namespace parameter_reading {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
namespace own_np = CGAL::Sharp_feature_extraction::internal_np;

inline void require(bool condition, const char* message)
{
  if(!condition)
    throw std::invalid_argument(std::string("Sharp feature extraction: ") + message);
}

inline void require_distance(double value, const char* name)
{
  if(!(value >= 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("Sharp feature extraction: ") + name
                                + " must be a finite, non-negative distance");
}

inline void require_degree(int degree)
{
  require(degree == 1 || degree == 2, "degree_fitting must be 1 or 2");
}

inline void require_angle(double degrees, const char* name)
{
  if(!(degrees > 0 && degrees < 90))
    throw std::invalid_argument(std::string("Sharp feature extraction: ") + name + " must be in (0, 90) degrees");
}

} // namespace parameter_reading

template <typename NamedParameters>
Progress_callback read_callback(const NamedParameters& np, const Progress_callback& otherwise = Progress_callback())
{
  using namespace parameter_reading;
  return choose_parameter(get_parameter(np, CGAL::internal_np::callback), otherwise);
}

template <typename NamedParameters>
Scale_parameters read_scale_parameters(const NamedParameters& np, Scale_parameters p = Scale_parameters())
{
  using namespace parameter_reading;
  p.candidate_neighbors = choose_parameter(get_parameter(np, own_np::candidate_neighbors), p.candidate_neighbors);
  p.rmls_neighbors = choose_parameter(get_parameter(np, own_np::rmls_neighbors), p.rmls_neighbors);
  p.rmls_tolerance = choose_parameter(get_parameter(np, own_np::rmls_tolerance), p.rmls_tolerance);
  p.corner_radius = choose_parameter(get_parameter(np, own_np::corner_radius), p.corner_radius);
  p.growth_radius = choose_parameter(get_parameter(np, own_np::growth_radius), p.growth_radius);
  p.completion_distance = choose_parameter(get_parameter(np, own_np::completion_distance), p.completion_distance);
  p.degree_fitting = choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), p.degree_fitting);
  require_degree(p.degree_fitting);
  require_distance(p.rmls_tolerance, "rmls_tolerance");
  require_distance(p.corner_radius, "corner_radius");
  require_distance(p.growth_radius, "growth_radius");
  require_distance(p.completion_distance, "completion_distance");
  return p;
}

template <typename NamedParameters>
Candidate_parameters read_candidate_parameters(const NamedParameters& np, Candidate_parameters p = Candidate_parameters())
{
  using namespace parameter_reading;
  p.degree_fitting = choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), p.degree_fitting);
  p.residual_threshold = choose_parameter(get_parameter(np, CGAL::internal_np::threshold_distance), p.residual_threshold);
  require_degree(p.degree_fitting);
  require(!std::isnan(p.residual_threshold) && std::isfinite(p.residual_threshold),
          "threshold_distance must be finite");
  return p;
}

template <typename NamedParameters>
Projection_parameters read_projection_parameters(const NamedParameters& np, Projection_parameters p = Projection_parameters())
{
  using namespace parameter_reading;
  p.degree_fitting = choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), p.degree_fitting);
  p.sharpness_angle = choose_parameter(get_parameter(np, CGAL::internal_np::sharpness_angle), p.sharpness_angle);
  require_degree(p.degree_fitting);
  require_angle(p.sharpness_angle, "sharpness_angle");
  return p;
}

template <typename NamedParameters>
Smoothing_parameters read_smoothing_parameters(const NamedParameters& np, Smoothing_parameters p = Smoothing_parameters())
{
  using namespace parameter_reading;
  p.passes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), p.passes);
  return p;
}

template <typename NamedParameters>
Completion_parameters read_completion_parameters(const NamedParameters& np, Completion_parameters p = Completion_parameters())
{
  using namespace parameter_reading;
  p.aperture = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_angle), p.aperture);
  p.laplacian_passes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxation_steps),
                                        p.laplacian_passes);
  require_angle(p.aperture, "maximum_angle");
  return p;
}

/// Scales given by the user (see `Sharp_feature_scales`): every distance finite and
/// non-negative, the sampled fraction in (0, 1], the search fraction in (0, sampled fraction].
/// The all-zero scales of a cloud without extent pass (the stages then find nothing).
inline void require_valid_scales(const Sharp_feature_scales<double>& scales)
{
  using namespace parameter_reading;
  require_distance(scales.spacing, "scales.spacing");
  require_distance(scales.noise, "scales.noise");
  require_distance(scales.candidate_radius, "scales.candidate_radius");
  require_distance(scales.residual_threshold, "scales.residual_threshold");
  require_distance(scales.rmls_tolerance, "scales.rmls_tolerance");
  require_distance(scales.corner_radius, "scales.corner_radius");
  require_distance(scales.growth_radius, "scales.growth_radius");
  require_distance(scales.completion_distance, "scales.completion_distance");
  require(scales.sampled_fraction > 0 && scales.sampled_fraction <= 1, "scales.sampled_fraction must be in (0, 1]");
  require(scales.search_fraction > 0 && scales.search_fraction <= scales.sampled_fraction,
          "scales.search_fraction must be in (0, scales.sampled_fraction]");
}

/// Every scale that `np` gives replaces its value in `scales` (the scales derived from it do
/// not follow: they were derived already); then all of them are checked (see
/// `require_valid_scales()`).
template <typename NamedParameters>
void override_scales(const NamedParameters& np, Sharp_feature_scales<double>& scales)
{
  const Scale_parameters given = read_scale_parameters(np);
  if(given.candidate_neighbors > 0)
    scales.candidate_neighbors = given.candidate_neighbors;
  if(given.rmls_neighbors > 0)
    scales.rmls_neighbors = given.rmls_neighbors;
  if(given.rmls_tolerance > 0)
    scales.rmls_tolerance = given.rmls_tolerance;
  if(given.corner_radius > 0)
    scales.corner_radius = given.corner_radius;
  if(given.growth_radius > 0)
    scales.growth_radius = given.growth_radius;
  if(given.completion_distance > 0)
    scales.completion_distance = given.completion_distance;
  require_valid_scales(scales);
}

/// The tags of the parameters that set a scale (see `Sharp_feature_scales`).
#define CGAL_SFE_SCALE_PARAMETER_TAGS                                                           \
  CGAL::Sharp_feature_extraction::internal_np::candidate_neighbors_t,                          \
  CGAL::Sharp_feature_extraction::internal_np::rmls_neighbors_t,                               \
  CGAL::Sharp_feature_extraction::internal_np::rmls_tolerance_t,                               \
  CGAL::Sharp_feature_extraction::internal_np::corner_radius_t,                                \
  CGAL::Sharp_feature_extraction::internal_np::growth_radius_t,                                \
  CGAL::Sharp_feature_extraction::internal_np::completion_distance_t

/// Whether `NamedParameters` holds none of the parameters `Tags`: a stage function asserts it,
/// at compile time, for the parameters of the other stages, which would have no effect there.
template <typename NamedParameters, typename... Tags>
constexpr bool holds_none_of()
{
  return (CGAL::parameters::is_default_parameter<NamedParameters, Tags>::value && ...);
}

/// Whether `NamedParameters` holds only parameters of stage 2 (its own scales included): the
/// check of `rmls_project_candidates()`, the free function and the member alike.
template <typename NamedParameters>
constexpr bool holds_only_projection_parameters()
{
  namespace own_np = CGAL::Sharp_feature_extraction::internal_np;
  return holds_none_of<NamedParameters, own_np::candidate_neighbors_t, own_np::growth_radius_t,
                       own_np::completion_distance_t, CGAL::internal_np::threshold_distance_t,
                       CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                       CGAL::internal_np::number_of_relaxation_steps_t>();
}

/// Whether `NamedParameters` holds only parameters of stage 3.
template <typename NamedParameters>
constexpr bool holds_only_smoothing_parameters()
{
  return holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS, CGAL::internal_np::degree_fitting_t,
                       CGAL::internal_np::threshold_distance_t, CGAL::internal_np::sharpness_angle_t,
                       CGAL::internal_np::maximum_angle_t, CGAL::internal_np::number_of_relaxation_steps_t>();
}

/// Whether `NamedParameters` holds only parameters of stage 4 (its growth radius included).
template <typename NamedParameters>
constexpr bool holds_only_growing_parameters()
{
  namespace own_np = CGAL::Sharp_feature_extraction::internal_np;
  return holds_none_of<NamedParameters, own_np::candidate_neighbors_t, own_np::rmls_neighbors_t,
                       own_np::rmls_tolerance_t, own_np::corner_radius_t, own_np::completion_distance_t,
                       CGAL::internal_np::degree_fitting_t, CGAL::internal_np::threshold_distance_t,
                       CGAL::internal_np::sharpness_angle_t, CGAL::internal_np::number_of_iterations_t,
                       CGAL::internal_np::maximum_angle_t, CGAL::internal_np::number_of_relaxation_steps_t>();
}

/// Whether `NamedParameters` holds only parameters of stage 5 (its completion distance
/// included; stage 5 reports no progress, so no callback).
template <typename NamedParameters>
constexpr bool holds_only_completion_parameters()
{
  namespace own_np = CGAL::Sharp_feature_extraction::internal_np;
  return holds_none_of<NamedParameters, own_np::candidate_neighbors_t, own_np::rmls_neighbors_t,
                       own_np::rmls_tolerance_t, own_np::corner_radius_t, own_np::growth_radius_t,
                       CGAL::internal_np::degree_fitting_t, CGAL::internal_np::threshold_distance_t,
                       CGAL::internal_np::sharpness_angle_t, CGAL::internal_np::number_of_iterations_t,
                       CGAL::internal_np::callback_t>();
}

/// Whether `NamedParameters` holds no parameter of the five stages nor a scale: what the
/// segmentation into patches accepts besides the points' own (point map, traits, callback).
template <typename NamedParameters>
constexpr bool holds_only_patch_parameters()
{
  return holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS, CGAL::internal_np::degree_fitting_t,
                       CGAL::internal_np::threshold_distance_t, CGAL::internal_np::sharpness_angle_t,
                       CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                       CGAL::internal_np::number_of_relaxation_steps_t>();
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
