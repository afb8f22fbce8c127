// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The whole package: the extraction context, every stage function, the function that runs
// them all, the tiled extraction, the patches and the height-field partition, the Mesh_3 check
// and repair of polylines, and the polyline I/O. Not included, because they need more than
// CGAL: the surface reconstruction (Mesh_3 and Poisson), the point-cloud coder (OpenJPEG); and
// not the point readers (IO/read_point_cloud.h, IO/read_LAS_points.h, IO/write_LAS_points.h).

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_H
#define CGAL_SHARP_FEATURE_EXTRACTION_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/Sharp_feature_extraction_context.h>
#include <CGAL/Sharp_feature_extraction/estimate_sharp_feature_scales.h>
#include <CGAL/Sharp_feature_extraction/compute_candidate_points.h>
#include <CGAL/Sharp_feature_extraction/rmls_project_candidates.h>
#include <CGAL/Sharp_feature_extraction/smooth_feature_points.h>
#include <CGAL/Sharp_feature_extraction/grow_feature_polylines.h>
#include <CGAL/Sharp_feature_extraction/complete_feature_polylines.h>
#include <CGAL/Sharp_feature_extraction/segment_into_patches.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/estimate_sharp_feature_scales_for_tiles.h>
#include <CGAL/Sharp_feature_extraction/tile_halo_width.h>
#include <CGAL/Sharp_feature_extraction/extract_tile_features.h>
#include <CGAL/Sharp_feature_extraction/stitch_tile_features.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features_in_tiles.h>
#include <CGAL/Sharp_feature_extraction/partition_into_height_fields.h>
#include <CGAL/Sharp_feature_extraction/find_mesh_3_polyline_problems.h>
#include <CGAL/Sharp_feature_extraction/repair_polylines_for_mesh_3.h>
#include <CGAL/Sharp_feature_extraction/IO/read_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>

#endif
