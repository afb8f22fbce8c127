// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_REPAIR_POLYLINES_FOR_MESH_3_H
#define CGAL_SHARP_FEATURE_EXTRACTION_REPAIR_POLYLINES_FOR_MESH_3_H

#include <CGAL/Sharp_feature_extraction/Mesh_3_polyline_repair_report.h>
#include <CGAL/Sharp_feature_extraction/find_mesh_3_polyline_problems.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_repair.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// repairs `polylines` in place so that `Mesh_domain_with_polyline_features_3::add_features()`
/// accepts them: afterwards `find_mesh_3_polyline_problems()`, called with the same named
/// parameters, finds nothing (polylines that cannot be repaired are dropped and counted).
///
/// Polylines that already satisfy the contract are returned unchanged, with a report of zeros.
/// Otherwise, in this order: non-finite points and zero-length segments are removed; points
/// are inserted on segments longer than half the tolerance (the shape does not change); ends
/// closer than the tolerance become one shared point (an end already shared exactly is kept,
/// otherwise their centroid); an open polyline whose ends meet becomes a closed loop; a
/// polyline running within the tolerance along a longer one is dropped as a duplicate; turns
/// sharper than the maximum angle are split; polylines are split where an end of another lies
/// on them, and where two cross, at one shared point; polylines shorter than the minimum length
/// are dropped (closed loops: three times that length); last, of two polylines still closer
/// than the tolerance without sharing a point there, the shorter is dropped.
///
/// \tparam Point_3 a point type of a CGAL kernel
/// \param polylines the polylines, each a sequence of points; changed in place
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of `Point_3`, from `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{threshold_distance}
///     \cgalParamDescription{the tolerance: points closer than this become one point, polylines
///                           closer than this are made to meet or are dropped}
///     \cgalParamType{`double`}
///     \cgalParamDefault{a thousandth of the diagonal of the bounding box of the polylines}
///     \cgalParamExtra{about half the smallest mesh edge size asked of Mesh_3 is a good
///                     choice; for extracted curves, 1.5 times the sampling spacing (what
///                     `reconstruct_surface_with_sharp_features()` uses)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_angle}
///     \cgalParamDescription{a polyline that turns by more than this angle, in degrees, is split there}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60, the angle at which the extraction splits its curves}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_length}
///     \cgalParamDescription{open polylines shorter than this are dropped}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0: only polylines of zero length are dropped}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was changed, counted.
template <typename Point_3, typename NamedParameters = parameters::Default_named_parameters>
Mesh_3_polyline_repair_report
repair_polylines_for_mesh_3(std::vector<std::vector<Point_3>>& polylines,
                            const NamedParameters& np = parameters::default_values())
{
  typedef typename Kernel_traits<Point_3>::Kernel Default_traits;
  typedef typename internal_np::Lookup_named_param_def<internal_np::geom_traits_t, NamedParameters,
                                                       Default_traits>::type Geom_traits;
  namespace mp = Sharp_feature_extraction::internal::mesh_polylines;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  Mesh_3_polyline_repair_report report;
  report.input_polylines = report.output_polylines = polylines.size();
  std::vector<Feature_polyline<Geom_traits>> curves = mp::as_feature_polylines<Geom_traits>(polylines);
  const mp::Contract_tolerances tolerances = mp::contract_tolerances(curves, np);
  if(mp::find_contract_violations(curves, tolerances).empty())
    return report;

  mp::Repair_settings settings;
  settings.tolerance = tolerances.distance;
  settings.maximum_angle = tolerances.angle;
  settings.minimum_length = choose_parameter(get_parameter(np, internal_np::minimum_length), 0.);
  report = mp::repair_feature_polylines(curves, settings);
  polylines.clear();
  for(const auto& c : curves)
    polylines.push_back(std::vector<Point_3>(c.points.begin(), c.points.end()));
  return report;
}

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_REPAIR_POLYLINES_FOR_MESH_3_H
