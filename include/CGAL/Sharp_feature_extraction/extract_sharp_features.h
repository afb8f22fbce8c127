// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_SHARP_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_EXTRACT_SHARP_FEATURES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
// The stage functions and the scales, so that one include gives the whole pipeline, stage by
// stage too.
#include <CGAL/Sharp_feature_extraction/estimate_sharp_feature_scales.h>
#include <CGAL/Sharp_feature_extraction/compute_candidate_points.h>
#include <CGAL/Sharp_feature_extraction/rmls_project_candidates.h>
#include <CGAL/Sharp_feature_extraction/smooth_feature_points.h>
#include <CGAL/Sharp_feature_extraction/grow_feature_polylines.h>
#include <CGAL/Sharp_feature_extraction/complete_feature_polylines.h>
#include <CGAL/Sharp_feature_extraction/segment_into_patches.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// Extracts the sharp feature curves of a point cloud: the five stages of Daniels et al. 2007
/// (`compute_candidate_points()`, `rmls_project_candidates()`, `smooth_feature_points()`,
/// `grow_feature_polylines()`, `complete_feature_polylines()`), with every intermediate result.
///
/// The default call needs only the points: every scale is derived from the data (see
/// `estimate_sharp_feature_scales()` and `Sharp_feature_scales`) and `result.network.scales`
/// reports the values used. It builds a `Sharp_feature_extraction_context` and runs its five
/// stages; build one yourself to run the stages one at a time on the same points.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`. The result does not depend on the number of threads.
/// \param points the input points; no normals are needed.
/// \param result receives the curves, corners, normals and every intermediate point set.
/// \param np optional named parameters among the ones listed below: those of
///   `estimate_sharp_feature_scales()` and of the five stage functions.
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
///     \cgalParamExtra{this overload computes in the traits of `result` (its template argument
///       `GeomTraits`); the parameter matters to the overload that writes polylines, whose point
///       type it gives}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{read by the noise estimation, stage 1 and stage 2 (which fits planes on
///       noisy data whatever this value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{threshold_distance}
///     \cgalParamDescription{the candidate threshold tau (a distance): a point whose residual
///       exceeds it is a candidate}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the mean residual of the points whose residual is at most the radius of a
///       stage-1 neighbourhood; on noisy clouds at most 1.3 times the median residual}
///     \cgalParamExtra{read by stage 1 (`compute_candidate_points()`); a negative value selects
///       the default}
///   \cgalParamNEnd
///   \cgalParamNBegin{sharpness_angle}
///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces that
///       meet at a sharp feature}
///     \cgalParamType{`double`}
///     \cgalParamDefault{25}
///     \cgalParamExtra{read by stage 2 (`rmls_project_candidates()`); must be in (0, 90)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{number of smoothing passes}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{3}
///     \cgalParamExtra{read by stage 3 (`smooth_feature_points()`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_angle}
///     \cgalParamDescription{half-angle, in degrees, of the completion search cone at a free end}
///     \cgalParamType{`double`}
///     \cgalParamDefault{30}
///     \cgalParamExtra{read by stage 5 (`complete_feature_polylines()`); must be in (0, 90)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_relaxation_steps}
///     \cgalParamDescription{number of Laplacian smoothing passes over the completed curves}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{2}
///     \cgalParamExtra{read by stage 5 (`complete_feature_polylines()`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a function that receives the progress and can stop the computation}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{called, on the calling thread, with the fraction of the work done (from 0
///       to 1) by stages 1 to 4 (stage 5, short, is not interrupted); when it returns `false` the
///       computation stops and the function returns `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors}
///     \cgalParamDescription{number of points in a stage-1 neighbourhood}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]. Read by
///       the scale estimation and stage 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors}
///     \cgalParamDescription{number of points in a stage-2 (RMLS) neighbourhood}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]. Read by
///       stage 2}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance}
///     \cgalParamDescription{largest residual (a distance) of a point that belongs to a smooth
///       surface in the forward search of stage 2}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default. Read by stage 2}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius}
///     \cgalParamDescription{corner points closer than this distance are grouped into one corner}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default. Read by stage 2}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius}
///     \cgalParamDescription{neighbourhood radius of polyline growing}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default. Read by stage 4}
///   \cgalParamNEnd
///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance}
///     \cgalParamDescription{largest gap bridged by completion}
///     \cgalParamType{`double` (a distance)}
///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
///     \cgalParamExtra{0 selects the default. Read by stage 5}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `false` if the `callback` interrupted the computation (the result is then partial).
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
///
/// Exact duplicates count once (every stage merges them: they add no surface information), so a
/// cloud and the same cloud with its points repeated, in any number, give the same curves. A
/// cloud with fewer than 20 distinct points yields no curves (and the function returns `true`).
template <typename ConcurrencyTag, typename PointRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
bool extract_sharp_features(const PointRange& points, Sharp_features<GeomTraits>& result,
                            const NamedParameters& np = parameters::default_values())
{
  const Sharp_feature_extraction_context<GeomTraits, ConcurrencyTag> context(points, np);
  return context.extract_sharp_features(result);
}

/// \ingroup PkgSharpFeatureExtractionRef
/// Extracts the sharp feature curves of a point cloud and writes each one, as a
/// `std::vector<Point_3>`, to `polylines`: the format `Mesh_domain_with_polyline_features_3::add_features()`
/// takes. Closed curves repeat their first point exactly; curves meeting at a corner share that
/// exact point.
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`. The result does not depend on the number of threads.
/// \param points the input points; no normals are needed.
/// \param polylines an output iterator that accepts `std::vector<geom_traits::Point_3>`.
/// \param np optional named parameters: the same as for the overload that fills a
///   `Sharp_features` (listed there), except that `geom_traits` gives the point type of the
///   polylines:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `SharpFeatureExtractionTraits`}
///     \cgalParamDefault{the kernel of the point type of `point_map`}
///     \cgalParamExtra{the polylines are `std::vector<geom_traits::Point_3>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
/// \returns `false` if the `callback` interrupted the computation (nothing is written then).
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
std::enable_if_t<!std::is_base_of<Sharp_features<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>,
                                  OutputIterator>::value, bool>
extract_sharp_features(const PointRange& points, OutputIterator polylines,
                       const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  Sharp_features<GT> result;
  if(!extract_sharp_features<ConcurrencyTag>(points, result, np))
    return false;
  for(const Feature_polyline<GT>& p : result.network.polylines)
    *polylines++ = p.points;
  return true;
}

} // namespace CGAL

#endif
