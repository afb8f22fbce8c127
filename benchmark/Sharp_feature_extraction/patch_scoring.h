// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scores surface patches against the true patches of a mesh: its faces joined across the edges
// that are not sharp (so that a crease fading out does not split a face), carried to every
// point of a cloud by its nearest triangle.

#ifndef SFE_BENCHMARK_PATCH_SCORING_H
#define SFE_BENCHMARK_PATCH_SCORING_H

#include "ground_truth.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <numeric>
#include <vector>

namespace sfe_bench {

/// A share of the points: true patches below it are not scored, and our patches below it are
/// not counted (slivers of a few points).
constexpr double counted_patch_share = 0.001;

/// The true patch of every face of `mesh`: faces joined across every edge shared by exactly
/// two faces whose normals differ by at most `angle_degrees` (the creases of the ground truth
/// are exactly the other edges).
inline std::vector<std::size_t> true_patch_of_faces(const Indexed_mesh& mesh, double angle_degrees)
{
  const std::size_t n = mesh.faces.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> faces_of_edge;
  for(std::size_t f = 0; f < n; ++f)
  {
    const std::vector<std::size_t>& face = mesh.faces[f];
    for(std::size_t i = 0; i < face.size(); ++i)
    {
      const std::size_t a = face[i], b = face[(i + 1) % face.size()];
      faces_of_edge[{(std::min)(a, b), (std::max)(a, b)}].push_back(f);
    }
  }
  for(const auto& entry : faces_of_edge)
  {
    const std::vector<std::size_t>& faces = entry.second;
    if(faces.size() == 2
       && internal::angle_in_degrees(internal::face_normal(mesh, mesh.faces[faces[0]]),
                                     internal::face_normal(mesh, mesh.faces[faces[1]])) <= angle_degrees)
    {
      const std::size_t a = find(faces[0]), b = find(faces[1]);
      parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  }
  std::vector<std::size_t> patch(n), number(n, n);
  std::size_t count = 0;
  for(std::size_t f = 0; f < n; ++f)
  {
    const std::size_t root = find(f);
    if(number[root] == n)
      number[root] = count++;
    patch[f] = number[root];
  }
  return patch;
}

/// The true patch of every point: that of its nearest face (polygons fanned into triangles).
inline std::vector<std::size_t> true_patch_of_points(const Indexed_mesh& mesh, const std::vector<std::size_t>& face_patch,
                                                     const std::vector<Point>& points)
{
  typedef K::Triangle_3 Triangle;
  typedef std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  std::vector<Triangle> triangles;
  std::vector<std::size_t> face_of_triangle;
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
    for(std::size_t i = 1; i + 1 < mesh.faces[f].size(); ++i)
    {
      const Triangle t(mesh.vertices[mesh.faces[f][0]], mesh.vertices[mesh.faces[f][i]], mesh.vertices[mesh.faces[f][i + 1]]);
      if(t.is_degenerate())
        continue;
      triangles.push_back(t);
      face_of_triangle.push_back(f);
    }
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  std::vector<std::size_t> patch(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const auto nearest = tree.closest_point_and_primitive(points[i]);
    patch[i] = face_patch[face_of_triangle[std::size_t(nearest.second - triangles.cbegin())]];
  }
  return patch;
}

struct Patch_scores
{
  /// True patches holding at least `counted_patch_share` of the points, and ours.
  std::size_t true_patches = 0, our_patches = 0;
  /// Mean over those true patches of the intersection over union with their best-matching
  /// patch of ours (the points in no patch of ours count in the union only).
  double mean_iou = 0;
  /// Adjusted Rand index of the two labellings (points in no patch form one more label).
  double adjusted_rand_index = 0;
  /// Share of the points in no patch.
  double unassigned = 0;
};

/// Scores `ours` (one label per point, `unassigned` for none) against `truth`.
inline Patch_scores score_patches(const std::vector<std::size_t>& truth, const std::vector<std::size_t>& ours,
                                  std::size_t unassigned)
{
  Patch_scores scores;
  const double n = double(truth.size());
  if(truth.empty())
    return scores;
  std::map<std::pair<std::size_t, std::size_t>, double> both;
  std::map<std::size_t, double> true_size, our_size;
  for(std::size_t i = 0; i < truth.size(); ++i)
  {
    both[{truth[i], ours[i]}] += 1;
    true_size[truth[i]] += 1;
    our_size[ours[i]] += 1;
  }
  for(const auto& [label, size] : our_size)
    if(label != unassigned && size >= counted_patch_share * n)
      ++scores.our_patches;
  scores.unassigned = our_size.count(unassigned) ? our_size[unassigned] / n : 0.;
  double iou_sum = 0;
  for(const auto& [label, size] : true_size)
  {
    if(size < counted_patch_share * n)
      continue;
    ++scores.true_patches;
    double best = 0;
    for(const auto& [key, common] : both)
      if(key.first == label && key.second != unassigned)
        best = (std::max)(best, common / (size + our_size[key.second] - common));
    iou_sum += best;
  }
  scores.mean_iou = scores.true_patches > 0 ? iou_sum / double(scores.true_patches) : 0.;
  auto pairs = [](double m) { return m * (m - 1) / 2; };
  double index = 0, true_pairs = 0, our_pairs = 0;
  for(const auto& entry : both)
    index += pairs(entry.second);
  for(const auto& entry : true_size)
    true_pairs += pairs(entry.second);
  for(const auto& entry : our_size)
    our_pairs += pairs(entry.second);
  const double expected = true_pairs * our_pairs / pairs(n), largest = (true_pairs + our_pairs) / 2;
  scores.adjusted_rand_index = largest > expected ? (index - expected) / (largest - expected) : 1.;
  return scores;
}

} // namespace sfe_bench

#endif
