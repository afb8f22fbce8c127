// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_PARAMETERS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Sharp_feature_extraction {

namespace internal_np {
enum candidate_neighbors_t { candidate_neighbors };
enum rmls_neighbors_t { rmls_neighbors };
enum rmls_tolerance_t { rmls_tolerance };
enum corner_radius_t { corner_radius };
enum growth_radius_t { growth_radius };
enum completion_distance_t { completion_distance };
enum number_of_tiles_t { number_of_tiles };
enum height_field_angle_t { height_field_angle };
enum grid_spacing_t { grid_spacing };
enum initial_labels_t { initial_labels };
enum quantization_step_t { quantization_step };
} // namespace internal_np

/// \ingroup PkgSharpFeatureExtractionRef
/// Named parameters of this package that CGAL's own list does not have. Each function returns
/// a CGAL named-parameter pack, so it chains with CGAL's parameters in both directions:
/// \code
/// namespace sfe = CGAL::Sharp_feature_extraction::parameters;
/// auto np = sfe::rmls_tolerance(0.002, sfe::growth_radius(0.01)).callback(progress);
/// \endcode
namespace parameters {

// Declares a named parameter of the package (kept defined: the reconstruction header declares
// its own with it too).
#define CGAL_SFE_NAMED_PARAMETER(NAME)                                                         \
  template <typename T, typename NP = CGAL::parameters::Default_named_parameters>              \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t, NP>                                 \
  NAME(const T& value, const NP& base = CGAL::parameters::default_values())                    \
  {                                                                                            \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t, NP>(value, base);         \
  }

/// Number of points in a stage-1 neighbourhood (the jet fit that gives the residual).
/// Default: 36, grown with the noise so that fits average it out.
CGAL_SFE_NAMED_PARAMETER(candidate_neighbors)
/// Number of points in a stage-2 (RMLS) neighbourhood. Default: twice `candidate_neighbors`.
CGAL_SFE_NAMED_PARAMETER(rmls_neighbors)
/// Largest residual (a distance) of a point belonging to one smooth surface in the forward
/// search. Default: 2.25 times the noise scale, at least 5% of the sampling spacing.
CGAL_SFE_NAMED_PARAMETER(rmls_tolerance)
/// Corner points closer than this distance are grouped into one corner.
/// Default: the median radius of the stage-2 neighbourhoods.
CGAL_SFE_NAMED_PARAMETER(corner_radius)
/// Neighbourhood radius for polyline growing. Default: the median radius of the stage-1 neighbourhoods.
CGAL_SFE_NAMED_PARAMETER(growth_radius)
/// Largest gap bridged by completion. Default: 7 times the sampling spacing, and at least
/// 3 times the growth radius.
CGAL_SFE_NAMED_PARAMETER(completion_distance)
/// The least number of tiles `extract_sharp_features_in_tiles()` cuts the cloud into.
/// Default: 8.
CGAL_SFE_NAMED_PARAMETER(number_of_tiles)
/// Largest angle, in degrees, between the normal of a point and the plane of its height field
/// (`partition_into_height_fields()`). Default: 60.
CGAL_SFE_NAMED_PARAMETER(height_field_angle)
/// Side of a cell of the grids over which height fields are sampled
/// (`partition_into_height_fields()`, `compress_point_cloud()`). Default: the sampling spacing.
CGAL_SFE_NAMED_PARAMETER(grid_spacing)
/// A label per input point (a `std::vector<std::size_t>`) from which the height-field
/// partition starts splitting: no piece then holds points of two labels before the merge, e.g.
/// `Surface_patches::labels`. Default: none (the split starts from the whole cloud).
CGAL_SFE_NAMED_PARAMETER(initial_labels)
/// Quantizer step (a distance) of the heights of `compress_point_cloud()`. Default: a
/// hundredth of the grid spacing.
CGAL_SFE_NAMED_PARAMETER(quantization_step)

} // namespace parameters
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
