// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The docstrings of the Python module `sharp_features` (what `help()` shows), kept apart from
// the bindings so that both read easily.

#ifndef SFE_PYTHON_SHARP_FEATURES_DOCSTRINGS_H
#define SFE_PYTHON_SHARP_FEATURES_DOCSTRINGS_H

namespace docstrings {

constexpr const char* module = R"doc(Sharp feature curves of a point cloud.

The five stages of Daniels et al. 2007 (candidate points, RMLS projection, smoothing,
polyline growing, completion), as implemented by the C++ package
CGAL::Sharp_feature_extraction, on a NumPy array of points:

    import numpy as np, sharp_features
    points = np.loadtxt("cloud.xyz")[:, :3]
    result = sharp_features.extract(points, sharpness_angle=30)
    print(len(result.polylines), "curves,", len(result.corners), "corners")
    result.write_polylines("curves.polylines.txt")
)doc";

constexpr const char* cancelled = R"doc(Raised by extract() when the progress function returns False.

No partial result is returned. Ctrl-C raises KeyboardInterrupt instead, and an exception
raised by the progress function propagates unchanged.)doc";

constexpr const char* extract = R"doc(Extracts the sharp feature curves of a point cloud.

Parameters
----------
points : array_like, shape (N, 3)
    The point coordinates; no normals are needed. A C-contiguous float64 array is read in place;
    any other array (float32, non-contiguous, a list of triples) is converted once.
threads : int or None
    Number of threads (None: all cores). The result does not depend on it. The limit is
    process-wide while the call runs.
progress : callable or None
    Called on the calling thread with the fraction of the work done (a float in [0, 1]).
    Returning False (or any false value except None) cancels: extract() then raises
    sharp_features.Cancelled. An exception it raises stops the run and propagates.
    Ctrl-C also cancels (KeyboardInterrupt), with or without a progress function.

The other keywords are the named parameters of CGAL::extract_sharp_features(), under the
same names; None, or leaving one out, selects its default:

degree_fitting : int
    Degree of the fitted height fields: 1 (planes) or 2 (quadrics). Default 2.
threshold_distance : float
    Candidate threshold tau (a distance); negative: derived from the data (the default).
sharpness_angle : float
    Smallest angle, in degrees, between the normals of two surfaces at a sharp feature,
    in (0, 90). Default 25.
number_of_iterations : int
    Number of smoothing passes (stage 3). Default 3.
maximum_angle : float
    Half-angle, in degrees, of the completion search cone at a free end, in (0, 90). Default 30.
number_of_relaxation_steps : int
    Laplacian smoothing passes over the completed curves (stage 5). Default 2.
candidate_neighbors, rmls_neighbors : int
    Number of points in a stage-1 and in a stage-2 (RMLS) neighbourhood. 0: derived from the
    data (the default).
rmls_tolerance, corner_radius, growth_radius, completion_distance : float
    Distances: the largest residual of a point on a smooth surface (stage 2), the radius
    within which corner points are one corner, the polyline growing radius, the largest gap
    bridged by completion. 0: derived from the data (the default).

Result.scales reports the scales used, derived or given.

Returns
-------
Result
    The curves, their normals, the corners, the surface patches, the scales and the timings.

Raises
------
ValueError
    A coordinate or a parameter is out of range (NaN, infinity, an angle outside (0, 90)...),
    with the library's message, or points does not have shape (N, 3).
TypeError
    An unknown keyword, or a value of the wrong type.
Cancelled
    The progress function returned False.
)doc";

constexpr const char* result = R"doc(The sharp feature curves of a point cloud, as extract() returns them.

The coordinates are float64 arrays that belong to the result; curves meeting at a corner share
its exact point, and a closed curve repeats its first point at the end.)doc";

constexpr const char* polylines = R"doc(The curves.

A list of (n, 3) arrays, one per curve, the vertices in order along it.)doc";

constexpr const char* normals = R"doc(The normals of the two surfaces meeting along each curve.

A list of (n, 2, 3) arrays: normals[i][j] holds the two unit normals at polylines[i][j], each
oriented away from the other surface, in the same order along the whole curve.)doc";

constexpr const char* corners = R"doc(The corners where curves end.

An (m, 3) array of points; corner_polylines gives the curves incident to each.)doc";

constexpr const char* corner_polylines = R"doc(The curves incident to each corner.

A list of m integer arrays: corner_polylines[k] holds the indices (into polylines) of the curves
that start or end at corners[k].)doc";

constexpr const char* patches = R"doc(The surface patch of every input point.

An (N,) int64 array in the order of the points: the index of the patch that the curves enclose
the point in (CGAL::segment_into_patches(): regions that never cross a curve), or -1 for a point
in no patch (an outlier). Copies of a point share its patch.)doc";

constexpr const char* scales = R"doc(The scales the extraction used, derived from the data or given.

A dict with the fields of CGAL::Sharp_feature_scales: spacing, noise, candidate_neighbors,
candidate_radius, rmls_neighbors, residual_threshold, rmls_tolerance, corner_radius,
growth_radius, completion_distance, sampled_fraction, search_fraction.)doc";

constexpr const char* timings = R"doc(Wall-clock seconds of each step.

A dict: context (reading the points and estimating the scales), candidates, projection,
smoothing, growing, completion, and total.)doc";

constexpr const char* result_repr = R"doc(A one-line summary: the numbers of curves and corners.)doc";

constexpr const char* write_polylines = R"doc(Writes the curves in Mesh_3's polyline format.

One curve per line, "n x1 y1 z1 ... xn yn zn", every double written so that it reads back
exactly: the file the extract_sharp_features program writes with -o. path is a str or an
os.PathLike; raises OSError if the file cannot be written.)doc";

constexpr const char* write_ply = R"doc(Writes the curves as an ASCII PLY.

The curve vertices with both normals, a corner flag and a curve index, and one edge per
segment: the file the extract_sharp_features program writes with --ply. path is a str or an
os.PathLike; raises OSError if the file cannot be written.)doc";

constexpr const char* estimate_scales = R"doc(Estimates, once for a whole cloud, the scales every tile shares.

CGAL::estimate_sharp_feature_scales_for_tiles(): the scales of extract() from a regular
subsample of at most 20,000 points, and the stage-1 candidate threshold (residual_threshold)
from the residuals of the same subsample, so that every tile uses one threshold.

points may be the whole cloud or a part that keeps its sampling density (whole tiles, never
every k-th point: a sparser cloud has a larger spacing and every scale follows it).

Keywords: threads (as for extract()), and those of extract() that set the scales:
degree_fitting, threshold_distance, candidate_neighbors, rmls_neighbors, rmls_tolerance,
corner_radius, growth_radius, completion_distance.

Returns
-------
dict
    The fields of CGAL::Sharp_feature_scales (see Result.scales), to give to tile_halo_width(),
    extract_tile() and every worker.
)doc";

constexpr const char* tile_halo_width = R"doc(The halo a tile needs around its core box, a distance.

CGAL::tile_halo_width(): the points given to extract_tile() must be those within this distance
of the core box (along each axis), so that the tile's feature points are exactly those of the
whole cloud. scales is the dict estimate_scales() returns; the keyword number_of_iterations
(default 3) must be the one given to extract_tile().

Raises
------
ValueError
    scales lacks a field, a distance in it is negative or not finite, its sampled_fraction is
    not in (0, 1], or its search_fraction is not in (0, sampled_fraction].
)doc";

constexpr const char* extract_tile = R"doc(Stages 1 to 3 on one tile: the feature points its core box owns.

CGAL::extract_tile_features(). points are the tile's points: the core box [box_min, box_max)
(half-open on every axis: a point on a max face belongs to the next tile) and its halo of
tile_halo_width(scales). scales is the dict estimate_scales() returns, the same for every tile.
The keywords are threads and progress (as for extract()) and degree_fitting, sharpness_angle and
number_of_iterations.

Returns
-------
TileResult
    The edge and corner points whose source point lies in the core box; picklable.

Raises
------
ValueError
    A coordinate, a parameter or a scale is out of range (see tile_halo_width()), or box_min is
    not below box_max on every axis.
Cancelled
    The progress function returned False.
)doc";

constexpr const char* stitch_tiles = R"doc(Joins the tiles of a cloud into its feature curves.

CGAL::stitch_tile_features(): the tiles' feature points form the feature points of the whole
cloud; the curves are grown and completed through all of them at once (stages 4 and 5), so they
cross the tile faces without a gap or a duplicate, share their corners and close their loops.
The result does not depend on the order of tiles. Keywords: progress, maximum_angle and
number_of_relaxation_steps.

Returns
-------
Result
    The curves, corners, scales and timings (summed over the tiles); Result.patches is empty
    (the patches need the whole cloud).

Raises
------
ValueError
    The tiles have different scales or overlapping core boxes.
)doc";

constexpr const char* extract_tiled = R"doc(Extracts the sharp feature curves of a point cloud tile by tile.

CGAL::extract_sharp_features_in_tiles(): estimate_scales() once, extract_tile() on each cell of
a grid of at least `tiles` cells (default 8) over the bounding box, one tile at a time, then
stitch_tiles(). The curves are those of extract() given threshold_distance equal to the tiled
scales' residual_threshold. Keywords: those of extract().

Returns
-------
Result
    As stitch_tiles() returns it (Result.patches is empty).
)doc";

constexpr const char* tile_result = R"doc(The feature points of one tile, as extract_tile() returns them.

Picklable (its state is a dict of NumPy arrays and numbers), so that it can be sent between
processes; stitch_tiles() takes a list of them.)doc";

constexpr const char* tile_state = R"doc(The tile as a dict (its pickled state).

core_min, core_max: the core box; edge_points (n, 3), edge_normals (n, 2, 3), edge_sources (n,):
the edge points, the normals of their two surfaces and the index of their source point in the
tile's points; corner_points (m, 3), corner_normals (m, 3, 3), corner_weights (m,),
corner_sources (m,); scales; number_of_core_points, number_of_candidates; timings.)doc";

constexpr const char* tile_repr = R"doc(A one-line summary: the numbers of edge and corner points.)doc";

} // namespace docstrings

#endif
