// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_GROW_FEATURE_POLYLINES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_GROW_FEATURE_POLYLINES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/conversions.h>
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
/// \param np optional named parameters: `callback`, and
///   `Sharp_feature_extraction::parameters::growth_radius` (default: `features.scales.growth_radius`).
/// \returns `false` if the callback interrupted the computation.
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
bool grow_feature_polylines(const Feature_point_set<GeomTraits>& features,
                            Feature_curve_network<GeomTraits>& network,
                            const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  const sfe::Settings settings = sfe::read_settings(np);
  sfe::Scales scales = sfe::to_internal(features.scales);
  if(settings.growth_radius > 0)
    scales.growth_radius = settings.growth_radius;
  sfe::Progress progress(settings.callback);
  const sfe::Curve_network grown = sfe::grow_polylines(sfe::to_internal(features), scales.growth_radius, progress);
  if(progress.cancelled())
    return false;
  network = sfe::to_public<GeomTraits>(grown, scales);
  return true;
}

} // namespace CGAL

#endif
