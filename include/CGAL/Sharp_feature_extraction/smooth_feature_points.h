// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_SMOOTH_FEATURE_POINTS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_SMOOTH_FEATURE_POINTS_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/smoothing_impl.h>


namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Stage 3: smooths the edge points in place (paper, section 3.4).
///
/// Each edge point moves to its orthogonal projection on the principal line of its neighbourhood:
/// the nearest 10 edge points of the same crease (normal pairs within 25 degrees, orientation
/// included, so that the convex and concave edges of a narrow step stay apart), grown by 5
/// up to 30 until the largest covariance eigenvalue carries 80% of the total. Neighbourhoods
/// never reach past the nearest corner point, so corners stay sharp; corner points do not move.
/// In the last pass the normals are averaged over the neighbourhood, keeping their order and
/// orientation.
///
/// \param features the output of `rmls_project_candidates()`, smoothed in place.
/// \param np optional named parameters among the ones listed below; a parameter of another
///   stage does not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{number of smoothing passes}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{3}
///     \cgalParamExtra{0 leaves the points as they are}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of the work done (from 0
///       to 1); when it returns `false` the computation stops and the function returns `false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the callback interrupted the computation (the points are then unchanged).
template <typename ConcurrencyTag, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
bool smooth_feature_points(Feature_point_set<GeomTraits>& features,
                           const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_only_smoothing_parameters<NamedParameters>(),
                "smooth_feature_points: a parameter of another stage");
  return sfe::smooth_feature_point_set<ConcurrencyTag>(features, sfe::read_smoothing_parameters(np),
                                                       sfe::read_callback(np));
}

} // namespace CGAL

#endif
