// Feature-protected meshing (examples/Sharp_feature_extraction/meshing): a box with a chamfer,
// sampled, meshed with and without its creases. The exact creases stand in for extracted
// curves, so these tests check the meshing, not the extraction.

#include "meshing/chamfered_box.h"
#include "meshing/feature_curve_repair.h"
#include "meshing/mesh_measurement.h"
#include "meshing/orient_normals_along_sheets.h"
#include "meshing/point_cloud_meshing.h"
#include "utilities/mesh_surface_sampling.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_estimate_normals.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <utility>
#include <vector>

#if __has_include(<CGAL/Sharp_feature_extraction/extract_sharp_features.h>)
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#define SFE_TEST_HAS_EXTRACTION 1
#endif

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Feature_polyline<K> Curve;
typedef sfe_meshing::Chamfered_box<K> Box;

std::vector<Point_3> sample_box(const Box& box, std::size_t n, double noise)
{
  std::vector<Point_3> corners;
  std::vector<sfe_meshing::Triangle_indices> triangles;
  box.triangulate(corners, triangles);
  sfe_utilities::Triangle_soup soup;
  for(const Point_3& p : corners)
    soup.vertices.push_back({{p.x(), p.y(), p.z()}});
  soup.triangles = triangles;
  sfe_utilities::Sampling_options options;
  options.number_of_points = n;
  options.noise = noise;
  options.seed = 7;
  std::vector<Point_3> points;
  for(const auto& p : sfe_utilities::sample_triangle_soup(soup, options))
    points.push_back(Point_3(p[0], p[1], p[2]));
  return points;
}

struct Meshed
{
  sfe_meshing::Point_cloud_meshing_result<K> result;
  sfe_meshing::Surface_check check;
  sfe_meshing::Mesh_quality quality;
};

Meshed mesh_and_measure(const std::vector<Point_3>& points, const std::vector<Curve>& curves, bool features)
{
  const Box box;
  sfe_meshing::Point_cloud_meshing_options options;
  options.protect_curves = options.correct_normals = options.sharpen_creases = features;
  options.limits.time_limit = 300;
  Meshed m;
  m.result = sfe_meshing::mesh_point_cloud<K>(points, curves, options);
  m.check = sfe_meshing::check_triangle_soup(m.result.surface.points, m.result.surface.triangles);
  std::vector<Point_3> truth_points;
  std::vector<sfe_meshing::Triangle_indices> truth_triangles;
  box.triangulate(truth_points, truth_triangles);
  sfe_meshing::True_surface<K> truth(truth_points, truth_triangles, 30);
  sfe_meshing::Measurement_options measure;
  measure.samples = 50000;
  m.quality = sfe_meshing::measure_against_truth(m.result.surface.points, m.result.surface.triangles, truth, measure);
  std::cerr << (features ? "with" : "without") << " features: " << m.check.summary()
            << "; band mean " << m.quality.band_mean_distance << " dB, band normal "
            << m.quality.band_mean_normal_angle << " deg, crease angle " << m.quality.crease_reached_angle
            << " of " << m.quality.crease_true_angle << " deg (error " << m.quality.crease_angle_error
            << "), repair: " << m.result.repair.summary() << std::endl;
  return m;
}

} // namespace

TEST_CASE("curve repair: near-miss ends become one exact junction, an almost closed loop is closed, "
          "short and duplicate curves are dropped, and nothing is left for Mesh_3 to reject",
          "[meshing]")
{
  const Box box;
  const double s = 0.01;
  std::vector<Curve> curves = box.creases(2 * s);
  const std::size_t true_count = curves.size();
  // ends that miss their corner by a fraction of the spacing
  curves[0].points.front() = curves[0].points.front() + K::Vector_3(0.3 * s, -0.2 * s, 0.1 * s);
  curves[3].points.back() = curves[3].points.back() + K::Vector_3(0, 0.4 * s, 0);
  // a stub much shorter than the minimum length
  Curve stub;
  stub.points = {Point_3(0.5, 0.4, 0.3), Point_3(0.5, 0.4, 0.3 + 0.5 * s)};
  curves.push_back(stub);
  // a copy of a crease running alongside it
  Curve twin = curves[5];
  for(Point_3& p : twin.points)
    p = p + K::Vector_3(0.2 * s, 0.2 * s, 0.);
  twin.points.pop_back();
  twin.points.erase(twin.points.begin());
  twin.normals.resize(twin.points.size(), twin.normals.front());
  curves.push_back(twin);
  // a loop that stops short of its start, far from the box
  Curve loop;
  for(int i = 0; i < 60; ++i) {
    const double a = 2 * CGAL_PI * i / 60.;
    loop.points.push_back(Point_3(3 + 0.2 * std::cos(a), 3 + 0.2 * std::sin(a), 0));
  }
  loop.points.push_back(loop.points.front() + K::Vector_3(0.3 * s, 0.1 * s, 0));
  curves.push_back(loop);

  REQUIRE_FALSE(sfe_meshing::find_mesh_3_feature_problems(curves, 1.5 * s).empty());

  sfe_meshing::Curve_repair_options options;
  options.snap_tolerance = 1.5 * s;
  options.minimum_length = 3 * s;
  const sfe_meshing::Curve_repair_report report = sfe_meshing::repair_feature_curves_for_mesh_3(curves, options);
  INFO(report.summary());
  CHECK(sfe_meshing::find_mesh_3_feature_problems(curves, 1.5 * s).empty());
  CHECK(report.dropped_short >= 1);
  CHECK(report.dropped_parallel == 1);
  CHECK(report.closed_loops == 1);
  CHECK(curves.size() == true_count + 1);
  // every box corner is shared exactly by three curve ends
  for(const Point_3& corner : box.corners()) {
    int ends = 0;
    for(const Curve& c : curves)
      ends += (c.points.front() == corner) + (c.points.back() == corner);
    CHECK(ends == 3);
  }
}

TEST_CASE("curve repair splits a curve where another curve ends on it (a T-junction)", "[meshing]")
{
  Curve long_curve, branch;
  for(int i = 0; i <= 20; ++i)
    long_curve.points.push_back(Point_3(0.05 * i, 0, 0));
  for(int i = 0; i <= 10; ++i)
    branch.points.push_back(Point_3(0.52, 0.001 + 0.05 * i, 0));
  std::vector<Curve> curves = {long_curve, branch};
  sfe_meshing::Curve_repair_options options;
  options.snap_tolerance = 0.02;
  options.minimum_length = 0.03;
  sfe_meshing::repair_feature_curves_for_mesh_3(curves, options);
  REQUIRE(curves.size() == 3);
  CHECK(sfe_meshing::find_mesh_3_feature_problems(curves, 0.02).empty());
}

TEST_CASE("curve repair: two curves that leave a shared corner together, their vertices a small "
          "fraction of the spacing apart without being shared, are made Mesh_3-safe",
          "[meshing]")
{
  // two curves from one corner, 0.02 s apart over 5 s (a crease found twice near a corner:
  // Mesh_3's protecting balls there would have to shrink to the gap), then diverging, and a
  // third curve leaving the corner at 90 degrees, which is fine
  const double s = 0.01;
  const Point_3 corner(0, 0, 0);
  Curve a, b, c;
  for(int i = 0; i <= 40; ++i) {
    a.points.push_back(Point_3(0.25 * s * i, 0, 0));
    const double gap = i <= 20 ? 0.02 * s * (i > 0) : 0.02 * s + 0.5 * s * (i - 20);
    b.points.push_back(Point_3(0.25 * s * i, gap, 0));
    c.points.push_back(Point_3(0, 0, 0.25 * s * i));
  }
  b.points.front() = corner;
  std::vector<Curve> curves = {a, b, c};
  const double tol = 1.5 * s;
  CHECK_FALSE(sfe_meshing::find_mesh_3_feature_problems(curves, tol).empty());

  sfe_meshing::Curve_repair_options options;
  options.snap_tolerance = tol;
  options.minimum_length = 3 * s;
  const sfe_meshing::Curve_repair_report report = sfe_meshing::repair_feature_curves_for_mesh_3(curves, options);
  INFO(report.summary());
  CHECK(sfe_meshing::find_mesh_3_feature_problems(curves, tol).empty());
  // no two vertices of different curves closer than a tenth of the spacing unless equal
  double closest = 1;
  for(std::size_t i = 0; i < curves.size(); ++i)
    for(std::size_t j = i + 1; j < curves.size(); ++j)
      for(const Point_3& p : curves[i].points)
        for(const Point_3& q : curves[j].points)
          if(p != q)
            closest = (std::min)(closest, std::sqrt(CGAL::squared_distance(p, q)));
  CHECK(closest > 0.1 * s);
  // the perpendicular curve is kept
  bool perpendicular_kept = false;
  for(const Curve& curve : curves)
    perpendicular_kept = perpendicular_kept || curve.points.back() == c.points.back();
  CHECK(perpendicular_kept);
}

TEST_CASE("the crease model's part of the implicit function is continuous along a crease on a noisy "
          "cloud (the nearest sample's model alone jumps between noisy fits, and where jumps meet, "
          "the surface pinches and Mesh_3's manifold refinement never ends)",
          "[meshing]")
{
  const Box box;
  // noise of the order of the anchor benchmark cloud that pinched (0.5% dB ball on 100k
  // points: about half the spacing)
  const std::vector<Point_3> points = sample_box(box, 20000, 0.002);
  const double s = 0.02; // the spacing of 20k points on this box, about
  const std::vector<Curve> curves = box.creases(s);
  const sfe_meshing::Crease_model<K> model(curves, points, sfe_meshing::Crease_model_options::for_spacing(s));
  // walk along each crease, one spacing inside the solid (where the model alone decides), in
  // steps far below the sample step of the model
  const double step = 1e-3 * s;
  double steepest = 0;
  for(const Curve& c : curves) {
    const Point_3 a = c.points.front(), b = c.points.back();
    const double length = std::sqrt(CGAL::squared_distance(a, b));
    const K::Vector_3 t = (b - a) / length;
    K::Vector_3 inward = -(c.normals.front()[0] + c.normals.front()[1]);
    inward = inward / std::sqrt(inward.squared_length());
    double previous = 0;
    // away from the corners, where the crease's two faces alone meet
    for(double u = 0.2 * length; u < 0.8 * length; u += step) {
      double weight = 0;
      const double value = model.value(a + u * t + s * inward, weight);
      if(u > 0.2 * length)
        steepest = (std::max)(steepest, std::abs(weight * value - previous) / step);
      previous = weight * value;
    }
  }
  // along a straight crease between planar faces a continuous model barely changes (its
  // slope is the fits' noise over the kernel radius, measured below 0.1); a jump of a tenth
  // of the noise between two samples is a slope of about 20 at this step
  CHECK(steepest < 1);
}

TEST_CASE("the normals of a plate 3.5 spacings thick, sampled with 0.5% noise, are oriented outward on "
          "both faces (an orientation that crosses the plate turns one face inward, and Poisson "
          "then spans the part with a membrane)",
          "[meshing]")
{
  // 1 x 0.6 x 0.03; CGAL::mst_orient_normals() orients one face inward on this cloud (about
  // 1970 of the 4000 normals checked, on three seeds)
  const double thickness = 0.03;
  sfe_utilities::Triangle_soup plate;
  for(int i = 0; i < 8; ++i)
    plate.vertices.push_back({{(i & 1) ? 1. : 0., (i & 2) ? 0.6 : 0., (i & 4) ? thickness : 0.}});
  for(const auto& quad : {std::array<std::size_t, 4>{{0, 2, 3, 1}}, {{4, 5, 7, 6}}, {{0, 1, 5, 4}},
                          {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}}) {
    plate.triangles.push_back({{quad[0], quad[1], quad[2]}});
    plate.triangles.push_back({{quad[0], quad[2], quad[3]}});
  }
  sfe_utilities::Sampling_options sampling;
  sampling.number_of_points = 20000;
  sampling.noise = 0.005;
  sampling.seed = 1;
  typedef std::pair<Point_3, K::Vector_3> Point_with_normal;
  std::vector<Point_with_normal> pwn;
  for(const auto& p : sfe_utilities::sample_triangle_soup(plate, sampling))
    pwn.push_back(Point_with_normal(Point_3(p[0], p[1], p[2]), CGAL::NULL_VECTOR));
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(
    pwn, 18, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
               .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
  std::vector<Point_3> points;
  std::vector<K::Vector_3> normals;
  for(const Point_with_normal& p : pwn) {
    points.push_back(p.first);
    normals.push_back(p.second);
  }
  const std::vector<bool> oriented = sfe_meshing::orient_normals_along_sheets<K>(points, normals, 18);
  // the points of the two large faces, away from the rim: up above the middle, down below it
  const double rim = 0.05;
  std::size_t checked = 0, inward = 0, unoriented = 0;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Point_3& p = points[i];
    unoriented += oriented[i] ? 0 : 1;
    if(p.x() < rim || p.x() > 1 - rim || p.y() < rim || p.y() > 0.6 - rim)
      continue;
    ++checked;
    const bool up = p.z() > thickness / 2;
    inward += (normals[i].z() > 0) != up ? 1 : 0;
  }
  INFO(inward << " of " << checked << " normals inward, " << unoriented << " unoriented");
  CHECK(checked > 10000);
  CHECK(inward < 0.01 * checked);
  CHECK(unoriented == 0);
}

TEST_CASE("the crease model leaves the smooth function alone along a curve whose sides it cannot fit "
          "(a spurious curve across a face: a side without points kept the plane through the curve "
          "at the curve's own normal, a sheet through the solid that Mesh_3 could not mesh)",
          "[meshing]")
{
  const Box box;
  const std::vector<Point_3> points = sample_box(box, 20000, 0.002);
  const double s = 0.02;
  // across the bottom face (z = 0), one normal the face's, the other tilted by 45 degrees: no
  // point of the face lies clearly closer to the tilted plane
  Curve spurious;
  const K::Vector_3 down(0, 0, -1), tilted(0, -std::sqrt(0.5), -std::sqrt(0.5));
  for(int i = 0; i <= 20; ++i) {
    spurious.points.push_back(Point_3(0.3 + 0.02 * i, 0.4, 0));
    spurious.normals.push_back({{down, tilted}});
  }
  const sfe_meshing::Crease_model<K> model({spurious}, points,
                                           sfe_meshing::Crease_model_options::for_spacing(s));
  // on the face, around the middle of the curve: the model must not move the surface
  double largest = 0;
  for(double dy = -4 * s; dy <= 4 * s; dy += 0.25 * s)
    for(double dz = -s; dz <= s; dz += 0.25 * s) {
      double weight = 0;
      const double value = model.value(Point_3(0.5, 0.4 + dy, dz), weight);
      // the face itself is z = 0: a model of it gives -z or z (outward is -z); anything else is a
      // surface that is not there
      largest = (std::max)(largest, weight * std::abs(std::abs(value) - std::abs(dz)));
    }
  CHECK(largest < 0.1 * s);
}

TEST_CASE("curve vertices off the implicit surface are moved onto it, and a curve is cut, a "
          "margin away, where a vertex is farther from it than the allowed move (Mesh_3 refines "
          "without end towards a protected vertex off the surface)",
          "[meshing]")
{
  // the unit sphere as a signed distance; two arcs along the equator, vertices s/2 apart
  auto sphere = [](const Point_3& x) { return std::sqrt((x - CGAL::ORIGIN).squared_length()) - 1; };
  const double s = 0.01, max_move = 2 * s, margin = 3 * s, minimum_length = 3 * s;
  const int steps = 60;
  const double step_angle = 0.5 * s;
  Curve near_surface, with_far_vertex;
  for(int i = 0; i <= steps; ++i) {
    const double a = step_angle * i;
    // within a spacing of the sphere, on both sides
    const double r = 1 + ((i % 2) ? 0.8 : -0.8) * s;
    near_surface.points.push_back(Point_3(r * std::cos(a), r * std::sin(a), 0));
    // the middle vertex 2.5 spacings out: its neighbours within the margin go too
    const double r_far = (i == steps / 2) ? 1 + 2.5 * s : 1.;
    with_far_vertex.points.push_back(Point_3(r_far * std::cos(a), r_far * std::sin(a), 1e-3));
  }
  std::vector<Curve> curves = {near_surface, with_far_vertex};
  sfe_meshing::Curve_repair_report report;
  report.output_curves = curves.size();
  sfe_meshing::project_feature_curves_onto_surface<K>(curves, sphere, 0.05 * s, max_move, margin,
                                                      minimum_length, report);
  CHECK(report.cut_off_surface == 1);
  REQUIRE(curves.size() == 3);
  CHECK(report.output_curves == 3);
  CHECK(curves[0].points.size() == near_surface.points.size());
  for(const Curve& c : curves)
    for(const Point_3& p : c.points)
      CHECK(std::abs(sphere(p)) < 1e-3 * s);
  // the two pieces keep the rest of the arc: all but the margin around the far vertex
  const Point_3 far_vertex = with_far_vertex.points[steps / 2];
  for(std::size_t piece = 1; piece < 3; ++piece) {
    for(const Point_3& p : curves[piece].points)
      CHECK(std::sqrt(CGAL::squared_distance(p, far_vertex)) > margin);
    CHECK(curves[piece].points.size() >= std::size_t(steps / 2 - 2 * margin / s));
  }
}

TEST_CASE("a chamfered box sampled with 20k points and meshed with its creases is closed, manifold "
          "and free of self-intersections; against the same pipeline without creases the crease "
          "band error drops at least 3x, crease angles are within 10 degrees, and it needs no more "
          "triangles",
          "[meshing][slow]")
{
  const Box box;
  const std::vector<Point_3> points = sample_box(box, 20000, 0);
  const std::vector<Curve> curves = box.creases(0.02);

  const Meshed with = mesh_and_measure(points, curves, true);
  const Meshed without = mesh_and_measure(points, curves, false);

  REQUIRE(with.result.error.empty());
  REQUIRE(without.result.error.empty());
  CHECK(with.result.protected_curves == 15);
  CHECK(with.result.curve_problems.empty());
  for(const Meshed* m : {&with, &without}) {
    INFO(m->check.summary());
    CHECK(m->check.closed());
    CHECK(m->check.manifold());
    CHECK(m->check.self_intersections_tested);
    CHECK_FALSE(m->check.self_intersecting());
  }
  CHECK(with.quality.band_mean_distance * 3 <= without.quality.band_mean_distance);
  CHECK(with.quality.crease_angle_error <= 10);
  CHECK(with.quality.max_distance < 0.01);
  CHECK(with.result.surface.triangles.size() <= without.result.surface.triangles.size());
}

TEST_CASE("broken curves (ends off their corners, an open loop, a stub, curves without normals) "
          "are repaired or dropped, never make Mesh_3 assert, and the mesh stays valid",
          "[meshing][slow]")
{
  const Box box;
  const std::vector<Point_3> points = sample_box(box, 20000, 0.002);
  std::vector<Curve> curves = box.creases(0.02);
  const double s = 0.02;
  curves[1].points.back() = curves[1].points.back() + K::Vector_3(0.5 * s, 0, 0);
  curves[2].points.front() = curves[2].points.front() + K::Vector_3(0, 0.3 * s, 0.3 * s);
  curves[4].normals.clear();
  Curve stub;
  stub.points = {Point_3(0.5, 0.0, 0.3), Point_3(0.5, 0.0, 0.3 + 0.2 * s)};
  curves.push_back(stub);

  sfe_meshing::Point_cloud_meshing_options options;
  options.limits.time_limit = 300;
  const auto result = sfe_meshing::mesh_point_cloud<K>(points, curves, options);
  REQUIRE(result.error.empty());
  CHECK(result.curve_problems.empty());
  const sfe_meshing::Surface_check check =
    sfe_meshing::check_triangle_soup(result.surface.points, result.surface.triangles);
  INFO(check.summary() << "; " << result.repair.summary());
  CHECK(check.valid());
}

#ifdef SFE_TEST_HAS_EXTRACTION
TEST_CASE("the curves extracted from a sampled chamfered box mesh into a valid surface whose crease "
          "band error is at least 3x below the mesh without features",
          "[meshing][slow]")
{
  const Box box;
  const std::vector<Point_3> points = sample_box(box, 20000, 0);
  CGAL::Sharp_features<K> features;
  REQUIRE(CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, features));
  const Meshed with = mesh_and_measure(points, features.network.polylines, true);
  const Meshed without = mesh_and_measure(points, {}, false);
  REQUIRE(with.result.error.empty());
  INFO(with.check.summary());
  CHECK(with.check.valid());
  CHECK(with.quality.band_mean_distance * 3 <= without.quality.band_mean_distance);
}
#endif
