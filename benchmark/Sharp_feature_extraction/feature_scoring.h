// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scores of feature curves and feature points against the ground truth creases.
//
// Curves are compared by length: both polyline sets are resampled with a step much smaller
// than the tolerance eps, every sample carries the length it stands for, and its exact
// distance to the other set's segments comes from an AABB tree. Points (labelled or
// projected) are compared one by one, and the truth's coverage by them uses a kd-tree.

#ifndef SFE_BENCHMARK_FEATURE_SCORING_H
#define SFE_BENCHMARK_FEATURE_SCORING_H

#include "ground_truth.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace sfe_bench {

typedef K::Segment_3 Segment;

/// Polylines resampled so that consecutive samples are at most `step` apart.
/// Each sample stands for `weights[i]` of curve length and belongs to curve `curve[i]`.
struct Curve_samples
{
  std::vector<Point> points;
  std::vector<double> weights;
  std::vector<std::size_t> curve;
  double length = 0;
};

inline Curve_samples sample_polylines(const std::vector<Polyline>& curves, double step)
{
  Curve_samples samples;
  for(std::size_t c = 0; c < curves.size(); ++c)
    for(std::size_t i = 1; i < curves[c].size(); ++i)
    {
      const Point& a = curves[c][i - 1];
      const Point& b = curves[c][i];
      const double length = std::sqrt(CGAL::squared_distance(a, b));
      if(length == 0)
        continue;
      // Midpoints of equal sub-segments: each stands for exactly its sub-segment.
      const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::ceil(length / step)));
      for(std::size_t j = 0; j < n; ++j)
      {
        const double t = (j + 0.5) / n;
        samples.points.push_back(a + t * (b - a));
        samples.weights.push_back(length / n);
        samples.curve.push_back(c);
      }
      samples.length += length;
    }
  return samples;
}

/// Exact distance from a point to the nearest segment of a set of polylines, and which
/// polyline that segment belongs to.
class Polyline_distance
{
  typedef std::vector<Segment>::const_iterator Iterator;
  typedef CGAL::AABB_segment_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_traits<K, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

public:
  explicit Polyline_distance(const std::vector<Polyline>& curves)
  {
    for(std::size_t c = 0; c < curves.size(); ++c)
      for(std::size_t i = 1; i < curves[c].size(); ++i)
        if(curves[c][i - 1] != curves[c][i])
        {
          segments_.emplace_back(curves[c][i - 1], curves[c][i]);
          curve_of_segment_.push_back(c);
        }
    if(!segments_.empty())
    {
      tree_.insert(segments_.begin(), segments_.end());
      tree_.accelerate_distance_queries();
    }
  }

  bool empty() const { return segments_.empty(); }

  double distance(const Point& p) const
  {
    if(segments_.empty())
      return std::numeric_limits<double>::infinity();
    return std::sqrt(tree_.squared_distance(p));
  }

  /// Distance to the nearest curve and that curve's index.
  std::pair<double, std::size_t> nearest_curve(const Point& p) const
  {
    if(segments_.empty())
      return {std::numeric_limits<double>::infinity(), 0};
    const auto hit = tree_.closest_point_and_primitive(p);
    const std::size_t s = std::size_t(hit.second - segments_.begin());
    return {std::sqrt(CGAL::squared_distance(p, hit.first)), curve_of_segment_[s]};
  }

private:
  std::vector<Segment> segments_;
  std::vector<std::size_t> curve_of_segment_;
  Tree tree_;
};

/// Distance from a point to the nearest point of a point set (kd-tree).
class Point_set_distance
{
  typedef CGAL::Search_traits_3<K> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;

public:
  /// The tree holds each position once: a labelled set may repeat a point many times (every
  /// copy of a duplicated input point is labelled), and CGAL's Kd_tree construction recurses
  /// once per split of coincident points (a stack overflow at ~50k copies).
  explicit Point_set_distance(std::vector<Point> points)
  {
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    tree_.insert(points.begin(), points.end());
    if(!points.empty())
      tree_.build();
  }
  bool empty() const { return tree_.size() == 0; }
  double distance(const Point& p) const
  {
    if(tree_.size() == 0)
      return std::numeric_limits<double>::infinity();
    Search search(tree_, p, 1);
    return std::sqrt(search.begin()->second);
  }

private:
  Tree tree_;
};

/// Step used to resample curves, relative to dB: 20 times finer than the smallest eps.
constexpr double sampling_step_fraction = 0.00025;
/// A piece of curve counts as a fragment of a true curve when it follows it for at least
/// this many eps (shorter overlaps are curves that merely end near it, e.g. at a corner).
constexpr double fragment_min_length_in_eps = 3.;

/// Accuracy of feature curves at one tolerance eps.
struct Curve_scores
{
  double eps = 0;
  double recall = 0;    // fraction of true crease length within eps of the curves
  double precision = 0; // fraction of curve length within eps of a true crease
  double f1 = 0;
  std::size_t true_corners_found = 0; // true corners with a distinct found corner within eps
  /// Mean over the true curves that are found at all of the number of curves covering them.
  double pieces_per_true_curve = 0;
  /// True curves of which at least half the length is within eps of the curves.
  std::size_t true_curves_half_recalled = 0;
};

/// Accuracy of feature curves: length-weighted distances and per-eps scores.
struct Curve_evaluation
{
  std::size_t curves = 0, true_curves = 0, corners = 0, true_corners = 0;
  double length = 0, true_length = 0; // in units of dB
  double mean_distance = 0, rms_distance = 0, max_distance = 0; // of the curves to the truth, / dB
  std::vector<Curve_scores> at_eps;
};

namespace internal {

// Greedy one-to-one matching of found corners to true corners, closest pairs first.
inline std::size_t count_matched_corners(const std::vector<Point>& truth, const std::vector<Point>& found,
                                         double eps)
{
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for(std::size_t i = 0; i < truth.size(); ++i)
    for(std::size_t j = 0; j < found.size(); ++j)
    {
      const double d = std::sqrt(CGAL::squared_distance(truth[i], found[j]));
      if(d <= eps)
        pairs.emplace_back(d, i, j);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used_truth(truth.size(), false), used_found(found.size(), false);
  std::size_t matched = 0;
  for(const auto& pair : pairs)
    if(!used_truth[std::get<1>(pair)] && !used_found[std::get<2>(pair)])
    {
      used_truth[std::get<1>(pair)] = used_found[std::get<2>(pair)] = true;
      ++matched;
    }
  return matched;
}

} // namespace internal

/// Scores `curves` (with their corners) against `truth`, at each tolerance of `eps_fractions`
/// (fractions of dB). All distances and lengths are returned in units of dB.
inline Curve_evaluation evaluate_curves(const Ground_truth& truth, const std::vector<Polyline>& curves,
                                        const std::vector<Point>& corners,
                                        const std::vector<double>& eps_fractions)
{
  const double dB = truth.diagonal;
  const double step = sampling_step_fraction * dB;
  Curve_evaluation result;
  result.curves = curves.size();
  result.true_curves = truth.curves.size();
  result.corners = corners.size();
  result.true_corners = truth.corners.size();

  const Curve_samples true_samples = sample_polylines(truth.curves, step);
  const Curve_samples found_samples = sample_polylines(curves, step);
  result.length = found_samples.length / dB;
  result.true_length = true_samples.length / dB;

  const Polyline_distance to_found(curves), to_truth(truth.curves);
  std::vector<double> truth_to_found(true_samples.points.size());
  for(std::size_t i = 0; i < true_samples.points.size(); ++i)
    truth_to_found[i] = to_found.distance(true_samples.points[i]);
  std::vector<std::pair<double, std::size_t>> found_to_truth(found_samples.points.size());
  for(std::size_t i = 0; i < found_samples.points.size(); ++i)
    found_to_truth[i] = to_truth.nearest_curve(found_samples.points[i]);

  if(found_samples.length > 0 && !to_truth.empty())
  {
    double sum = 0, sum2 = 0;
    for(std::size_t i = 0; i < found_to_truth.size(); ++i)
    {
      const double d = found_to_truth[i].first;
      sum += found_samples.weights[i] * d;
      sum2 += found_samples.weights[i] * d * d;
      result.max_distance = (std::max)(result.max_distance, d);
    }
    result.mean_distance = sum / found_samples.length / dB;
    result.rms_distance = std::sqrt(sum2 / found_samples.length) / dB;
    result.max_distance /= dB;
  }

  for(double fraction : eps_fractions)
  {
    const double eps = fraction * dB;
    Curve_scores scores;
    scores.eps = fraction;

    std::vector<double> recalled_per_curve(truth.curves.size(), 0.), length_per_curve(truth.curves.size(), 0.);
    double recalled = 0;
    for(std::size_t i = 0; i < true_samples.points.size(); ++i)
    {
      length_per_curve[true_samples.curve[i]] += true_samples.weights[i];
      if(truth_to_found[i] <= eps)
      {
        recalled += true_samples.weights[i];
        recalled_per_curve[true_samples.curve[i]] += true_samples.weights[i];
      }
    }
    scores.recall = true_samples.length > 0 ? recalled / true_samples.length : 0;
    for(std::size_t c = 0; c < truth.curves.size(); ++c)
      if(length_per_curve[c] > 0 && recalled_per_curve[c] >= 0.5 * length_per_curve[c])
        ++scores.true_curves_half_recalled;

    // Precision, and which found curve follows which true curve for how long.
    std::map<std::pair<std::size_t, std::size_t>, double> overlap; // (true, found) -> length
    double precise = 0;
    for(std::size_t i = 0; i < found_samples.points.size(); ++i)
      if(found_to_truth[i].first <= eps)
      {
        precise += found_samples.weights[i];
        overlap[{found_to_truth[i].second, found_samples.curve[i]}] += found_samples.weights[i];
      }
    scores.precision = found_samples.length > 0 ? precise / found_samples.length : 0;
    scores.f1 = scores.precision + scores.recall > 0
                    ? 2 * scores.precision * scores.recall / (scores.precision + scores.recall)
                    : 0;

    std::vector<std::size_t> pieces(truth.curves.size(), 0);
    for(const auto& entry : overlap)
      if(entry.second >= fragment_min_length_in_eps * eps ||
         entry.second >= 0.5 * length_per_curve[entry.first.first])
        ++pieces[entry.first.first];
    std::size_t found_true_curves = 0, total_pieces = 0;
    for(std::size_t n : pieces)
      if(n > 0)
      {
        ++found_true_curves;
        total_pieces += n;
      }
    scores.pieces_per_true_curve = found_true_curves > 0 ? double(total_pieces) / found_true_curves : 0;
    scores.true_corners_found = internal::count_matched_corners(truth.corners, corners, eps);
    result.at_eps.push_back(scores);
  }
  return result;
}

/// Accuracy of a set of feature points (labelled input points or projected points) at one eps.
struct Point_scores
{
  double eps = 0;
  double precision = 0; // fraction of the points within eps of a true crease
  double coverage = 0;  // fraction of true crease length with a point within eps
};

struct Point_evaluation
{
  std::size_t points = 0;
  double mean_distance = 0; // of the points to the truth, / dB
  std::vector<Point_scores> at_eps;
};

inline Point_evaluation evaluate_points(const Ground_truth& truth, const std::vector<Point>& points,
                                        const std::vector<double>& eps_fractions)
{
  const double dB = truth.diagonal;
  Point_evaluation result;
  result.points = points.size();
  const Polyline_distance to_truth(truth.curves);
  const Point_set_distance to_points(points);
  const Curve_samples true_samples = sample_polylines(truth.curves, sampling_step_fraction * dB);

  std::vector<double> point_to_truth(points.size());
  double sum = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    point_to_truth[i] = to_truth.distance(points[i]);
    sum += point_to_truth[i];
  }
  if(!points.empty() && !to_truth.empty())
    result.mean_distance = sum / points.size() / dB;
  std::vector<double> truth_to_points(true_samples.points.size());
  for(std::size_t i = 0; i < true_samples.points.size(); ++i)
    truth_to_points[i] = to_points.distance(true_samples.points[i]);

  for(double fraction : eps_fractions)
  {
    const double eps = fraction * dB;
    Point_scores scores;
    scores.eps = fraction;
    std::size_t near = 0;
    for(double d : point_to_truth)
      if(d <= eps)
        ++near;
    scores.precision = points.empty() ? 0 : double(near) / points.size();
    double covered = 0;
    for(std::size_t i = 0; i < true_samples.points.size(); ++i)
      if(truth_to_points[i] <= eps)
        covered += true_samples.weights[i];
    scores.coverage = true_samples.length > 0 ? covered / true_samples.length : 0;
    result.at_eps.push_back(scores);
  }
  return result;
}

} // namespace sfe_bench

#endif // SFE_BENCHMARK_FEATURE_SCORING_H
