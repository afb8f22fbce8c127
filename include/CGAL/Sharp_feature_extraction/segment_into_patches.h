// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_SEGMENT_INTO_PATCHES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_SEGMENT_INTO_PATCHES_H

#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Splits the points into the surface patches that the feature curves enclose (paper,
/// section 3.6), and fits a plane and a quadric to each.
///
/// A point within the growth radius of a curve vertex or corner lies in the band of that
/// crease, on the side of the surface (among those whose normals the vertex, or the corner,
/// carries) that passes closest to it; it lies there clearly when that surface is nearer than
/// the next by a spacing plus twice the noise. A point outside the bands lies on a crease that
/// no curve marks (a gap in a curve) when the jet fitted to its stage-1 neighbourhood leaves a
/// residual above the candidate threshold (`Sharp_feature_scales::residual_threshold`) and
/// above what a crease of 25 degrees leaves (0.042 stage-1 radii): such points stop the
/// regions as the bands do. Every point that lies clearly on its side (or outside the bands and
/// on no such crease) links to its 6 nearest such points within 3 spacings (longer links reach
/// outliers), and the regions are the sets connected by the links that stay on one side and
/// whose ends are among the 12 nearest of each other (an outlier near a surface is not among the
/// nearest of the surface points, so outliers do not bridge two faces): no
/// region crosses a curve, a crease that fades out does not split a face (the regions join
/// around its end), and a strip between two close creases is a region of its own. A point
/// whose side is not clear takes the region of the nearest clear point on its side. Two regions
/// whose surfaces, fitted on either side of the links between them over a stage-2
/// neighbourhood (`Sharp_feature_scales::rmls_neighbors`), have normals within 15 degrees
/// along at least 4 in 5 of those links (a link that a crease band sees cross to another side
/// counts against) are pieces of one face and join (a face pinched
/// between the bands of two curves, or cut by the surfaces of a corner extended). Regions
/// smaller than a stage-2 neighbourhood (not counting the points on a crease without a curve)
/// merge into the region they share most links with; those without links (outliers) stay
/// unassigned. Two patches are adjacent along a curve when each
/// holds most of the band points of one of its sides.
///
/// Where the noise made stages 1 and 2 run on means (`Sharp_feature_scales::search_fraction`
/// below 1), the sampled points that they are the means of are split, with the scales of the
/// sampled points: a neighbourhood of the same radius holds `sampled_fraction /
/// search_fraction` times the points, and the spacing is smaller by the square root of that.
///
/// The result depends on the points and the curves only: the same whatever the number of
/// threads.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`.
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
///
/// \param points the input points (the same range as given to the extraction).
/// \param network the curves that bound the patches, with the scales they were computed with
///   (`network.scales`): the output of `extract_sharp_features()` or
///   `complete_feature_polylines()`, or curves of the user's with scales.
/// \param patches receives a label for every input point, the patches and their adjacencies.
/// \param np optional named parameters among the ones listed below; a parameter of another
///   stage does not compile.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `SharpFeatureExtractionTraits`}
///     \cgalParamDefault{the kernel of the point type of `point_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{receives the progress in [0,1]; returning `false` stops the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the callback interrupted the computation (`patches` is then empty).
/// \throws std::invalid_argument if a coordinate is not finite.
template <typename ConcurrencyTag, typename PointRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
bool segment_into_patches(const PointRange& points, const Feature_curve_network<GeomTraits>& network,
                          Surface_patches<GeomTraits>& patches,
                          const NamedParameters& np = parameters::default_values())
{
  namespace sfe = Sharp_feature_extraction::internal;
  static_assert(sfe::holds_only_patch_parameters<NamedParameters>(),
                "segment_into_patches: a parameter of another stage");
  const Sharp_feature_extraction_context<GeomTraits, ConcurrencyTag> context(points, network.scales, np);
  return context.segment_into_patches(network, patches);
}

} // namespace CGAL

#endif
