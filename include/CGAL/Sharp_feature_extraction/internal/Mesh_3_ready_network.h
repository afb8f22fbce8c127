// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The last step of stage 5: the completed curve network is made to satisfy the Mesh_3 contract
// (internal/Mesh_polyline_contract.h) with the tolerance that `find_mesh_3_polyline_problems()`
// uses by default, by the same repair that `repair_polylines_for_mesh_3()` applies to a user's
// polylines. Unlike that function it keeps what the network knows: the corners (with their
// normals) and the two normals of every curve vertex, and it gives the vertices back as they
// were (the repair inserts vertices along the segments to see the whole curves).

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_3_READY_NETWORK_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_3_READY_NETWORK_H

#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_repair.h>

#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// The repair computes with CGAL's predicates and constructions: on this kernel, with the same
/// doubles as the working traits (the conversions both ways are exact).
typedef CGAL::Simple_cartesian<double> Repair_kernel;
typedef Feature_curve_network<Repair_kernel> Repair_network;

/// A point as a key of an exact comparison (curves share points exactly or not at all).
typedef std::array<double, 3> Exact_point_key;

inline Exact_point_key exact_key(const Repair_kernel::Point_3& p) { return {{p.x(), p.y(), p.z()}}; }

/// Removes the interior vertices that the repair inserted and did not move (they lie on the
/// segments between the vertices of the input): every vertex the repair moved became the end
/// of a piece, so the pieces keep their shape and the vertex density of stage 5.
inline void remove_inserted_vertices(Repair_network& network, const std::set<Exact_point_key>& input_vertices)
{
  for(Feature_polyline<Repair_kernel>& curve : network.polylines)
  {
    Feature_polyline<Repair_kernel> kept = curve;
    kept.points.clear();
    kept.normals.clear();
    const bool with_normals = curve.normals.size() == curve.points.size();
    for(std::size_t v = 0; v < curve.points.size(); ++v)
    {
      const bool end = v == 0 || v + 1 == curve.points.size();
      if(!end && input_vertices.count(exact_key(curve.points[v])) == 0)
        continue;
      kept.points.push_back(curve.points[v]);
      if(with_normals)
        kept.normals.push_back(curve.normals[v]);
    }
    curve = std::move(kept);
  }
}

/// After the repair, the corners are the points where curve ends meet: the corners of the
/// network that are still curve ends (with their normals), then the points shared by the ends
/// of two curves or more (where the repair split or joined curves; their normals are those of
/// the first curve's end vertex). A loop whose two ends alone meet passes through no corner.
inline void rebuild_corners(Repair_network& network, const std::vector<Feature_corner<Repair_kernel>>& old_corners)
{
  std::map<Exact_point_key, std::vector<std::pair<std::size_t, bool>>> ends_at;
  for(std::size_t c = 0; c < network.polylines.size(); ++c)
    for(bool back : {false, true})
    {
      const auto& points = network.polylines[c].points;
      ends_at[exact_key(back ? points.back() : points.front())].emplace_back(c, back);
    }
  std::map<Exact_point_key, std::size_t> corner_at;
  network.corners.clear();
  for(const Feature_corner<Repair_kernel>& corner : old_corners)
    if(ends_at.count(exact_key(corner.point)) != 0 && corner_at.count(exact_key(corner.point)) == 0)
    {
      corner_at[exact_key(corner.point)] = network.corners.size();
      network.corners.push_back(Feature_corner<Repair_kernel>{corner.point, corner.normals, {}});
    }
  for(Feature_polyline<Repair_kernel>& curve : network.polylines)
  {
    curve.front_corner = curve.back_corner = no_index;
    for(bool back : {false, true})
    {
      const auto& point = back ? curve.points.back() : curve.points.front();
      const auto& meeting = ends_at[exact_key(point)];
      const bool only_own_loop = meeting.size() == 2 && meeting[0].first == meeting[1].first;
      auto found = corner_at.find(exact_key(point));
      if(found == corner_at.end())
      {
        if(meeting.size() < 2 || only_own_loop)
          continue;
        Feature_corner<Repair_kernel> corner;
        corner.point = point;
        if(!curve.normals.empty())
        {
          const auto& pair = back ? curve.normals.back() : curve.normals.front();
          corner.normals.assign(pair.begin(), pair.end());
        }
        found = corner_at.emplace(exact_key(point), network.corners.size()).first;
        network.corners.push_back(corner);
      }
      (back ? curve.back_corner : curve.front_corner) = found->second;
    }
  }
}

/// Makes the curves of `network` pass `find_mesh_3_polyline_problems()` with its default
/// tolerance (see `Mesh_polyline_contract`): ends within the tolerance are snapped together
/// (onto a corner if there is one), curves are split where an end or another curve touches
/// them and at sharp turns, duplicates and curves still in contact are dropped.
inline void make_network_mesh_3_ready(Working_network& working)
{
  namespace mp = mesh_polylines;
  Repair_network network = convert_network<Repair_kernel>(working);
  mp::Repair_settings settings;
  settings.tolerance = mp::default_tolerance(network.polylines);
  settings.maximum_angle = mp::Mesh_polyline_contract::sharp_turn_angle;
  if(mp::find_contract_violations(network.polylines, mp::Contract_tolerances{settings.tolerance, settings.maximum_angle})
       .empty())
    return;
  std::set<Exact_point_key> input_vertices;
  std::vector<Repair_kernel::Point_3> corner_points;
  for(const auto& curve : network.polylines)
    for(const auto& p : curve.points)
      input_vertices.insert(exact_key(p));
  for(const auto& corner : network.corners)
    corner_points.push_back(corner.point);
  const std::vector<Feature_corner<Repair_kernel>> old_corners = network.corners;
  mp::repair_feature_polylines(network.polylines, settings, corner_points);
  remove_inserted_vertices(network, input_vertices);
  rebuild_corners(network, old_corners);
  working = convert_network<Working_traits>(network);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_MESH_3_READY_NETWORK_H
