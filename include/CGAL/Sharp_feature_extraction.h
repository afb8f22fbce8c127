// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The whole package: the extraction context, every stage function, the function that runs
// them all, and the I/O.

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
#include <CGAL/Sharp_feature_extraction/IO/read_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>

#endif
