// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_FIND_MESH_3_POLYLINE_PROBLEMS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_FIND_MESH_3_POLYLINE_PROBLEMS_H

#include <CGAL/Sharp_feature_extraction/Mesh_3_polyline_problem.h>
#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_contract.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <vector>

namespace CGAL {

namespace Sharp_feature_extraction {
namespace internal {
namespace mesh_polylines {

template <typename Curve, typename NamedParameters>
Contract_tolerances contract_tolerances(const std::vector<Curve>& curves, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Contract_tolerances t;
  t.distance = is_default_parameter<NamedParameters, CGAL::internal_np::threshold_distance_t>::value
                 ? default_tolerance(curves)
                 : double(choose_parameter(get_parameter(np, CGAL::internal_np::threshold_distance), 0.));
  t.angle = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_angle),
                             Mesh_polyline_contract::sharp_turn_angle);
  return t;
}

/// The polylines as feature polylines without normals: the type the repair works on.
template <typename GeomTraits, typename Point_3>
std::vector<Feature_polyline<GeomTraits>> as_feature_polylines(const std::vector<std::vector<Point_3>>& polylines)
{
  std::vector<Feature_polyline<GeomTraits>> curves(polylines.size());
  for(std::size_t i = 0; i < polylines.size(); ++i)
    curves[i].points.assign(polylines[i].begin(), polylines[i].end());
  return curves;
}

} // namespace mesh_polylines
} // namespace internal
} // namespace Sharp_feature_extraction

/// \ingroup PkgSharpFeatureExtractionRef
/// checks whether `polylines` can be given as they are to
/// `Mesh_domain_with_polyline_features_3::add_features()`, and lists what is wrong if not. The
/// contract checked is the one `repair_polylines_for_mesh_3()` establishes:
/// - every polyline has two points or more, all finite, and no zero-length segment;
/// - polylines meet only at their ends, and polylines meeting at a point share it exactly
///   (ends closer than the tolerance are one point; an end never lies on the interior of a
///   polyline);
/// - a closed polyline repeats its first point exactly at its end, and has three distinct
///   points or more;
/// - no polyline turns by more than the maximum angle inside (turns measured between chords
///   reaching the tolerance along the polyline on each side, so that a zigzag of a few vertices
///   does not count, at vertices farther than the tolerance from both ends);
/// - no vertices of two polylines, or of one polyline far apart along it, are closer than the
///   tolerance without being one point, except where two polylines leave a point they share
///   at 5 degrees or more: near-duplicate, overlapping and crossing polylines are problems.
///
/// The proximity tests see the whole segments, not only the vertices.
///
/// \tparam Point_3 a point type of a CGAL kernel
/// \param polylines the polylines, each a sequence of points
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of `Point_3`, from `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{threshold_distance}
///     \cgalParamDescription{the tolerance: points closer than this must be one point}
///     \cgalParamType{`double`}
///     \cgalParamDefault{a thousandth of the diagonal of the bounding box of the polylines}
///     \cgalParamExtra{use the same value as for `repair_polylines_for_mesh_3()`; about half the
///                     smallest mesh edge size asked of Mesh_3 is a good choice}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_angle}
///     \cgalParamDescription{the largest turn, in degrees, allowed inside one polyline}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60, the angle at which the extraction splits its curves}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the problems found, in no particular order; empty when the polylines can be
///          protected as they are.
template <typename Point_3, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Mesh_3_polyline_problem>
find_mesh_3_polyline_problems(const std::vector<std::vector<Point_3>>& polylines,
                              const NamedParameters& np = parameters::default_values())
{
  typedef typename Kernel_traits<Point_3>::Kernel Default_traits;
  typedef typename internal_np::Lookup_named_param_def<internal_np::geom_traits_t, NamedParameters,
                                                       Default_traits>::type Geom_traits;
  namespace mp = Sharp_feature_extraction::internal::mesh_polylines;
  const auto curves = mp::as_feature_polylines<Geom_traits>(polylines);
  return mp::find_contract_violations(curves, mp::contract_tolerances(curves, np));
}

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_FIND_MESH_3_POLYLINE_PROBLEMS_H
