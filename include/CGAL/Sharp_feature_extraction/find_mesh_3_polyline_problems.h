// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_FIND_MESH_3_POLYLINE_PROBLEMS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_FIND_MESH_3_POLYLINE_PROBLEMS_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_contract.h>
#include <CGAL/Sharp_feature_extraction/internal/Spatial_grid.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// One reason why `Mesh_domain_with_polyline_features_3::add_features()` could reject a set of
/// polylines, as found by `find_mesh_3_polyline_problems()`.
struct Mesh_3_polyline_problem
{
  /// What is wrong.
  enum Kind {
    TOO_FEW_POINTS,      ///< a polyline with fewer than two points
    NON_FINITE_POINT,    ///< a coordinate is infinite or NaN
    ZERO_LENGTH_SEGMENT, ///< two consecutive points are equal
    DEGENERATE_LOOP,     ///< a closed polyline with fewer than three distinct points
    UNSHARED_END,        ///< an end lies near an end (of another polyline, or of its own) without being that point
    END_ON_INTERIOR,     ///< an end lies on the interior of a polyline, which is not split there
    SHARP_TURN,          ///< the polyline turns by more than the maximum angle inside
    UNSHARED_CONTACT     ///< vertices of two polylines (or far apart along one) are close without being one point
  };
  /// What is wrong.
  Kind kind = TOO_FEW_POINTS;
  /// The index of the polyline concerned.
  std::size_t polyline = 0;
  /// The index of the other polyline involved (`polyline` itself when there is none).
  std::size_t other_polyline = 0;
  /// One line of explanation, for people.
  std::string description;
};

namespace Sharp_feature_extraction {
namespace internal {
namespace mesh_polylines {

/// The tolerance and the angle of the contract, from the named parameters.
struct Contract_tolerances
{
  double distance = 0;
  double angle = Mesh_polyline_contract::sharp_turn_angle;
};

/// The default tolerance: a thousandth of the bounding-box diagonal of the polylines, far below
/// any mesh size Mesh_3 could be given for them, far above rounding errors.
constexpr double default_tolerance_fraction = 1e-3;

template <typename Curve>
double default_tolerance(const std::vector<Curve>& curves)
{
  CGAL::Bbox_3 box;
  for(const Curve& c : curves)
    for(const auto& p : c.points)
      if(is_finite_point(p))
        box += p.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  return std::isfinite(diagonal) && diagonal > 0 ? default_tolerance_fraction * diagonal : 1.;
}

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

/// The check itself, on anything with `points` (see `find_mesh_3_polyline_problems()`).
template <typename Curve>
std::vector<Mesh_3_polyline_problem> find_contract_violations(const std::vector<Curve>& input,
                                                              const Contract_tolerances& tolerances)
{
  typedef typename std::remove_const<typename std::remove_reference<decltype(input[0].points[0])>::type>::type Point_3;
  typedef Mesh_3_polyline_problem Problem;
  const double tolerance = tolerances.distance;
  std::vector<Problem> problems;
  auto say = [&](typename Problem::Kind kind, std::size_t c, std::size_t other, const std::string& what) {
    problems.push_back(Problem{kind, c, other, "polyline " + std::to_string(c) + ": " + what});
  };
  // the proximity tests look at vertices: on a copy whose segments are short against the
  // tolerance, they see the whole polylines
  std::vector<Curve> curves = input;
  for(Curve& c : curves)
    densify(c, Mesh_polyline_contract::densify_fraction * tolerance);
  Spatial_grid<Point_3> ends(tolerance), interiors(tolerance);
  std::vector<std::size_t> interior_owner;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const auto& pts = curves[c].points;
    if(pts.size() < 2) {
      say(Problem::TOO_FEW_POINTS, c, c, "fewer than two points");
      continue;
    }
    for(std::size_t i = 0; i < pts.size(); ++i) {
      if(!is_finite_point(pts[i]))
        say(Problem::NON_FINITE_POINT, c, c, "non-finite point");
      else if(i > 0 && pts[i] == pts[i - 1])
        say(Problem::ZERO_LENGTH_SEGMENT, c, c, "repeated consecutive point");
    }
    if(pts.front() == pts.back() && pts.size() < 4)
      say(Problem::DEGENERATE_LOOP, c, c, "closed with fewer than three distinct points");
    for(std::size_t i : sharp_turn_vertices(curves[c], tolerance, tolerances.angle, true))
      say(Problem::SHARP_TURN, c, c, "turns by more than the maximum angle at vertex " + std::to_string(i));
    ends.insert(pts.front(), 2 * c);
    ends.insert(pts.back(), 2 * c + 1);
    for(std::size_t i = 1; i + 1 < pts.size(); ++i) {
      interiors.insert(pts[i], interior_owner.size());
      interior_owner.push_back(c);
    }
  }
  for(std::size_t c = 0; c < curves.size(); ++c) {
    const auto& pts = curves[c].points;
    if(pts.size() < 2)
      continue;
    for(const Point_3& q : {pts.front(), pts.back()}) {
      ends.for_each_within(q, tolerance, [&](std::size_t other, double) {
        const auto& o = curves[other / 2].points;
        const Point_3& r = other % 2 == 0 ? o.front() : o.back();
        if(r != q && other / 2 >= c)
          say(Problem::UNSHARED_END, c, other / 2,
              "end nearly meets an end of polyline " + std::to_string(other / 2) + " without sharing it");
      });
      interiors.for_each_within(q, tolerance * Mesh_polyline_contract::merge_fraction, [&](std::size_t id, double) {
        say(Problem::END_ON_INTERIOR, c, interior_owner[id],
            "end lies on the interior of polyline " + std::to_string(interior_owner[id]));
      });
    }
  }
  for(const Unshared_contact& contact : find_unshared_contacts<Curve, Point_3>(curves, tolerance)) {
    std::ostringstream what;
    what << "a vertex is " << contact.distance << " from a vertex of polyline " << contact.b
         << " without sharing a point";
    say(Problem::UNSHARED_CONTACT, contact.a, contact.b, what.str());
  }
  return problems;
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
