// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_MESH_3_POLYLINE_REPAIR_REPORT_H
#define CGAL_SHARP_FEATURE_EXTRACTION_MESH_3_POLYLINE_REPAIR_REPORT_H

#include <cstddef>
#include <sstream>
#include <string>
#include <utility>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// What `repair_polylines_for_mesh_3()` changed, counted. All counts are zero when the
/// polylines were left as they were.
struct Mesh_3_polyline_repair_report
{
  /// Number of polylines given.
  std::size_t input_polylines = 0;
  /// Number of polylines returned.
  std::size_t output_polylines = 0;
  /// Points removed: non-finite points, and points closer than a thousandth of the tolerance
  /// to the previous one (zero-length segments).
  std::size_t removed_points = 0;
  /// Points inserted on segments longer than half the tolerance, so that the proximity
  /// repairs see the whole segments (the shape of the polylines does not change).
  std::size_t inserted_points = 0;
  /// Ends moved onto a junction point shared with the other ends near it.
  std::size_t snapped_ends = 0;
  /// Open polylines whose two ends became one point: closed loops.
  std::size_t closed_loops = 0;
  /// Splits where an end of a polyline, or another polyline, touched the interior of one.
  std::size_t junction_splits = 0;
  /// Splits at turns sharper than the maximum angle.
  std::size_t sharp_turn_splits = 0;
  /// Polylines dropped because they were shorter than the minimum length, or degenerate.
  std::size_t dropped_short = 0;
  /// Polylines dropped because they ran along a longer one (near-duplicates).
  std::size_t dropped_duplicates = 0;
  /// Points removed where a polyline still came closer than the tolerance to another one (or to
  /// itself, far along it) without sharing a point there: they are cut out of one of the two
  /// (the shorter; of a polyline touching itself, the pass nearer one of its ends), which the
  /// other covers there within the tolerance.
  std::size_t removed_in_contact = 0;
  /// Polylines dropped because they still came closer than the tolerance to another one
  /// without sharing a point there after the cuts (the last resort of the repair).
  std::size_t dropped_in_contact = 0;
  /// Feature polylines whose normals did not match their points and were removed (the
  /// reconstruction only: plain polylines have no normals).
  std::size_t discarded_normals = 0;

  /// `true` if the polylines were changed.
  bool changed() const
  {
    return removed_points + inserted_points + snapped_ends + closed_loops + junction_splits + sharp_turn_splits +
             dropped_short + dropped_duplicates + removed_in_contact + dropped_in_contact + discarded_normals > 0;
  }

  /// One line for people, listing the counts that are not zero.
  std::string summary() const
  {
    std::ostringstream out;
    out << input_polylines << " polylines in, " << output_polylines << " out";
    const std::pair<const char*, std::size_t> items[] = {
      {"points removed", removed_points},           {"points inserted", inserted_points},
      {"ends snapped", snapped_ends},               {"loops closed", closed_loops},
      {"junction splits", junction_splits},         {"sharp-turn splits", sharp_turn_splits},
      {"short polylines dropped", dropped_short},   {"duplicates dropped", dropped_duplicates},
      {"points in contact removed", removed_in_contact}, {"polylines in contact dropped", dropped_in_contact},
      {"normals discarded", discarded_normals}};
    for(const auto& item : items)
      if(item.second > 0)
        out << ", " << item.second << " " << item.first;
    return out.str();
  }
};

} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_MESH_3_POLYLINE_REPAIR_REPORT_H
