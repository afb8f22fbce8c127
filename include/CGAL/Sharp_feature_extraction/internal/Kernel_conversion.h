// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The result types from one geometric traits to another: the stages compute with
// `Working_traits` (double precision), the user reads the results in the user's kernel. Like
// CGAL's Cartesian_converter, one template per result type, whatever the two traits.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_KERNEL_CONVERSION_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_KERNEL_CONVERSION_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

typedef Eigen::Vector3d Vec3;

/// The coordinates of a point or vector of any kernel (or of a `Vec3`), in double precision.
template <typename PointOrVector>
Vec3 to_vec3(const PointOrVector& p)
{
  return Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

template <typename Target, typename PointOrVector>
typename Target::Point_3 convert_point(const PointOrVector& p)
{
  const Vec3 v = to_vec3(p);
  return typename Target::Point_3(v.x(), v.y(), v.z());
}

template <typename Target, typename PointOrVector>
typename Target::Vector_3 convert_vector(const PointOrVector& p)
{
  const Vec3 v = to_vec3(p);
  return typename Target::Vector_3(v.x(), v.y(), v.z());
}

template <typename TargetFT, typename SourceFT>
Sharp_feature_scales<TargetFT> convert_scales(const Sharp_feature_scales<SourceFT>& s)
{
  auto value = [](const SourceFT& x) { return TargetFT(CGAL::to_double(x)); };
  Sharp_feature_scales<TargetFT> out;
  out.spacing = value(s.spacing);
  out.noise = value(s.noise);
  out.candidate_neighbors = s.candidate_neighbors;
  out.candidate_radius = value(s.candidate_radius);
  out.rmls_neighbors = s.rmls_neighbors;
  out.residual_threshold = value(s.residual_threshold);
  out.rmls_tolerance = value(s.rmls_tolerance);
  out.corner_radius = value(s.corner_radius);
  out.growth_radius = value(s.growth_radius);
  out.completion_distance = value(s.completion_distance);
  out.sampled_fraction = value(s.sampled_fraction);
  out.search_fraction = value(s.search_fraction);
  return out;
}

template <typename Target, typename Source>
Feature_point_set<Target> convert_feature_points(const Feature_point_set<Source>& f)
{
  Feature_point_set<Target> out;
  out.edge_points.reserve(f.edge_points.size());
  for(const Edge_point<Source>& e : f.edge_points)
    out.edge_points.push_back(Edge_point<Target>{
      convert_point<Target>(e.point),
      {{convert_vector<Target>(e.normals[0]), convert_vector<Target>(e.normals[1])}},
      e.source});
  for(const Corner_point<Source>& c : f.corner_points)
    out.corner_points.push_back(Corner_point<Target>{
      convert_point<Target>(c.point),
      {{convert_vector<Target>(c.normals[0]), convert_vector<Target>(c.normals[1]),
        convert_vector<Target>(c.normals[2])}},
      typename Target::FT(CGAL::to_double(c.weight)), c.source});
  out.scales = convert_scales<typename Target::FT>(f.scales);
  return out;
}

/// The network in `Target`. Shared corner points and closed loops stay exact: every
/// occurrence of a point is converted from the same coordinates, deterministically.
template <typename Target, typename Source>
Feature_curve_network<Target> convert_network(const Feature_curve_network<Source>& net)
{
  Feature_curve_network<Target> out;
  for(const Feature_corner<Source>& k : net.corners)
  {
    Feature_corner<Target> corner;
    corner.point = convert_point<Target>(k.point);
    for(const auto& n : k.normals)
      corner.normals.push_back(convert_vector<Target>(n));
    corner.incident_polylines = k.incident_polylines;
    out.corners.push_back(std::move(corner));
  }
  for(const Feature_polyline<Source>& curve : net.polylines)
  {
    Feature_polyline<Target> p;
    p.points.reserve(curve.points.size());
    for(const auto& v : curve.points)
      p.points.push_back(convert_point<Target>(v));
    p.normals.reserve(curve.normals.size());
    for(const auto& n : curve.normals)
      p.normals.push_back({{convert_vector<Target>(n[0]), convert_vector<Target>(n[1])}});
    p.front_corner = curve.front_corner;
    p.back_corner = curve.back_corner;
    out.polylines.push_back(std::move(p));
  }
  out.scales = convert_scales<typename Target::FT>(net.scales);
  return out;
}

template <typename Target, typename Source>
Surface_patches<Target> convert_patches(const Surface_patches<Source>& in)
{
  Surface_patches<Target> out;
  out.labels = in.labels;
  out.adjacencies = in.adjacencies;
  for(const Surface_patch<Source>& patch : in.patches)
  {
    Surface_patch<Target> converted;
    converted.number_of_points = patch.number_of_points;
    converted.centroid = convert_point<Target>(patch.centroid);
    converted.normal = convert_vector<Target>(patch.normal);
    converted.plane_residual = typename Target::FT(CGAL::to_double(patch.plane_residual));
    converted.quadric_residual = typename Target::FT(CGAL::to_double(patch.quadric_residual));
    converted.bounding_polylines = patch.bounding_polylines;
    out.patches.push_back(std::move(converted));
  }
  return out;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
