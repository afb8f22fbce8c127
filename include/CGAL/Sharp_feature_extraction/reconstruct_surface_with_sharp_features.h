// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header includes Mesh_3 and Poisson_implicit_surface_3 (a heavy compilation); the
// extraction headers never include it.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_RECONSTRUCT_SURFACE_WITH_SHARP_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_RECONSTRUCT_SURFACE_WITH_SHARP_FEATURES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/Surface_reconstruction_report.h>
#include <CGAL/Sharp_feature_extraction/internal/reconstruction/reconstruction_impl.h>

#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {

namespace internal_np {
enum protect_polylines_t { protect_polylines };
enum correct_normals_t { correct_normals };
enum sharpen_creases_t { sharpen_creases };
enum facet_size_t { facet_size };
enum facet_distance_t { facet_distance };
enum edge_size_t { edge_size };
enum facet_angle_t { facet_angle };
enum unresponsive_mesher_handler_t { unresponsive_mesher_handler };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgSharpFeatureExtractionRef
/// Named parameters of `reconstruct_surface_with_sharp_features()` that CGAL's own list does
/// not have; they chain with CGAL's parameters like those of `parameters.h`.
/// Protect the polylines in Mesh_3 (a `bool`).
CGAL_SFE_NAMED_PARAMETER(protect_polylines)
/// Give the points near a polyline the normal of their own side of the crease (a `bool`).
CGAL_SFE_NAMED_PARAMETER(correct_normals)
/// Replace the implicit function near the polylines by the two surfaces that meet there (a `bool`).
CGAL_SFE_NAMED_PARAMETER(sharpen_creases)
/// Mesh_3's largest radius of a surface Delaunay ball (a length).
CGAL_SFE_NAMED_PARAMETER(facet_size)
/// Mesh_3's largest distance from a facet to the surface (a length).
CGAL_SFE_NAMED_PARAMETER(facet_distance)
/// Mesh_3's largest mesh edge along a protected polyline (a length).
CGAL_SFE_NAMED_PARAMETER(edge_size)
/// Mesh_3's smallest facet angle (degrees).
CGAL_SFE_NAMED_PARAMETER(facet_angle)
/// What to do when Mesh_3 is stuck (a `std::function<void(double)>`).
CGAL_SFE_NAMED_PARAMETER(unresponsive_mesher_handler)

} // namespace parameters

namespace internal {
namespace reconstruction {

template <typename NamedParameters>
Reconstruction_settings reconstruction_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace own = Sharp_feature_extraction::internal_np;
  Reconstruction_settings s;
  s.protect_polylines = choose_parameter(get_parameter(np, own::protect_polylines), true);
  s.correct_normals = choose_parameter(get_parameter(np, own::correct_normals), true);
  s.sharpen_creases = choose_parameter(get_parameter(np, own::sharpen_creases), true);
  s.facet_size = choose_parameter(get_parameter(np, own::facet_size), 0.);
  s.facet_distance = choose_parameter(get_parameter(np, own::facet_distance), 0.);
  s.edge_size = choose_parameter(get_parameter(np, own::edge_size), 0.);
  s.facet_angle = choose_parameter(get_parameter(np, own::facet_angle), Reconstruction_constants::facet_angle);
  s.time_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  s.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  s.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  s.unresponsive_handler =
    choose_parameter(get_parameter(np, own::unresponsive_mesher_handler), std::function<void(double)>());
  return s;
}

} // namespace reconstruction
} // namespace internal
} // namespace Sharp_feature_extraction

/// \ingroup PkgSharpFeatureExtractionRef
/// reconstructs the closed surface sampled by `points` as a triangle mesh whose creases follow
/// the feature polylines of `features` (the paper's reconstruction application): Poisson
/// surface reconstruction, sharpened near the polylines, meshed by Mesh_3 with the polylines
/// protected.
///
/// The steps: the polylines are repaired for Mesh_3 (as by `repair_polylines_for_mesh_3()`,
/// with a tolerance of 0.94 times the spacing, polylines shorter than 1.9 spacings dropped, the
/// network's corners preferred as junction points); normals are estimated by jet fitting and
/// oriented along the sheets of the surface (a spanning tree that does not cross thin walls);
/// near a polyline, a point gets the normal of its own side of the crease, from two quadric
/// patches fitted on either side; Poisson's implicit function is replaced near the polylines by
/// the two patches, so that the creases stay sharp; the polyline vertices are moved onto that
/// function's zero set (a polyline is cut where it is farther than 1.25 spacings from it, or
/// where the zero set has another sheet nearer than `edge_size` along the vertex's normal: a
/// wall or a gap thinner than Mesh_3's protecting balls, whose refinement would not end); where
/// these moves and cuts undid the repair, it runs again (the vertices it moves are moved onto the
/// zero set again), and a polyline that still fails `find_mesh_3_polyline_problems()` is
/// dropped; Mesh_3 meshes the zero set with the polylines protected, with manifold output.
///
/// Every size is relative to `features.scales.spacing` (the mean distance to the 6th nearest
/// neighbour) and `features.scales.noise`: pass the network computed by
/// `extract_sharp_features()` on the same points. With `protect_polylines`, `correct_normals`
/// and `sharpen_creases` all `false`, the same pipeline runs without the polylines (for
/// comparison).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
///         (the normal estimation)
/// \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
/// \tparam GeomTraits a CGAL kernel
///
/// \param points the sampled points (no normals needed)
/// \param features the feature curves and the scales of the points, from `extract_sharp_features()`;
///        polylines whose `normals` do not match their `points` are used for protection only
/// \param output_points receives the vertices of the surface
/// \param output_triangles receives its triangles, as indices into `output_points`, oriented
///        consistently (outward when the surface is closed)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` with value type `GeomTraits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the fraction of the work done, in [0, 1]; while Mesh_3
///                           runs (a step that cannot tell its progress) it is called about 5
///                           times per second with the same fraction. Returning `false` stops the
///                           reconstruction: the function returns with `stopped` set in the report,
///                           and the surface Mesh_3 had when it stopped (none before it started)}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{while Mesh_3 runs, it is called from another thread}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{Mesh_3 is stopped after this many seconds (the report says `stopped`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0: no limit}
///     \cgalParamExtra{Mesh_3 is also stopped beyond 2 vertices per input point: a refinement
///                     finer than the sampling is running away}
///   \cgalParamNEnd
///   \cgalParamNBegin{unresponsive_mesher_handler}
///     \cgalParamDescription{called once, from another thread, with the seconds elapsed, when
///                           Mesh_3 is still running at twice `maximum_running_time`. Mesh_3
///                           (CGAL 5.5) reads its stop flag only while it refines; stuck in the
///                           protection of the polylines, it may never return, and only the
///                           process can end it: a program may print why and exit from here}
///     \cgalParamType{`std::function<void(double)>`}
///     \cgalParamDefault{none: keep waiting}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{the seed of Mesh_3's random initial points}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{protect_polylines}
///     \cgalParamDescription{protect the polylines in Mesh_3}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{correct_normals}
///     \cgalParamDescription{give the points near a polyline the normal of their own side}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sharpen_creases}
///     \cgalParamDescription{replace the implicit function near the polylines by the two surfaces meeting there}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_size}
///     \cgalParamDescription{Mesh_3's largest radius of a surface Delaunay ball}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.875 times the spacing}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_distance}
///     \cgalParamDescription{Mesh_3's largest distance from a facet to the surface}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.0625 times the spacing, or the noise scale if larger (a facet distance
///                       below the noise would chase its bumps)}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_size}
///     \cgalParamDescription{Mesh_3's largest mesh edge along a protected polyline}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.875 times the spacing}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_angle}
///     \cgalParamDescription{Mesh_3's smallest facet angle, in degrees}
///     \cgalParamType{`double`}
///     \cgalParamDefault{25}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was done: sizes, repairs, counts, timings, and whether Mesh_3 was stopped.
///          A surface that is not stopped is closed and manifold in all the benchmark's valid
///          runs; check it if you depend on it.
/// \throws Surface_reconstruction_error when no surface can be made (fewer than 100 points,
///         `features.scales.spacing` not positive, Poisson's solver failing, Mesh_3 failing an
///         assertion, or no surface found).
template <typename ConcurrencyTag, typename PointRange, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
Surface_reconstruction_report<GeomTraits>
reconstruct_surface_with_sharp_features(const PointRange& points, const Feature_curve_network<GeomTraits>& features,
                                        std::vector<typename GeomTraits::Point_3>& output_points,
                                        std::vector<std::array<std::size_t, 3>>& output_triangles,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename internal_np::Lookup_named_param_def<internal_np::point_t, NamedParameters,
                                                       Identity_property_map<Point_3>>::type Point_map;
  namespace rc = Sharp_feature_extraction::internal::reconstruction;
  const Point_map point_map = parameters::choose_parameter<Point_map>(parameters::get_parameter(np, internal_np::point_map));
  std::vector<Point_3> positions;
  for(const auto& p : points)
    positions.push_back(get(point_map, p));
  Surface_reconstruction_report<GeomTraits> report;
  auto surface = rc::reconstruct<GeomTraits, ConcurrencyTag>(positions, features, rc::reconstruction_settings(np), report);
  output_points = std::move(surface.points);
  output_triangles = std::move(surface.triangles);
  return report;
}

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_RECONSTRUCT_SURFACE_WITH_SHARP_FEATURES_H
