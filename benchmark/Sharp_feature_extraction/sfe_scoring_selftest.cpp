// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// sfe_scoring_selftest: the benchmark's scores on fake results whose scores are known.
//
//   sfe_scoring_selftest [--truth PREFIX]
//
// Without --truth it uses a unit cube built in memory (12 creases, 8 corners); with it, the
// ground truth written by sfe_ground_truth. Prints one line per check and "N passed, M failed".

#include "bench_support.h"
#include "feature_scoring.h"
#include "ground_truth.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace sfe_bench;

namespace {

int passed = 0, failed = 0;

void check(bool condition, const std::string& what, double value)
{
  std::cout << (condition ? "PASS " : "FAIL ") << what << " (got " << value << ")\n";
  (condition ? passed : failed)++;
}

bool near(double a, double b, double tolerance = 1e-9) { return std::abs(a - b) <= tolerance; }

Ground_truth unit_cube_truth()
{
  Indexed_mesh cube;
  for(int i = 0; i < 8; ++i)
    cube.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // Two outward triangles per face of the cube.
  const std::size_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads)
  {
    cube.faces.push_back({q[0], q[1], q[2]});
    cube.faces.push_back({q[0], q[2], q[3]});
  }
  return compute_ground_truth(cube, 30);
}

double total_length(const std::vector<Polyline>& curves)
{
  double length = 0;
  for(const Polyline& c : curves)
    for(std::size_t i = 1; i < c.size(); ++i)
      length += std::sqrt(CGAL::squared_distance(c[i - 1], c[i]));
  return length;
}

// Splits a polyline at half its length (inserting the midpoint) into two curves.
std::pair<Polyline, Polyline> split_in_half(const Polyline& curve)
{
  const double half = 0.5 * total_length({curve});
  double walked = 0;
  for(std::size_t i = 1; i < curve.size(); ++i)
  {
    const double length = std::sqrt(CGAL::squared_distance(curve[i - 1], curve[i]));
    if(walked + length >= half)
    {
      const Point middle = curve[i - 1] + ((half - walked) / length) * (curve[i] - curve[i - 1]);
      Polyline first(curve.begin(), curve.begin() + i), second{middle};
      first.push_back(middle);
      second.insert(second.end(), curve.begin() + i, curve.end());
      return {first, second};
    }
    walked += length;
  }
  return {curve, Polyline()};
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Command_line options(argc, argv, {{"truth", ""}});
    const Ground_truth truth =
        options.text("truth").empty() ? unit_cube_truth() : read_ground_truth(options.text("truth"));
    const double dB = truth.diagonal;
    const std::vector<double> eps = report_eps(); // 0.5% and 1% of dB
    std::cout << "truth: " << truth.curves.size() << " curves, " << truth.corners.size() << " corners\n";

    if(options.text("truth").empty())
    {
      check(truth.curves.size() == 12, "cube: 12 true curves", truth.curves.size());
      check(truth.corners.size() == 8, "cube: 8 true corners", truth.corners.size());
      check(near(total_length(truth.curves), 12), "cube: crease length 12", total_length(truth.curves));
    }

    // 1. The truth itself scores perfectly.
    {
      const Curve_evaluation e = evaluate_curves(truth, truth.curves, truth.corners, eps);
      check(near(e.at_eps[0].recall, 1) && near(e.at_eps[0].precision, 1), "truth: recall = precision = 1",
            e.at_eps[0].recall * e.at_eps[0].precision);
      check(e.max_distance < 1e-12, "truth: max distance 0", e.max_distance);
      check(e.at_eps[0].true_corners_found == truth.corners.size(), "truth: every corner found",
            e.at_eps[0].true_corners_found);
      check(near(e.at_eps[0].pieces_per_true_curve, 1), "truth: 1 piece per true curve",
            e.at_eps[0].pieces_per_true_curve);
    }

    // 2. Translated by 0.3% dB: every distance is at most 0.3% dB, so all within eps = 0.5%.
    {
      const Vector shift = 0.003 * dB * Vector(1, 2, 2) / 3.; // |shift| = 0.003 dB
      std::vector<Polyline> moved = truth.curves;
      for(Polyline& c : moved)
        for(Point& p : c)
          p = p + shift;
      std::vector<Point> corners;
      for(const Point& p : truth.corners)
        corners.push_back(p + shift);
      const Curve_evaluation e = evaluate_curves(truth, moved, corners, eps);
      check(near(e.at_eps[0].recall, 1) && near(e.at_eps[0].precision, 1),
            "shifted 0.3%: recall = precision = 1 at eps 0.5%", e.at_eps[0].f1);
      check(e.max_distance <= 0.003 + 1e-9 && e.mean_distance > 0, "shifted 0.3%: 0 < distances <= 0.3% dB",
            e.max_distance);
      check(e.at_eps[0].true_corners_found == truth.corners.size(), "shifted 0.3%: corners found",
            e.at_eps[0].true_corners_found);
      // Shifted by 5% dB, far beyond both tolerances in the direction normal to most creases:
      // the corners are lost for sure.
      std::vector<Point> far_corners;
      for(const Point& p : truth.corners)
        far_corners.push_back(p + shift * (0.05 / 0.003));
      const Curve_evaluation f = evaluate_curves(truth, {}, far_corners, eps);
      check(f.at_eps[1].true_corners_found == 0 && f.at_eps[1].recall == 0,
            "shifted 5%: no corner, no recall", f.at_eps[1].true_corners_found);
    }

    // 3. Every other curve dropped: recall = kept length (+ at most eps per curve end that
    //    touches a kept curve), precision 1.
    {
      std::vector<Polyline> kept;
      for(std::size_t i = 0; i < truth.curves.size(); i += 2)
        kept.push_back(truth.curves[i]);
      const double expected = total_length(kept) / total_length(truth.curves);
      const Curve_evaluation e = evaluate_curves(truth, kept, {}, eps);
      const double slack = 2 * truth.curves.size() * eps[0] * dB / total_length(truth.curves);
      check(e.at_eps[0].recall >= expected - 1e-9 && e.at_eps[0].recall <= expected + slack,
            "half the curves: recall = their share of the length", e.at_eps[0].recall);
      check(near(e.at_eps[0].precision, 1), "half the curves: precision 1", e.at_eps[0].precision);
    }

    // 4. Every curve split in two at half its length: 2 pieces per true curve, same recall.
    {
      std::vector<Polyline> pieces;
      for(const Polyline& c : truth.curves)
      {
        const auto halves = split_in_half(c);
        pieces.push_back(halves.first);
        pieces.push_back(halves.second);
      }
      const Curve_evaluation e = evaluate_curves(truth, pieces, {}, eps);
      check(e.at_eps[0].pieces_per_true_curve >= 1.95 && e.at_eps[0].pieces_per_true_curve <= 2,
            "split curves: 2 pieces per true curve", e.at_eps[0].pieces_per_true_curve);
      check(near(e.at_eps[0].recall, 1), "split curves: recall 1", e.at_eps[0].recall);
    }

    // 5. A spurious curve far away, as long as the truth: precision 1/2.
    {
      std::vector<Polyline> curves = truth.curves;
      const double length = total_length(truth.curves);
      curves.push_back({Point(10 * dB, 0, 0), Point(10 * dB + length, 0, 0)});
      const Curve_evaluation e = evaluate_curves(truth, curves, {}, eps);
      check(near(e.at_eps[1].precision, 0.5, 1e-6), "spurious curve: precision 1/2", e.at_eps[1].precision);
      check(near(e.at_eps[1].f1, 2 * 0.5 / 1.5, 1e-6), "spurious curve: F1 2/3", e.at_eps[1].f1);
    }

    // 6. Points: a dense sampling of the truth plus as many far points.
    {
      const Curve_samples samples = sample_polylines(truth.curves, 0.001 * dB);
      std::vector<Point> points = samples.points;
      for(std::size_t i = 0; i < samples.points.size(); ++i)
        points.push_back(samples.points[i] + Vector(0, 0, 10 * dB));
      const Point_evaluation e = evaluate_points(truth, points, eps);
      check(near(e.at_eps[0].precision, 0.5), "points: precision 1/2", e.at_eps[0].precision);
      check(near(e.at_eps[0].coverage, 1), "points: coverage 1", e.at_eps[0].coverage);
      const Point_evaluation half =
          evaluate_points(truth, std::vector<Point>(points.begin() + samples.points.size(), points.end()), eps);
      check(half.at_eps[1].precision == 0 && half.at_eps[1].coverage == 0, "far points: nothing",
            half.at_eps[1].coverage);
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "sfe_scoring_selftest: " << e.what() << std::endl;
    ++failed;
  }
  std::cout << passed << " passed, " << failed << " failed" << std::endl;
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
