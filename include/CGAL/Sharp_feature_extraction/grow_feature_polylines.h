// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_GROW_FEATURE_POLYLINES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_GROW_FEATURE_POLYLINES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/polyline_growing_impl.h>


namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Stage 4: grows polylines through the smoothed edge points (paper, section 3.5).
///
/// Corner points are fixed vertices. Seeds are taken farthest from any corner first. From a seed,
/// the polyline grows both ways: the next vertex is the farthest unvisited edge point of the same
/// crease within the growth radius, ahead of the current direction and inside a 45-degree cone;
/// every point ahead within the radius is consumed. A walk stops when nothing lies ahead, at a
/// corner ahead (which it joins) or at its own seed (a closed loop). Polylines with fewer than
/// 4 vertices are dropped. Normals are kept in consistent order and orientation along each curve.
///
/// \param features the output of `smooth_feature_points()`.
/// \param network receives the polylines and the corners.
/// \param np optional named parameters among the ones listed below; a parameter of another
///   stage does not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of the work done (from 0
///       to 1); when it returns `false` the computation stops and the function returns `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius}
///     \cgalParamDescription{neighbourhood radius of the polyline growing: the next vertex is
///       searched within this distance}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{`features.scales.growth_radius`}
///     \cgalParamExtra{0 keeps the default; a positive value replaces
///       `features.scales.growth_radius` for this call}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the callback interrupted the computation.
/// \throws std::invalid_argument if a parameter is out of range or a scale of
///   `features.scales` is negative or not finite.
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
bool grow_feature_polylines(const Feature_point_set<GeomTraits>& features,
                            Feature_curve_network<GeomTraits>& network,
                            const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_only_growing_parameters<NamedParameters>(),
                "grow_feature_polylines: a parameter of another stage");
  return sfe::grow_feature_curve_network(features, network, np, sfe::read_callback(np));
}

} // namespace CGAL

#endif
