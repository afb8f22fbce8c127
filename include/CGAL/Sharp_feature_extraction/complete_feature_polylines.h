// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_COMPLETE_FEATURE_POLYLINES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_COMPLETE_FEATURE_POLYLINES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/completion_impl.h>


namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Stage 5: completes the curve network in place (paper, section 3.5, end-point analysis).
///
/// Free-ended polylines shorter than 4 growth radii are removed as noise. At each free
/// end, the outward tangent (principal direction of the last 6 vertices) defines a search cone of
/// half-angle `maximum_angle`, up to the completion distance; the closest polyline vertex or
/// corner inside it decides: (a) another end facing back: the gap is bridged (or a loop closed);
/// (b) an interior vertex: that polyline is split there and a corner is created; an existing
/// corner: the end joins it; another end at an angle: a corner the projection missed, created
/// where the tangents of all the free ends converging there cross (least squares); (c) nothing:
/// a dissipating feature end is left as it is. Free ends left over whose tangent rays still cross
/// within the completion distance are joined the same way. Corners with fewer than two curves are
/// removed; a corner between two curves that continue each other (turning by less than 60
/// degrees) is merged through. A curve turning by more than 60 degrees at a vertex
/// is split there (Mesh_3 would round such a turn off). Then `number_of_relaxation_steps` passes
/// of non-shrinking Laplacian smoothing (Taubin's lambda|mu, inverse-distance weights) move
/// interior vertices, ends fixed; finally each corner moves to where the lines fitted to its
/// curves near it meet, when that is within a growth radius.
///
/// Guarantees: curves that meet at a corner share the exact corner point; closed loops repeat
/// their first point exactly; normals are consistent in order and orientation along each curve.
///
/// \param network the output of `grow_feature_polylines()`, completed in place.
/// \param np optional named parameters among the ones listed below; a parameter of another
///   stage, and `callback` (this stage is short and cannot be interrupted), do not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{maximum_angle}
///     \cgalParamDescription{half-angle, in degrees, of the search cone at a free end}
///     \cgalParamType{`double`}
///     \cgalParamDefault{30}
///     \cgalParamExtra{must be in (0, 90)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_relaxation_steps}
///     \cgalParamDescription{number of passes of non-shrinking Laplacian smoothing of the interior
///       vertices of the completed curves}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{0 leaves the vertices where completion put them}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance}
///     \cgalParamDescription{largest gap bridged by completion, and the reach of the search cone
///       at a free end}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{`network.scales.completion_distance`}
///     \cgalParamExtra{0 keeps the default; a positive value replaces
///       `network.scales.completion_distance` for this call}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument if a parameter is out of range or a scale of
///   `network.scales` is negative or not finite.
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
void complete_feature_polylines(Feature_curve_network<GeomTraits>& network,
                                const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_only_completion_parameters<NamedParameters>(),
                "complete_feature_polylines: a parameter of another stage");
  sfe::complete_feature_curve_network(network, np, sfe::read_completion_parameters(np));
}

} // namespace CGAL

#endif
