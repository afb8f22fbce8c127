// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Surface patches (paper 3.6): the points split into the regions that the feature curves
// enclose. Regions grow over the points that lie clearly on one side of every crease (outside
// the crease bands and on no crease that the curves miss, or in a band but clearly nearer one
// of its surfaces), along links between such points that stay on one side; the points of a
// band within the blur of the crease join the region on their side; regions that meet without
// a crease between them join.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_PATCHES_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_PATCHES_IMPL_H

#include <CGAL/Sharp_feature_extraction/internal/All_nearest_neighbors.h>
#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Height_field_fit.h>
#include <CGAL/Sharp_feature_extraction/internal/Indexed_input.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Principal_axes.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/candidate_points_impl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

struct Patch_constants
{
  /// Each point links to this many nearest points (the neighbours that define the spacing).
  static constexpr std::size_t linked_neighbors = 6;
  /// Links longer than this many spacings are not surface: they reach outliers.
  static constexpr double longest_link = 3;
  /// A link grows a region only if its ends are among the this many nearest points of each
  /// other: an outlier floating near a surface has surface points among its nearest, but no
  /// surface point has it among its own (they are on the surface, nearer), so that outliers do
  /// not bridge two faces across their crease. Twice the linked neighbours: the strict mutual
  /// neighbours cut narrow strips apart.
  static constexpr std::size_t mutual_neighbors = 2 * linked_neighbors;
  /// A point of a crease band whose side is not clear takes the region of the nearest clear
  /// point on its side, among this many nearest clear points (those on the other side are about
  /// as near: a few times the number of linked neighbours).
  static constexpr std::size_t band_candidates = 32;
  /// A point of a crease band lies clearly on one side when it is closer to the surface of that
  /// side than to the next by this many spacings plus `side_clearance_noises` noise scales:
  /// nearer the crease, the sampling and the noise blur the sides.
  static constexpr double side_clearance_spacings = 1;
  static constexpr double side_clearance_noises = 2;
  /// Regions with fewer points than a stage-2 neighbourhood are not faces (the forward search
  /// could not have found them as surfaces): they merge into the neighbour they share most
  /// links with.
  static constexpr double smallest_patch_per_rmls_neighbors = 1;
  /// Two regions whose surfaces, where they meet, have normals within this angle (degrees)
  /// meet without a crease: the curves mark creases of the sharpness angle (25 degrees by
  /// default) and more; the margin absorbs the error of normals fitted through the noise.
  static constexpr double crease_angle = 15;
  /// A point outside every crease band lies on a crease that no curve marks (a gap in a
  /// curve) when the largest residual of the jet fitted to its stage-1 neighbourhood exceeds the
  /// candidate threshold and this fraction of the stage-1 radius: the residual, at a crease,
  /// of a quadric fitted across it is about 3/16 of the radius times the tangent of half its
  /// angle (the least-squares fit of a + b x^2 to |x| on [-1, 1] has a = 3/16), 0.042 for a
  /// crease of the sharpness angle (25 degrees), half of that for the 12-degree folds of a
  /// tessellated cylinder, which must not stop the regions.
  static constexpr double unmarked_crease_residual_per_radius = 0.042;
  /// The jet of the residual above: a quadric, as stage 1 fits by default.
  static constexpr int unmarked_crease_jet_degree = 2;
  /// Two regions are joined when the links between them that see no crease outnumber those
  /// that see one by this factor: along a crease between two faces, nearly every link sees it;
  /// between two pieces of one face, only the few whose normals the noise tilted.
  static constexpr std::size_t smooth_links_per_crease_link = 4;
};

/// Union-find over point positions; the root of a set is its smallest element, so that the
/// partition and its representatives do not depend on the order of the unions.
class Disjoint_sets
{
public:
  explicit Disjoint_sets(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }

  std::size_t find(std::size_t i)
  {
    while(m_parent[i] != i)
    {
      m_parent[i] = m_parent[m_parent[i]];
      i = m_parent[i];
    }
    return i;
  }

  void unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a != b)
      m_parent[(std::max)(a, b)] = (std::min)(a, b);
  }

private:
  std::vector<std::size_t> m_parent;
};

/// Where a point lies relative to the curves: the nearest crease landmark within the crease
/// band (`no_index` outside it: see `Crease_landmarks`), and the surface there that it lies on.
struct Crease_side
{
  std::size_t landmark = no_index;
  std::size_t side = 0;
  /// Whether the point lies clearly on its side: outside the bands and on no crease that the
  /// curves miss, or in a band and closer to the surface of its side than to the next by a
  /// margin (see `Patch_constants::side_clearance_spacings`).
  bool clear = true;

  /// Whether the point lies on a crease that no curve marks: outside the bands, yet not clear
  /// (see `mark_creases_without_curve()`). It has no side.
  bool on_crease_without_curve() const { return !clear && landmark == no_index; }
};

/// The places that tell the sides of the creases: every curve vertex, with the normals of its
/// two surfaces, and every corner, with the normals of all the surfaces that meet there (its
/// own and those of the ends of its curves, nearly parallel ones counted once). A point near a
/// corner is located by the corner: the normals of one curve there do not include the third
/// surface of the corner.
class Crease_landmarks
{
public:
  explicit Crease_landmarks(const Working_network& network)
  {
    std::vector<std::vector<Vec3>> corner_normals(network.corners.size());
    for(std::size_t k = 0; k < network.corners.size(); ++k)
      for(const Vec3& n : network.corners[k].normals)
        add_distinct(corner_normals[k], n);
    for(std::size_t c = 0; c < network.polylines.size(); ++c)
    {
      const Working_polyline& curve = network.polylines[c];
      for(std::size_t v = 0; v < curve.points.size(); ++v)
      {
        m_vertex_points.push_back(curve.points[v]);
        m_normals.push_back({curve.normals[v][0], curve.normals[v][1]});
        m_curve.push_back(c);
      }
      for(const auto& [corner, v] : {std::make_pair(curve.front_corner, std::size_t(0)),
                                     std::make_pair(curve.back_corner, curve.points.size() - 1)})
        if(corner != no_index)
          for(const Vec3& n : curve.normals[v])
            add_distinct(corner_normals[corner], n);
    }
    m_vertex_index.build<CGAL::Sequential_tag>(m_vertex_points);
    m_first_corner = m_normals.size();
    for(std::size_t k = 0; k < network.corners.size(); ++k)
    {
      m_corner_points.push_back(network.corners[k].point);
      m_normals.push_back(corner_normals[k]);
      m_curve.push_back(no_index);
    }
    m_corner_index.build<CGAL::Sequential_tag>(m_corner_points);
  }

  /// The surface, among those of `landmark`, that passes closest to `x`, and by how much `x`
  /// is closer to it than to the next closest (infinite with one surface).
  struct Nearest_surface
  {
    std::size_t side = 0;
    double clearance = std::numeric_limits<double>::infinity();
  };

  Nearest_surface nearest_surface(std::size_t landmark, const Vec3& x) const
  {
    const Vec3 d = x - point(landmark);
    const std::vector<Vec3>& normals = m_normals[landmark];
    Nearest_surface nearest;
    double closest = std::numeric_limits<double>::infinity(), next = closest;
    for(std::size_t k = 0; k < normals.size(); ++k)
    {
      const double distance = std::abs(normals[k].dot(d));
      if(distance < closest)
      {
        next = closest;
        closest = distance;
        nearest.side = k;
      }
      else
        next = (std::min)(next, distance);
    }
    if(normals.size() >= 2)
      nearest.clearance = next - closest;
    return nearest;
  }

  /// The surface, among those of `landmark`, that passes closest to `x`.
  std::size_t side(std::size_t landmark, const Vec3& x) const { return nearest_surface(landmark, x).side; }

  /// Where `x` lies: by the nearest corner within `band`, else by the nearest curve vertex
  /// within `band`; clearly on its side if its clearance is `margin` or more.
  Crease_side locate(const Vec3& x, double band, double margin, std::vector<std::size_t>& scratch) const
  {
    Crease_side where;
    m_corner_index.nearest(x, 1, scratch);
    if(!scratch.empty() && (m_corner_points[scratch.front()] - x).norm() <= band)
      where.landmark = m_first_corner + scratch.front();
    else
    {
      m_vertex_index.nearest(x, 1, scratch);
      if(!scratch.empty() && (m_vertex_points[scratch.front()] - x).norm() <= band)
        where.landmark = scratch.front();
    }
    if(where.landmark != no_index)
    {
      const Nearest_surface nearest = nearest_surface(where.landmark, x);
      where.side = nearest.side;
      where.clear = nearest.clearance >= margin;
    }
    return where;
  }

  /// The curve of a landmark that is a curve vertex (`no_index` for a corner).
  std::size_t curve(std::size_t landmark) const { return m_curve[landmark]; }

private:
  std::vector<Vec3> m_vertex_points, m_corner_points;
  std::vector<std::vector<Vec3>> m_normals;
  std::vector<std::size_t> m_curve;
  std::size_t m_first_corner = 0;
  Point_index m_vertex_index, m_corner_index;

  const Vec3& point(std::size_t landmark) const
  {
    return landmark < m_first_corner ? m_vertex_points[landmark] : m_corner_points[landmark - m_first_corner];
  }

  static void add_distinct(std::vector<Vec3>& normals, const Vec3& n)
  {
    const double cos_same = std::cos(radians(same_crease_normal_angle));
    for(const Vec3& m : normals)
      if(m.dot(n) > cos_same)
        return;
    normals.push_back(n);
  }
};

/// The patches of the distinct points (positions in `Indexed_input::points`), before they are
/// given to the user: a label per point (`no_index`: unassigned), and the sides of the curves.
struct Patch_labels
{
  std::vector<std::size_t> label;
  std::vector<Crease_side> where;
  std::size_t number_of_patches = 0;
};

/// The points that lie clearly on their side of every crease (see `Crease_side::clear`), indexed
/// for nearest-neighbour queries: the regions grow over them.
struct Clear_points
{
  /// Their positions in `Indexed_input::points`.
  std::vector<std::size_t> positions;
  std::vector<Vec3> points;
  Point_index index;
};

/// Marks as not clear the points outside every crease band that lie on a crease that no curve
/// marks (see `Patch_constants::unmarked_crease_residual_per_radius`): where a curve has a gap,
/// they close the barrier between its two faces that the bands of its pieces leave open, which
/// the regions would otherwise grow through. Returns false if cancelled.
template <typename ConcurrencyTag>
bool mark_creases_without_curve(const Indexed_points& input, const Scales& scales, Progress progress,
                                std::vector<Crease_side>& where)
{
  if(scales.candidate_neighbors == 0 || !(scales.candidate_radius > 0))
    return progress.report(1.);
  const double threshold = (std::max)(scales.residual_threshold,
                                      Patch_constants::unmarked_crease_residual_per_radius * scales.candidate_radius);
  return for_each_neighborhood<ConcurrencyTag>(
    input.points, input.index, scales.candidate_neighbors, neighborhood_cell_per_radius * scales.candidate_radius,
    progress, [&](std::size_t i, const std::vector<std::size_t>& neighbors) {
      if(where[i].landmark == no_index
         && fit_residuals(input.points, neighbors, Patch_constants::unmarked_crease_jet_degree).max_residual > threshold)
        where[i].clear = false;
    });
}

/// The regions of the points that lie clearly on their side: a clear point links to its
/// `linked_neighbors` nearest clear points within `longest_link` spacings (the nearest of all
/// would be, near a crease, mostly points within its blur, and a face pinched between the
/// bands of two curves would fall apart where its clear points are few), and the regions are
/// the sets connected by the links that stay on one side (a band is wider than a link, so a
/// link between two points outside the bands crosses no crease; a link with an end in a band is
/// kept when that end lies clearly on its side and the crease there puts the other end on the
/// same side, and each end is among the `mutual_neighbors` nearest of the other: outliers do not
/// bridge faces). A point whose side is not clear links to its nearest points of any kind, for the
/// merging of small regions only. A strip between two close creases, narrower than two bands,
/// is a region of its own; a face pinched by the bands of two curves stays one. Returns false
/// if cancelled.
template <typename ConcurrencyTag>
bool grow_regions(const Indexed_points& input, const Crease_landmarks& landmarks, const Scales& scales,
                  Progress progress, Patch_labels& labels, Clear_points& clear,
                  std::vector<std::vector<std::size_t>>& links)
{
  typedef Patch_constants Constants;
  const std::vector<Vec3>& points = input.points;
  const std::size_t n = points.size();
  labels.where.assign(n, Crease_side());
  links.assign(n, {});
  const double band = scales.growth_radius;
  const double longest = Constants::longest_link * scales.spacing;
  const double margin = Constants::side_clearance_spacings * scales.spacing
                        + Constants::side_clearance_noises * scales.noise;
  Progress locating = progress.sub(0, 0.3), marking = progress.sub(0.3, 0.6), linking = progress.sub(0.6, 1);
  // nearest[i]: the `mutual_neighbors` nearest points of i (clear ones if i is clear) within a link
  std::vector<std::vector<std::size_t>> nearest(n);
  if(!parallel_blocks<ConcurrencyTag>(n, locating, [&](std::size_t first, std::size_t last) {
       std::vector<std::size_t> scratch;
       for(std::size_t i = first; i < last; ++i)
         labels.where[i] = landmarks.locate(points[i], band, margin, scratch);
     })
     || !mark_creases_without_curve<ConcurrencyTag>(input, scales, marking, labels.where))
    return false;
  clear = Clear_points();
  for(std::size_t i = 0; i < n; ++i)
    if(labels.where[i].clear)
    {
      clear.positions.push_back(i);
      clear.points.push_back(points[i]);
    }
  clear.index.build<ConcurrencyTag>(clear.points);
  if(!parallel_blocks<ConcurrencyTag>(n, linking, [&](std::size_t first, std::size_t last) {
       std::vector<std::size_t> scratch;
       for(std::size_t i = first; i < last; ++i)
       {
         const bool is_clear = labels.where[i].clear;
         (is_clear ? clear.index : input.index).nearest(points[i], Constants::mutual_neighbors + 1, scratch);
         for(std::size_t k : scratch)
         {
           const std::size_t j = is_clear ? clear.positions[k] : k;
           if(j == i || (points[j] - points[i]).norm() > longest)
             continue;
           if(links[i].size() < Constants::linked_neighbors)
             links[i].push_back(j);
           nearest[i].push_back(j);
         }
       }
     }))
    return false;
  // a link stays on one surface when each of its ends in a band lies clearly on its side and
  // sees the other end on that side; it grows a region when its ends are mutual near neighbours
  auto sees_on_its_side = [&](std::size_t i, std::size_t j) {
    const Crease_side& where = labels.where[i];
    if(!where.clear || where.landmark == no_index)
      return where.clear;
    const auto seen = landmarks.nearest_surface(where.landmark, points[j]);
    return seen.side == where.side && seen.clearance >= margin;
  };
  Disjoint_sets sets(n);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j : links[i])
      if(std::find(nearest[j].begin(), nearest[j].end(), i) != nearest[j].end() && sees_on_its_side(i, j)
         && sees_on_its_side(j, i))
        sets.unite(i, j);
  labels.label.assign(n, no_index);
  for(std::size_t i = 0; i < n; ++i)
    if(labels.where[i].clear)
      labels.label[i] = sets.find(i);
  return true;
}

/// Gives every point of a crease band whose side is not clear the region of the nearest clear
/// point that lies on its side of the crease (among the `band_candidates` nearest clear points:
/// a point within the noise of the crease may lie on either side). Points with no such
/// neighbour, and those on a crease that no curve marks (they have no side), keep no region:
/// the merging of small regions gives them the region they share most links with. Returns
/// false if cancelled.
template <typename ConcurrencyTag>
bool assign_band_points(const std::vector<Vec3>& points, const Crease_landmarks& landmarks, const Clear_points& clear,
                        Progress progress, Patch_labels& labels)
{
  std::vector<std::size_t> assigned(points.size(), no_index);
  if(!parallel_blocks<ConcurrencyTag>(points.size(), progress, [&](std::size_t first, std::size_t last) {
       std::vector<std::size_t> nearest;
       for(std::size_t i = first; i < last; ++i)
       {
         const Crease_side& where = labels.where[i];
         if(where.clear || where.on_crease_without_curve())
           continue;
         clear.index.nearest(points[i], Patch_constants::band_candidates, nearest);
         for(std::size_t k : nearest)
           if(landmarks.side(where.landmark, clear.points[k]) == where.side)
           {
             assigned[i] = labels.label[clear.positions[k]];
             break;
           }
       }
     }))
    return false;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!labels.where[i].clear && !labels.where[i].on_crease_without_curve())
      labels.label[i] = assigned[i];
  return true;
}

/// The unit normal of the surface of region `label` around `x`: the least-squares plane of the
/// points of that region among the `neighbors` nearest to `x`; false when they are fewer than
/// `linked_neighbors` (too few to fit through the noise).
inline bool region_normal_around(const Indexed_points& input, const std::vector<std::size_t>& label, std::size_t region,
                                 const Vec3& x, std::size_t neighbors, std::vector<std::size_t>& scratch, Vec3& normal)
{
  input.index.nearest(x, neighbors, scratch);
  scratch.erase(std::remove_if(scratch.begin(), scratch.end(), [&](std::size_t j) { return label[j] != region; }),
                scratch.end());
  Local_frame frame;
  Vec3 variances;
  if(scratch.size() < Patch_constants::linked_neighbors || !principal_frame(input.points, scratch, frame, variances))
    return false;
  normal = frame.n;
  return true;
}

/// Joins the regions that meet without a crease between them: two regions whose surfaces, on
/// either side of the links between them, have normals within `Patch_constants::crease_angle`
/// along most of those links (a link that a crease band sees cross to another side counts as
/// crossing a crease whatever the normals: where noise blurs a crease, the fitted normals of
/// its two faces can come closer than the angle). Such regions are pieces of one face that a crease band cut
/// apart where it left no clear point across it: a face pinched between the bands of two close
/// curves (a tooth tip of a gear), or beside a corner whose surfaces, extended, cut through it.
/// The normals are fitted over a stage-2 neighbourhood (`rmls_neighbors`), which the forward
/// search found large enough to fit a surface through the noise. Returns false if cancelled.
template <typename ConcurrencyTag>
bool join_regions_without_crease(const Indexed_points& input, const Crease_landmarks& landmarks, const Scales& scales,
                                 const std::vector<std::vector<std::size_t>>& links, Progress progress,
                                 Patch_labels& labels)
{
  const std::size_t n = labels.label.size();
  const std::vector<std::size_t>& label = labels.label;
  auto across = [&](std::size_t i, std::size_t j) {
    return label[i] != no_index && label[j] != no_index && label[i] != label[j];
  };
  // both ends of a link between two regions (links are not symmetric: j need not link back to i)
  std::vector<char> on_boundary(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j : links[i])
      if(across(i, j))
        on_boundary[i] = on_boundary[j] = 1;
  std::vector<std::size_t> boundary;
  for(std::size_t i = 0; i < n; ++i)
    if(on_boundary[i])
      boundary.push_back(i);
  // normals[k]: of the region of boundary[k] around it (if it has enough points there)
  std::vector<Vec3> normals(boundary.size());
  std::vector<char> has_normal(boundary.size(), 0);
  if(!parallel_blocks<ConcurrencyTag>(boundary.size(), progress, [&](std::size_t first, std::size_t last) {
       std::vector<std::size_t> scratch;
       for(std::size_t k = first; k < last; ++k)
       {
         const std::size_t i = boundary[k];
         has_normal[k] =
           region_normal_around(input, label, label[i], input.points[i], scales.rmls_neighbors, scratch, normals[k]);
       }
     }))
    return false;
  std::vector<std::size_t> position_in_boundary(n, no_index);
  for(std::size_t k = 0; k < boundary.size(); ++k)
    position_in_boundary[boundary[k]] = k;
  // a link crosses a crease where one of its ends lies in a band and sees the other on another side
  auto crosses_a_crease = [&](std::size_t i, std::size_t j) {
    const Crease_side& where = labels.where[i];
    return where.landmark != no_index && landmarks.side(where.landmark, input.points[j]) != where.side;
  };
  // votes[(a, b)]: links between regions a < b that cross no crease and whose two normals agree,
  // and the others
  std::map<std::pair<std::size_t, std::size_t>, std::array<std::size_t, 2>> votes;
  const double cos_crease = std::cos(radians(Patch_constants::crease_angle));
  for(std::size_t k = 0; k < boundary.size(); ++k)
  {
    const std::size_t i = boundary[k];
    for(std::size_t j : links[i])
    {
      if(!across(i, j) || !has_normal[k] || !has_normal[position_in_boundary[j]])
        continue;
      const bool smooth = !crosses_a_crease(i, j) && !crosses_a_crease(j, i)
                          && std::abs(normals[k].dot(normals[position_in_boundary[j]])) >= cos_crease;
      ++votes[{(std::min)(label[i], label[j]), (std::max)(label[i], label[j])}][smooth ? 0 : 1];
    }
  }
  auto mostly_smooth = [](const std::array<std::size_t, 2>& count) {
    return count[0] > 0 && count[0] >= Patch_constants::smooth_links_per_crease_link * count[1];
  };
  // Join the pairs most links call smooth first; a join is made when the links between the two
  // sets joined so far are mostly smooth, so that a piece lying along a crease (smooth with
  // both of its sides) does not join the two faces of that crease.
  std::vector<std::pair<std::size_t, std::pair<std::size_t, std::size_t>>> candidates;
  for(const auto& [pair, count] : votes)
    if(mostly_smooth(count))
      candidates.emplace_back(count[0], pair);
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  Disjoint_sets sets(n);
  for(const auto& candidate : candidates)
  {
    const std::size_t a = sets.find(candidate.second.first), b = sets.find(candidate.second.second);
    if(a == b)
      continue;
    std::array<std::size_t, 2> between = {0, 0};
    for(const auto& [pair, count] : votes)
    {
      const std::size_t x = sets.find(pair.first), y = sets.find(pair.second);
      if((x == a && y == b) || (x == b && y == a))
      {
        between[0] += count[0];
        between[1] += count[1];
      }
    }
    if(mostly_smooth(between))
      sets.unite(a, b);
  }
  for(std::size_t i = 0; i < n; ++i)
    if(labels.label[i] != no_index)
      labels.label[i] = sets.find(labels.label[i]);
  return true;
}

/// The number of points in the region of every point's root (0 for points that are not roots),
/// those on a crease that no curve marks left out (see `mark_creases_without_curve()`).
inline std::vector<std::size_t> region_sizes(Disjoint_sets& sets, const std::vector<Crease_side>& where)
{
  std::vector<std::size_t> size(where.size(), 0);
  for(std::size_t i = 0; i < where.size(); ++i)
    if(!where[i].on_crease_without_curve())
      ++size[sets.find(i)];
  return size;
}

/// One round of merging: every region with fewer than `smallest` points (see `region_sizes()`)
/// joins the region it shares most links with (ties: the smaller root), as counted at the start
/// of the round.
/// Returns false when no small region has a link out.
inline bool merge_small_regions_once(const std::vector<std::vector<std::size_t>>& links,
                                     const std::vector<Crease_side>& where, std::size_t smallest, Disjoint_sets& sets)
{
  const std::size_t n = links.size();
  const std::vector<std::size_t> size = region_sizes(sets, where);
  std::map<std::size_t, std::map<std::size_t, std::size_t>> shared; // small root -> root -> links
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t r = sets.find(i);
    if(size[r] >= smallest)
      continue;
    for(std::size_t j : links[i])
      if(sets.find(j) != r)
        ++shared[r][sets.find(j)];
  }
  std::vector<std::pair<std::size_t, std::size_t>> merges;
  for(const auto& [r, counts] : shared)
  {
    std::size_t best = no_index, most = 0;
    for(const auto& [other, count] : counts)
      if(count > most)
      {
        best = other;
        most = count;
      }
    merges.emplace_back(r, best);
  }
  for(const auto& [r, best] : merges)
    sets.unite(r, best);
  return !merges.empty();
}

/// Merges the regions with fewer than `smallest` points into the region they share most links
/// with (crossing links included: a sliver of band on the wrong side of its curve joins the
/// face around it), round after round; regions left small without any link are unassigned
/// (outliers). The points on a crease that no curve marks do not count: where noise blurs such
/// a crease, they would make faces of the few clear points between them. Then numbers the
/// regions 0, 1, ... by their smallest point.
inline void merge_small_regions(const std::vector<std::vector<std::size_t>>& links, std::size_t smallest,
                                Patch_labels& labels)
{
  const std::size_t n = labels.label.size();
  Disjoint_sets sets(n);
  for(std::size_t i = 0; i < n; ++i)
    if(labels.label[i] != no_index)
      sets.unite(i, labels.label[i]);
  for(bool merged = true; merged;)
    merged = merge_small_regions_once(links, labels.where, smallest, sets);
  const std::vector<std::size_t> size = region_sizes(sets, labels.where);
  std::vector<std::size_t> number(n, no_index);
  labels.number_of_patches = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t r = sets.find(i);
    if(size[r] < smallest)
    {
      labels.label[i] = no_index;
      continue;
    }
    if(number[r] == no_index)
      number[r] = labels.number_of_patches++;
    labels.label[i] = number[r];
  }
}

/// The pairs of patches on the two sides of each curve: on each side, the patch holding most
/// of the band points of that side.
inline std::vector<Patch_adjacency> find_adjacencies(const Crease_landmarks& landmarks, const Patch_labels& labels,
                                                     std::size_t number_of_curves)
{
  // votes[curve][side]: patch -> band points
  std::vector<std::array<std::map<std::size_t, std::size_t>, 2>> votes(number_of_curves);
  for(std::size_t i = 0; i < labels.label.size(); ++i)
  {
    const Crease_side& where = labels.where[i];
    if(where.landmark != no_index && landmarks.curve(where.landmark) != no_index && labels.label[i] != no_index)
      ++votes[landmarks.curve(where.landmark)][where.side][labels.label[i]];
  }
  auto majority = [](const std::map<std::size_t, std::size_t>& count) {
    std::size_t best = no_index, most = 0;
    for(const auto& [patch, n] : count)
      if(n > most)
      {
        best = patch;
        most = n;
      }
    return best;
  };
  std::vector<Patch_adjacency> adjacencies;
  for(std::size_t c = 0; c < number_of_curves; ++c)
  {
    const std::size_t a = majority(votes[c][0]), b = majority(votes[c][1]);
    if(a != no_index && b != no_index && a != b)
      adjacencies.push_back(Patch_adjacency{(std::min)(a, b), (std::max)(a, b), c});
  }
  return adjacencies;
}

/// The plane and quadric fitted to the points of each patch.
inline std::vector<Surface_patch<Working_traits>> fit_patches(const std::vector<Vec3>& points, const Patch_labels& labels)
{
  std::vector<std::vector<std::size_t>> members(labels.number_of_patches);
  for(std::size_t i = 0; i < labels.label.size(); ++i)
    if(labels.label[i] != no_index)
      members[labels.label[i]].push_back(i);
  std::vector<Surface_patch<Working_traits>> patches(labels.number_of_patches);
  for(std::size_t k = 0; k < patches.size(); ++k)
  {
    Surface_patch<Working_traits>& patch = patches[k];
    patch.number_of_points = members[k].size();
    Local_frame frame;
    Vec3 variances;
    if(!principal_frame(points, members[k], frame, variances))
    {
      patch.centroid = points[members[k].front()];
      patch.normal = Vec3::UnitZ();
      continue;
    }
    patch.centroid = frame.origin;
    patch.normal = frame.n;
    patch.plane_residual = std::sqrt(variances[0]);
    Height_field quadric;
    if(quadric.fit(points, members[k], frame, 2))
    {
      double sum = 0;
      for(std::size_t i : members[k])
        sum += quadric.height(points[i]) * quadric.height(points[i]);
      patch.quadric_residual = std::sqrt(sum / double(members[k].size()));
    }
  }
  return patches;
}

/// The patches of `input` bounded by the curves of `network` (see `segment_into_patches()`),
/// with labels in input order. Where `means_or_points` holds means (see
/// `Sharp_feature_scales::search_fraction`), the sampled points that they are the means of are
/// segmented: a mean of points from both sides of a crease lies on neither, and the means, fewer
/// and smoothed, mark a crease that no curve marks less clearly, so that the regions grew
/// through the gaps of the curves (fandisk at 1% noise, seeds 3 / 4 / 5: mean IoU 0.64 / 0.63 /
/// 0.76 with 10 / 10 / 14 patches for 12 on the means, 0.83 / 0.82 / 0.83 with 14 / 15 / 14 on the
/// sampled points). Returns false if cancelled.
template <typename ConcurrencyTag>
bool segment_patches(const Indexed_input& means_or_points, const Working_network& network, Progress progress,
                     Working_patches& out)
{
  const Indexed_points& input =
    means_or_points.refinement ? *means_or_points.refinement : static_cast<const Indexed_points&>(means_or_points);
  const Scales scales =
    means_or_points.refinement ? scales_of_sampled_points(network.scales) : network.scales;
  out = Working_patches();
  out.labels.assign(input.input_size(), Working_patches::unassigned);
  if(input.points.empty() || !(scales.spacing > 0))
    return progress.report(1.);
  const Crease_landmarks landmarks(network);
  Patch_labels labels;
  Clear_points clear;
  std::vector<std::vector<std::size_t>> links;
  if(!grow_regions<ConcurrencyTag>(input, landmarks, scales, progress.sub(0, 0.6), labels, clear, links)
     || !assign_band_points<ConcurrencyTag>(input.points, landmarks, clear, progress.sub(0.6, 0.75), labels)
     || !join_regions_without_crease<ConcurrencyTag>(input, landmarks, scales, links, progress.sub(0.75, 0.9), labels))
    return false;
  const std::size_t smallest =
    std::size_t(Patch_constants::smallest_patch_per_rmls_neighbors * double(scales.rmls_neighbors));
  merge_small_regions(links, (std::max<std::size_t>)(1, smallest), labels);
  out.patches = fit_patches(input.points, labels);
  out.adjacencies = find_adjacencies(landmarks, labels, network.polylines.size());
  for(const Patch_adjacency& adjacency : out.adjacencies)
    for(std::size_t patch : {adjacency.first_patch, adjacency.second_patch})
      out.patches[patch].bounding_polylines.push_back(adjacency.polyline);
  for(std::size_t j = 0; j < input.input_size(); ++j)
    out.labels[j] = labels.label[input.position_of_input[j]];
  return progress.report(1.);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
