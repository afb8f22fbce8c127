// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The split-merge partition of a point cloud into height fields (Ochotta and Saupe 2004,
// section 3): split until every piece is a height field over its own plane, then merge
// neighbouring pieces while their union stays one.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_HEIGHT_FIELD_PARTITION_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_HEIGHT_FIELD_PARTITION_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Number of nearest points whose plane gives a point's normal: two rings around it on a
/// uniform sample, enough to average the sampling irregularity.
constexpr std::size_t height_field_normal_neighbors = 12;
/// Number of nearest points a point links to: the links define which pieces are neighbours
/// and which points of a piece are connected (one ring on a uniform sample).
constexpr std::size_t height_field_link_neighbors = 6;
/// Pieces with fewer points have no plane: they are height fields by definition.
constexpr std::size_t smallest_split_piece = 3;
/// Pieces left with fewer points after the merge are absorbed by a neighbour: a frame would
/// cost more than their points, and they are mostly points of a crease, whose normals (the
/// plane of neighbours on both sides) lean away from every piece.
constexpr std::size_t smallest_piece = height_field_normal_neighbors;

/// What the partition needs of the cloud: an unoriented normal per point and its links.
struct Height_field_cloud
{
  std::vector<Vec3> points;
  std::vector<Vec3> normals;
  /// `links[i * height_field_link_neighbors + j]`: the j-th nearest other point of point i.
  std::vector<std::size_t> links;
  /// Mean distance from a point to its 6th nearest neighbour (as `Sharp_feature_scales::spacing`).
  double spacing = 0;

  std::size_t size() const { return points.size(); }
};

/// Normals, links and spacing of `points`; false if `progress` was cancelled.
template <typename ConcurrencyTag>
bool build_height_field_cloud(std::vector<Vec3> points, Progress& progress, Height_field_cloud& out)
{
  out.points = std::move(points);
  const std::size_t n = out.points.size();
  Point_index index;
  index.build<ConcurrencyTag>(out.points);
  out.normals.assign(n, Vec3::UnitZ());
  out.links.assign(n * height_field_link_neighbors, 0);
  std::vector<double> sixth(n, 0.);
  const bool done = parallel_blocks<ConcurrencyTag>(n, progress, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> near;
    for(std::size_t i = first; i < last; ++i)
    {
      index.nearest(out.points[i], height_field_normal_neighbors + 1, near, true);
      Principal_axes axes;
      if(compute_principal_axes(near.size(), [&](std::size_t j) { return out.points[near[j]]; }, axes))
        out.normals[i] = axes.axes.col(0);
      // near[0] is the point itself (or a copy of it); a point with fewer neighbours than
      // links links to itself, which joins nothing.
      for(std::size_t j = 0; j < height_field_link_neighbors; ++j)
        out.links[i * height_field_link_neighbors + j] = j + 1 < near.size() ? near[j + 1] : i;
      const std::size_t sixth_rank = 6;
      sixth[i] = near.size() > sixth_rank ? (out.points[near[sixth_rank]] - out.points[i]).norm() : 0.;
    }
  });
  double sum = 0;
  for(double d : sixth)
    sum += d;
  out.spacing = n > 0 ? sum / double(n) : 0.;
  return done;
}

/// The bound a piece must meet: every point's normal within `maximum_angle` of the piece's
/// plane normal, and no two layers over one cell of side `grid_spacing`.
struct Height_field_bound
{
  double cos_maximum_angle = 0;
  /// Largest height difference of two points over one cell of a height field whose slope the
  /// angle bounds: a cell diagonal times the steepest slope, twice for the normals' error.
  double layer_tolerance = 0;
  double grid_spacing = 0;

  Height_field_bound(double maximum_angle_degrees, double grid_spacing)
    : cos_maximum_angle(std::cos(maximum_angle_degrees * CGAL_PI / 180.)),
      layer_tolerance(2 * std::sqrt(2.) * std::tan(maximum_angle_degrees * CGAL_PI / 180.) * grid_spacing),
      grid_spacing(grid_spacing)
  {}
};

/// How far a set of points is from a height field over its least-squares plane.
struct Height_field_test
{
  Principal_axes axes;
  /// The smallest |cosine| between a point's normal and the plane normal.
  double smallest_cosine = 1;
  /// Whether two points over one grid cell lie farther apart in height than the bound allows.
  bool layered = false;

  bool passes(const Height_field_bound& bound) const
  {
    return smallest_cosine >= bound.cos_maximum_angle && !layered;
  }
};

/// Whether two of `cells` (cell coordinates and height, sorted or not) over one cell differ in
/// height by more than `tolerance`.
inline bool has_layers(std::vector<std::tuple<std::int64_t, std::int64_t, double>>& cells, double tolerance)
{
  std::sort(cells.begin(), cells.end());
  for(std::size_t first = 0, last = 0; first < cells.size(); first = last)
  {
    while(last < cells.size() && std::get<0>(cells[last]) == std::get<0>(cells[first]) &&
          std::get<1>(cells[last]) == std::get<1>(cells[first]))
      ++last;
    // Sorted by height within a cell: its first and last are its lowest and highest.
    if(std::get<2>(cells[last - 1]) - std::get<2>(cells[first]) > tolerance)
      return true;
  }
  return false;
}

/// Tests `members` against `bound`. The layers are only looked for when the normals pass (a
/// piece that fails both is split across its longest axis).
inline Height_field_test test_height_field(const Height_field_cloud& cloud, const std::vector<std::size_t>& members,
                                           const Height_field_bound& bound)
{
  Height_field_test t;
  compute_principal_axes(members.size(), [&](std::size_t j) { return cloud.points[members[j]]; }, t.axes);
  const Vec3 normal = t.axes.axes.col(0), u = t.axes.axes.col(2), v = t.axes.axes.col(1);
  for(std::size_t i : members)
    t.smallest_cosine = (std::min)(t.smallest_cosine, std::abs(cloud.normals[i].dot(normal)));
  if(t.smallest_cosine < bound.cos_maximum_angle)
    return t;
  std::vector<std::tuple<std::int64_t, std::int64_t, double>> cells;
  cells.reserve(members.size());
  for(std::size_t i : members)
  {
    const Vec3 d = cloud.points[i] - t.axes.centroid;
    cells.emplace_back(std::int64_t(std::floor(d.dot(u) / bound.grid_spacing)),
                       std::int64_t(std::floor(d.dot(v) / bound.grid_spacing)), d.dot(normal));
  }
  t.layered = has_layers(cells, bound.layer_tolerance);
  return t;
}

/// Splits `group` (indices of points sharing `piece[i] == id`) into its connected components
/// along the links, appended to `components`.
inline void connected_components(const Height_field_cloud& cloud, const std::vector<std::size_t>& group,
                                 std::vector<std::size_t>& mark, std::vector<std::vector<std::size_t>>& components)
{
  // mark[i]: 1 while i is in the group and unvisited, 0 otherwise.
  for(std::size_t i : group)
    mark[i] = 1;
  std::vector<std::size_t> stack;
  for(std::size_t seed : group)
  {
    if(mark[seed] == 0)
      continue;
    std::vector<std::size_t> component;
    mark[seed] = 0;
    stack.push_back(seed);
    while(!stack.empty())
    {
      const std::size_t i = stack.back();
      stack.pop_back();
      component.push_back(i);
      for(std::size_t j = 0; j < height_field_link_neighbors; ++j)
      {
        const std::size_t k = cloud.links[i * height_field_link_neighbors + j];
        if(mark[k] == 1)
        {
          mark[k] = 0;
          stack.push_back(k);
        }
      }
    }
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  }
}

/// The split stage: the connected components of each initial group are split in two until
/// each is a height field within `bound` (or too small to split). A piece with two layers
/// is cut at its plane (which separates them); another, across its longest axis at its
/// centroid. Returns the pieces (sorted indices), by smallest index.
inline std::vector<std::vector<std::size_t>> split_into_height_fields(const Height_field_cloud& cloud,
                                                                      const std::vector<std::vector<std::size_t>>& groups,
                                                                      const Height_field_bound& bound)
{
  std::vector<std::size_t> mark(cloud.size(), 0);
  std::vector<std::vector<std::size_t>> pending, pieces;
  for(const auto& group : groups)
    connected_components(cloud, group, mark, pending);
  while(!pending.empty())
  {
    std::vector<std::size_t> piece = std::move(pending.back());
    pending.pop_back();
    const Height_field_test t = test_height_field(cloud, piece, bound);
    if(piece.size() < smallest_split_piece || t.passes(bound))
    {
      pieces.push_back(std::move(piece));
      continue;
    }
    const Vec3 across = t.layered ? Vec3(t.axes.axes.col(0)) : Vec3(t.axes.axes.col(2));
    std::vector<std::size_t> sides[2];
    for(std::size_t i : piece)
      sides[(cloud.points[i] - t.axes.centroid).dot(across) >= 0 ? 1 : 0].push_back(i);
    if(sides[0].empty() || sides[1].empty())
    {
      // Coincident points: no plane separates them.
      pieces.push_back(std::move(piece));
      continue;
    }
    for(const auto& side : sides)
      connected_components(cloud, side, mark, pending);
  }
  std::sort(pieces.begin(), pieces.end());
  return pieces;
}

/// Bins of the normal directions, for the merge's estimate of a union: the half-sphere of
/// unoriented normals in rings of `normal_bin_degrees` from the pole, each cut into sectors of
/// the same angle. A normal lies within a bin's half-diagonal (about 11 degrees) of its centre.
constexpr double normal_bin_degrees = 15;
constexpr int normal_rings = 6, normal_sectors = 24; // 90 and 360 degrees in bins
typedef std::bitset<normal_rings * normal_sectors> Normal_bins;

inline std::size_t normal_bin(const Vec3& n)
{
  const Vec3 up = n.z() < 0 ? Vec3(-n) : n;
  const double polar = std::acos((std::min)(1., up.z())) * 180 / CGAL_PI;
  const double azimuth = std::atan2(up.y(), up.x()) * 180 / CGAL_PI + 180;
  const int ring = (std::min)(normal_rings - 1, int(polar / normal_bin_degrees));
  const int sector = (std::min)(normal_sectors - 1, int(azimuth / normal_bin_degrees));
  return std::size_t(ring * normal_sectors + sector);
}

inline Vec3 normal_bin_centre(std::size_t bin)
{
  const double polar = (double(bin / normal_sectors) + 0.5) * normal_bin_degrees * CGAL_PI / 180;
  const double azimuth = ((double(bin % normal_sectors) + 0.5) * normal_bin_degrees - 180) * CGAL_PI / 180;
  return Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
}

/// What the merge keeps of a piece to estimate a union without visiting its points: its
/// moments (about a fixed point of the cloud, the plane of the union from them) and its
/// normal bins.
struct Piece_summary
{
  double count = 0;
  Vec3 sum = Vec3::Zero();
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();
  Normal_bins bins;

  void add(const Piece_summary& other)
  {
    count += other.count;
    sum += other.sum;
    second_moment += other.second_moment;
    bins |= other.bins;
  }
};

/// The smallest |cosine| between the union's plane normal and the centres of its normal bins:
/// the estimate of the union's `Height_field_test::smallest_cosine` that orders the merges.
inline double estimate_smallest_cosine(Piece_summary joined)
{
  const Vec3 mean = joined.sum / joined.count;
  const Eigen::Matrix3d covariance = joined.second_moment / joined.count - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const Vec3 normal = solver.eigenvectors().col(0).normalized();
  double smallest = 1;
  for(std::size_t b = 0; b < joined.bins.size(); ++b)
    if(joined.bins[b])
      smallest = (std::min)(smallest, std::abs(normal_bin_centre(b).dot(normal)));
  return smallest;
}

/// The merge stage: repeatedly joins the two linked pieces whose union looks the best height
/// field (the largest estimated smallest cosine) and passes `bound`, as long as one does.
inline std::vector<std::vector<std::size_t>> merge_height_fields(const Height_field_cloud& cloud,
                                                                 std::vector<std::vector<std::size_t>> pieces,
                                                                 const Height_field_bound& bound, Progress& progress)
{
  const std::size_t no_piece = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> piece_of(cloud.size(), no_piece);
  for(std::size_t p = 0; p < pieces.size(); ++p)
    for(std::size_t i : pieces[p])
      piece_of[i] = p;
  std::vector<std::map<std::size_t, std::size_t>> neighbors(pieces.size()); // piece -> link count
  for(std::size_t i = 0; i < cloud.size(); ++i)
    for(std::size_t j = 0; j < height_field_link_neighbors; ++j)
    {
      const std::size_t a = piece_of[i], b = piece_of[cloud.links[i * height_field_link_neighbors + j]];
      if(a != b && a != no_piece && b != no_piece)
      {
        ++neighbors[a][b];
        ++neighbors[b][a];
      }
    }
  std::vector<Piece_summary> summaries(pieces.size());
  const Vec3 reference = cloud.points.empty() ? Vec3::Zero() : cloud.points.front();
  for(std::size_t p = 0; p < pieces.size(); ++p)
    for(std::size_t i : pieces[p])
    {
      const Vec3 d = cloud.points[i] - reference;
      summaries[p].count += 1;
      summaries[p].sum += d;
      summaries[p].second_moment.noalias() += d * d.transpose();
      summaries[p].bins.set(normal_bin(cloud.normals[i]));
    }
  std::vector<std::size_t> version(pieces.size(), 0);
  // (estimated smallest cosine of the union, -a, -b, version of a, version of b): the best
  // union first, ties to the smallest indices. Only the best is tested exactly, when it comes
  // first: testing every union after every merge would visit the large pieces' points again
  // and again.
  typedef std::tuple<double, std::ptrdiff_t, std::ptrdiff_t, std::size_t, std::size_t> Candidate;
  std::priority_queue<Candidate> queue;
  // A union whose estimate falls short of the bound by more than a bin's half-diagonal fails
  // the exact test: it is not queued.
  const double bin_half_diagonal = std::sqrt(2.) / 2 * normal_bin_degrees * CGAL_PI / 180;
  const double hopeless_cosine = std::cos((std::min)(CGAL_PI / 2, std::acos(bound.cos_maximum_angle) + bin_half_diagonal));
  auto consider = [&](std::size_t a, std::size_t b) {
    if(a > b)
      std::swap(a, b);
    Piece_summary joined = summaries[a];
    joined.add(summaries[b]);
    const double estimate = estimate_smallest_cosine(joined);
    if(estimate >= hopeless_cosine)
      queue.emplace(estimate, -std::ptrdiff_t(a), -std::ptrdiff_t(b), version[a], version[b]);
  };
  auto passes = [&](std::size_t a, std::size_t b) {
    std::vector<std::size_t> joined(pieces[a]);
    joined.insert(joined.end(), pieces[b].begin(), pieces[b].end());
    return test_height_field(cloud, joined, bound).passes(bound);
  };
  // b joins a (a < b: the union keeps the smaller index).
  auto join = [&](std::size_t a, std::size_t b) {
    pieces[a].insert(pieces[a].end(), pieces[b].begin(), pieces[b].end());
    pieces[b].clear();
    summaries[a].add(summaries[b]);
    ++version[a];
    ++version[b];
    for(const auto& entry : neighbors[b])
    {
      if(entry.first == a)
        continue;
      neighbors[a][entry.first] += entry.second;
      neighbors[entry.first].erase(b);
      neighbors[entry.first][a] += entry.second;
    }
    neighbors[a].erase(b);
    neighbors[b].clear();
  };
  for(std::size_t a = 0; a < pieces.size(); ++a)
    for(const auto& entry : neighbors[a])
      if(a < entry.first)
        consider(a, entry.first);
  const std::size_t initial = pieces.size();
  std::size_t merges = 0;
  while(!queue.empty())
  {
    const Candidate best = queue.top();
    queue.pop();
    const std::size_t a = std::size_t(-std::get<1>(best)), b = std::size_t(-std::get<2>(best));
    if(version[a] != std::get<3>(best) || version[b] != std::get<4>(best) || pieces[a].empty() ||
       pieces[b].empty() || !passes(a, b))
      continue;
    join(a, b);
    for(const auto& entry : neighbors[a])
      consider(a, entry.first);
    if(!progress.report(double(++merges) / double(initial)))
      return {};
  }
  // The small pieces join the piece they share most links with, whether the union is a height
  // field or not.
  std::size_t small = 0;
  while(small < pieces.size())
  {
    if(pieces[small].empty() || pieces[small].size() >= smallest_piece || neighbors[small].empty())
    {
      ++small;
      continue;
    }
    std::size_t best = neighbors[small].begin()->first;
    for(const auto& entry : neighbors[small])
      if(entry.second > neighbors[small][best])
        best = entry.first;
    join((std::min)(small, best), (std::max)(small, best));
    // The union may still be small: it is looked at again.
    small = (std::min)(small, best);
  }
  std::vector<std::vector<std::size_t>> merged;
  for(auto& piece : pieces)
    if(!piece.empty())
    {
      std::sort(piece.begin(), piece.end());
      merged.push_back(std::move(piece));
    }
  std::sort(merged.begin(), merged.end());
  return merged;
}

/// The initial groups of the split: the points by initial label (`labels` empty: all in one).
inline std::vector<std::vector<std::size_t>> group_by_label(std::size_t n, const std::vector<std::size_t>& labels)
{
  if(labels.empty())
  {
    std::vector<std::vector<std::size_t>> all(1);
    for(std::size_t i = 0; i < n; ++i)
      all[0].push_back(i);
    return all;
  }
  std::map<std::size_t, std::vector<std::size_t>> by_label;
  for(std::size_t i = 0; i < n; ++i)
    by_label[labels[i]].push_back(i);
  std::vector<std::vector<std::size_t>> groups;
  for(auto& entry : by_label)
    groups.push_back(std::move(entry.second));
  return groups;
}

/// The piece of every point, pieces numbered by their smallest point index.
inline std::vector<std::size_t> piece_labels(std::size_t n, const std::vector<std::vector<std::size_t>>& pieces)
{
  std::vector<std::size_t> labels(n, 0);
  for(std::size_t p = 0; p < pieces.size(); ++p)
    for(std::size_t i : pieces[p])
      labels[i] = p;
  return labels;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
