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
/// \param np any named parameter of `estimate_sharp_feature_scales()` and of the five stage
///   functions.
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
/// exact point. Same parameters as the overload that fills a `Sharp_features`.
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
