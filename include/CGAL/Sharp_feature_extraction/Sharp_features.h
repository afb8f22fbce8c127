// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Result types of the sharp feature extraction pipeline: what every stage returns.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_SHARP_FEATURES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_SHARP_FEATURES_H

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// The scales that drive every stage. Each one is derived from the data when the extraction
/// context is built (see `estimate_sharp_feature_scales()`) unless the user overrides it with a
/// named parameter; the values actually used are reported here so that a run can be reproduced.
template <typename FT>
struct Sharp_feature_scales
{
  /// Sampling spacing: the mean, over the points, of the distance to their 6th nearest
  /// neighbour. (CGAL's `compute_average_spacing()` with 6 neighbours is 1.6 times smaller on
  /// uniform samples of CGAL's fandisk, anchor and pinion.)
  FT spacing = 0;
  /// Noise scale, about the RMS of the noise along the normal: the RMS residual of jets fitted
  /// to neighbourhoods wider than the noise band (see `CGAL::estimate_sharp_feature_scales()`).
  FT noise = 0;
  /// Number of points in a stage-1 (candidate) neighbourhood.
  std::size_t candidate_neighbors = 0;
  /// Radius of a stage-1 neighbourhood: the median distance from a point to its
  /// `candidate_neighbors`-th nearest neighbour.
  FT candidate_radius = 0;
  /// Number of points in a stage-2 (RMLS) neighbourhood.
  std::size_t rmls_neighbors = 0;
  /// Candidate threshold tau on the stage-1 residual (a distance).
  FT residual_threshold = 0;
  /// RMLS tolerance: largest residual (a distance) of a point that belongs to a smooth surface.
  FT rmls_tolerance = 0;
  /// Radius within which corner points are grouped into one corner (stage 2).
  FT corner_radius = 0;
  /// Neighbourhood radius used to grow polylines (stage 4).
  FT growth_radius = 0;
  /// Largest gap that completion bridges (stage 5).
  FT completion_distance = 0;
  /// Fraction of the distinct input points to which stage 2 fits its surfaces: 1, unless the
  /// noise spans so many spacings that the stage-1 neighbourhoods it calls for would hold more
  /// than 400 points. The cloud is then thinned to the fraction that leaves 400 in their
  /// radius, by a hash of each point's coordinates (so that a tile keeps the points the whole
  /// cloud keeps; see `CGAL::estimate_sharp_feature_scales()`).
  FT sampled_fraction = 1;
  /// Fraction of the distinct input points on which stage 1 and the forward search of stage 2
  /// run: 1, unless the noise calls for stage-1 neighbourhoods of more than 100 points. The
  /// sampled points are then thinned further, by the same hash, to the fraction that leaves 100
  /// in their radius, and each point kept moves to the mean of the sampled points that it
  /// represents (those nearer to it than to any other point kept). `spacing` and the
  /// neighbourhood sizes are those of the means, every other point takes the results of the
  /// mean that represents it, and stage 2 refines the surfaces that it finds on the means on
  /// the sampled points, which the patches then split (see `CGAL::segment_into_patches()`). At
  /// most `sampled_fraction`.
  FT search_fraction = 1;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Output of stage 1 (`compute_candidate_points()`).
template <typename GeomTraits>
struct Candidate_points
{
  /// The number type of the kernel.
  typedef typename GeomTraits::FT FT;
  /// Residual r(p) of every input point, in input order: the largest distance, along the
  /// fit normal, from a neighbour of p to the jet fitted to p's neighbourhood.
  std::vector<FT> residuals;
  /// Indices (into the input range) of the points whose residual exceeds the threshold.
  std::vector<std::size_t> indices;
  /// The scales derived from the data (or given by the user), used by every later stage.
  Sharp_feature_scales<FT> scales;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// A point on the intersection of two smooth surfaces, with the normals of both.
/// The normals are unit vectors, each oriented away from the other surface: outward on a
/// convex crease, inward on a concave one.
template <typename GeomTraits>
struct Edge_point
{
  /// The point on the crease.
  typename GeomTraits::Point_3 point;
  /// Unit normals of the two surfaces at `point`, each oriented away from the other surface.
  std::array<typename GeomTraits::Vector_3, 2> normals;
  /// Index of the input point this edge point was projected from.
  std::size_t source = 0;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// A point where three (or more) smooth surfaces meet, with the normals of the three.
template <typename GeomTraits>
struct Corner_point
{
  /// The common point of the three surfaces.
  typename GeomTraits::Point_3 point;
  /// Unit normals of the three surfaces at `point`, each oriented away from the other two.
  std::array<typename GeomTraits::Vector_3, 3> normals;
  /// Confidence 1/|c - e|, where e is the edge projection of the same candidate.
  typename GeomTraits::FT weight = 0;
  /// Index of the input point this corner point was projected from.
  std::size_t source = 0;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Output of stages 2 and 3: the feature point cloud F = E u C.
template <typename GeomTraits>
struct Feature_point_set
{
  /// Points on the intersection of two surfaces, with both normals.
  std::vector<Edge_point<GeomTraits>> edge_points;
  /// Points where three surfaces meet: one per corner, after grouping (stage 2).
  std::vector<Corner_point<GeomTraits>> corner_points;
  /// The scales the stages were run with.
  Sharp_feature_scales<typename GeomTraits::FT> scales;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// A feature curve. An open curve runs from `points.front()` to `points.back()`; a closed one
/// repeats its first point exactly at the end. `normals[i]` are the normals of the two surfaces
/// meeting at `points[i]`, in the same order and orientation along the whole curve.
template <typename GeomTraits>
struct Feature_polyline
{
  /// Value of `front_corner` and `back_corner` for an end that is not at a corner.
  static constexpr std::size_t no_corner = (std::numeric_limits<std::size_t>::max)();

  /// The vertices, in order along the curve.
  std::vector<typename GeomTraits::Point_3> points;
  /// The normals of the two surfaces at each vertex: `normals[i]` belongs to `points[i]`.
  std::vector<std::array<typename GeomTraits::Vector_3, 2>> normals;
  /// Index (into `Feature_curve_network::corners`) of the corner the curve starts at, or `no_corner`.
  std::size_t front_corner = no_corner;
  /// Index of the corner the curve ends at, or `no_corner`.
  std::size_t back_corner = no_corner;

  /// `true` if the last point repeats the first exactly: a closed loop (which may start and
  /// end at a corner).
  bool is_closed() const { return points.size() > 2 && points.front() == points.back(); }
};

/// \ingroup PkgSharpFeatureExtractionRef
/// A corner of the curve network: its point is shared exactly by every incident curve.
template <typename GeomTraits>
struct Feature_corner
{
  /// The corner point, exactly equal to the end point of every incident curve.
  typename GeomTraits::Point_3 point;
  /// Normals of the surfaces meeting at the corner: three when it came from a corner point or
  /// from a corner of valence 4 that completion split in two, otherwise the two normals of the
  /// curve vertex where completion created it.
  std::vector<typename GeomTraits::Vector_3> normals;
  /// Indices (into `Feature_curve_network::polylines`) of the curves that start or end here.
  std::vector<std::size_t> incident_polylines;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Output of stages 4 and 5: polylines and the corners where they meet.
template <typename GeomTraits>
struct Feature_curve_network
{
  /// The curves.
  std::vector<Feature_polyline<GeomTraits>> polylines;
  /// The corners. Before completion (stage 4), every corner point of stage 2; after completion,
  /// only the corners where curves end.
  std::vector<Feature_corner<GeomTraits>> corners;
  /// The scales the curves were computed with.
  Sharp_feature_scales<typename GeomTraits::FT> scales;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// A surface patch (paper, section 3.6): a region of the points that the feature curves
/// enclose, with the surface fitted to it.
template <typename GeomTraits>
struct Surface_patch
{
  /// The number of distinct input points in the patch.
  std::size_t number_of_points = 0;
  /// The centroid of its points.
  typename GeomTraits::Point_3 centroid;
  /// Unit normal of the least-squares plane of its points (its orientation is arbitrary:
  /// the points carry none).
  typename GeomTraits::Vector_3 normal;
  /// Root-mean-square distance from its points to that plane.
  typename GeomTraits::FT plane_residual = 0;
  /// Root-mean-square distance, along `normal`, from its points to the least-squares quadric
  /// height field over that plane (large where the patch is not a height field, e.g. a
  /// cylinder turning by more than half a turn).
  typename GeomTraits::FT quadric_residual = 0;
  /// Indices (into `Feature_curve_network::polylines`) of the curves along which it meets
  /// another patch, ascending.
  std::vector<std::size_t> bounding_polylines;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Two patches that meet along a curve: on its two sides.
struct Patch_adjacency
{
  /// The patch on one side (the smaller index).
  std::size_t first_patch = 0;
  /// The patch on the other side.
  std::size_t second_patch = 0;
  /// Index of the curve in `Feature_curve_network::polylines`.
  std::size_t polyline = 0;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Output of `segment_into_patches()`: a patch for every input point, and the patches.
template <typename GeomTraits>
struct Surface_patches
{
  /// Value of a label for a point in no patch (an outlier).
  static constexpr std::size_t unassigned = (std::numeric_limits<std::size_t>::max)();

  /// For every input point, in input order: the index of its patch in `patches`, or
  /// `unassigned`. Copies of a point share its label.
  std::vector<std::size_t> labels;
  /// The patches, numbered in the spatial order of their first point.
  std::vector<Surface_patch<GeomTraits>> patches;
  /// The pairs of patches that meet along a curve, by curve, then by patches.
  std::vector<Patch_adjacency> adjacencies;
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Wall-clock time of each stage, in seconds.
struct Sharp_feature_timings
{
  /// Building the extraction context: reading, checking and indexing the input points and
  /// estimating the scales.
  double context = 0;
  /// Stage 1.
  double candidates = 0;
  /// Stage 2.
  double projection = 0;
  /// Stage 3.
  double smoothing = 0;
  /// Stage 4.
  double growing = 0;
  /// Stage 5.
  double completion = 0;
  /// The sum of the context and the five stages.
  double total() const { return context + candidates + projection + smoothing + growing + completion; }
};

/// \ingroup PkgSharpFeatureExtractionRef
/// Everything `extract_sharp_features()` computes: the final curves and every intermediate
/// point set, for inspection.
template <typename GeomTraits>
struct Sharp_features
{
  /// Final curves and corners (after completion).
  Feature_curve_network<GeomTraits> network;
  /// Stage 1: candidate points and residuals.
  Candidate_points<GeomTraits> candidates;
  /// Stage 2: RMLS-projected edge and corner points.
  Feature_point_set<GeomTraits> projected;
  /// Stage 3: smoothed feature points.
  Feature_point_set<GeomTraits> smoothed;
  /// Stage 4: polylines before completion.
  Feature_curve_network<GeomTraits> grown;
  /// Wall-clock time of each stage.
  Sharp_feature_timings timings;
};

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_SHARP_FEATURES_H
