// reconstruct_surface_with_sharp_features(): a box with a chamfer, sampled, meshed with and
// without its creases. The exact creases stand in for extracted curves in most tests, so that
// they check the reconstruction, not the extraction; the scales come from the extraction.

#include "chamfered_box.h"

#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/find_mesh_3_polyline_problems.h>
#include <CGAL/Sharp_feature_extraction/reconstruct_surface_with_sharp_features.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/jet_estimate_normals.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Feature_polyline<K> Curve;
typedef sfe_test::Chamfered_box<K> Box;
namespace sfe = CGAL::Sharp_feature_extraction;
namespace rc = CGAL::Sharp_feature_extraction::internal::reconstruction;

/// The shared fixture: 20k points on the box, and what the extraction found on them (the
/// reconstruction's scales), computed once per noise level.
struct Box_cloud
{
  Box box;
  std::vector<Point_3> points;
  CGAL::Sharp_features<K> extracted;

  /// the length the reconstruction's constants are multiples of
  double s() const { return extracted.network.scales.spacing / rc::Reconstruction_constants::spacing_per_s; }
  /// the extracted scales with the given curves, without corners
  CGAL::Feature_curve_network<K> network_with(const std::vector<Curve>& curves) const
  {
    CGAL::Feature_curve_network<K> network = extracted.network;
    network.polylines = curves;
    network.corners.clear();
    return network;
  }
};

const Box_cloud& box_cloud(double noise)
{
  static std::map<double, std::unique_ptr<Box_cloud>> clouds;
  std::unique_ptr<Box_cloud>& cloud = clouds[noise];
  if(!cloud) {
    cloud.reset(new Box_cloud);
    cloud->points = cloud->box.sample(20000, noise, 7);
    REQUIRE(CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(cloud->points, cloud->extracted));
  }
  return *cloud;
}

struct Meshed
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::Surface_reconstruction_report<K> report;
  bool polygon_mesh = false, closed = false, self_intersecting = true;
  /// area-weighted mean distance to the box of the facets within 2% of the box diagonal of a
  /// true crease (at their centroids), as a fraction of the diagonal
  double band_mean_distance = 0;

  bool valid() const { return polygon_mesh && closed && !self_intersecting; }
};

/// CGAL's own checks: a manifold, oriented soup, closed, without self-intersections.
void check_with_pmp(Meshed& m)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::vector<std::size_t>> polygons;
  for(const auto& t : m.triangles)
    polygons.push_back(std::vector<std::size_t>(t.begin(), t.end()));
  m.polygon_mesh = !polygons.empty() && PMP::is_polygon_soup_a_polygon_mesh(polygons);
  if(!m.polygon_mesh)
    return;
  CGAL::Surface_mesh<Point_3> mesh;
  PMP::polygon_soup_to_polygon_mesh(m.points, polygons, mesh);
  m.closed = CGAL::is_closed(mesh);
  m.self_intersecting = PMP::does_self_intersect(mesh);
}

void measure_crease_band(const Box& box, Meshed& m)
{
  const double diagonal = std::sqrt(box.size_x * box.size_x + box.size_y * box.size_y + box.size_z * box.size_z);
  const double band = 0.02 * diagonal;
  std::vector<K::Segment_3> creases;
  for(const Curve& c : box.creases(1))
    creases.push_back(K::Segment_3(c.points.front(), c.points.back()));
  double weighted = 0, area = 0;
  for(const auto& t : m.triangles) {
    const Point_3 centroid = CGAL::centroid(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    double to_crease = band;
    for(const K::Segment_3& c : creases)
      to_crease = (std::min)(to_crease, std::sqrt(CGAL::squared_distance(centroid, c)));
    if(to_crease >= band)
      continue;
    const double a = std::sqrt(CGAL::squared_area(m.points[t[0]], m.points[t[1]], m.points[t[2]]));
    weighted += a * std::abs(box.signed_distance(centroid));
    area += a;
  }
  m.band_mean_distance = area > 0 ? weighted / area / diagonal : 0;
}

Meshed reconstruct(const Box_cloud& cloud, const CGAL::Feature_curve_network<K>& network, bool features)
{
  Meshed m;
  m.report = CGAL::reconstruct_surface_with_sharp_features<CGAL::Parallel_if_available_tag>(
    cloud.points, network, m.points, m.triangles,
    sfe::parameters::protect_polylines(
      features, sfe::parameters::correct_normals(
      features, sfe::parameters::sharpen_creases(features, CGAL::parameters::maximum_running_time(300.)))));
  check_with_pmp(m);
  measure_crease_band(cloud.box, m);
  std::cerr << (features ? "with" : "without") << " features: " << m.triangles.size() << " triangles, "
            << (m.valid() ? "valid" : "NOT valid") << "; band mean " << m.band_mean_distance
            << " dB, repair: " << m.report.repair.summary() << std::endl;
  return m;
}

/// What `find_mesh_3_polyline_problems()` finds wrong with the curves the reconstruction
/// protected, with the tolerance of its repair.
std::vector<CGAL::Mesh_3_polyline_problem> contract_problems(const CGAL::Surface_reconstruction_report<K>& report)
{
  std::vector<std::vector<Point_3>> polylines;
  for(const auto& curve : report.protected_polylines)
    polylines.push_back(curve.points);
  const double s = report.spacing / rc::Reconstruction_constants::spacing_per_s;
  return CGAL::find_mesh_3_polyline_problems(
    polylines, CGAL::parameters::threshold_distance(rc::Reconstruction_constants::repair_tolerance * s));
}

/// the tolerances of the curve projection as the reconstruction sets them, for a spacing s and
/// an edge size of 3 s
rc::Polyline_projection_settings projection_settings(double s)
{
  rc::Polyline_projection_settings settings;
  settings.gradient_step = 0.05 * s;
  settings.maximal_move = 2 * s;
  settings.clearance = 3 * s;
  settings.clearance_step = 0.25 * s;
  // the clearance plus an edge size of 3 s, as in the reconstruction
  settings.cut_margin = 6 * s;
  settings.minimum_length = 3 * s;
  return settings;
}

} // namespace

TEST_CASE("the crease model's part of the implicit function is continuous along a crease on a noisy "
          "cloud (the nearest sample's model alone jumps between noisy fits, and where jumps meet, "
          "the surface pinches and Mesh_3's manifold refinement never ends)",
          "[meshing]")
{
  // noise of the order of the anchor benchmark cloud that pinched (0.5% dB ball on 100k
  // points: about half the spacing)
  const Box_cloud& cloud = box_cloud(0.002);
  const double s = cloud.s();
  const std::vector<Curve> curves = cloud.box.creases(s);
  const rc::Crease_model<K> model(curves, cloud.points, rc::Crease_model_options::for_spacing(s));
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
  std::vector<Point_3> corners;
  for(int i = 0; i < 8; ++i)
    corners.push_back(Point_3((i & 1) ? 1. : 0., (i & 2) ? 0.6 : 0., (i & 4) ? thickness : 0.));
  std::vector<sfe_test::Triangle_indices> triangles;
  for(const auto& quad : {std::array<std::size_t, 4>{{0, 2, 3, 1}}, {{4, 5, 7, 6}}, {{0, 1, 5, 4}},
                          {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}}) {
    triangles.push_back({{quad[0], quad[1], quad[2]}});
    triangles.push_back({{quad[0], quad[2], quad[3]}});
  }
  typedef std::pair<Point_3, K::Vector_3> Point_with_normal;
  std::vector<Point_with_normal> pwn;
  for(const Point_3& p : sfe_test::sample_triangles(corners, triangles, 20000, 0.005, 1))
    pwn.push_back(Point_with_normal(p, CGAL::NULL_VECTOR));
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(
    pwn, 18, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
               .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
  std::vector<Point_3> points;
  std::vector<K::Vector_3> normals;
  for(const Point_with_normal& p : pwn) {
    points.push_back(p.first);
    normals.push_back(p.second);
  }
  const std::vector<bool> oriented = rc::orient_normals_along_sheets<K>(points, normals, 18);
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
  const Box_cloud& cloud = box_cloud(0.002);
  const double s = cloud.s();
  // across the bottom face (z = 0), one normal the face's, the other tilted by 45 degrees: no
  // point of the face lies clearly closer to the tilted plane
  Curve spurious;
  const K::Vector_3 down(0, 0, -1), tilted(0, -std::sqrt(0.5), -std::sqrt(0.5));
  for(int i = 0; i <= 20; ++i) {
    spurious.points.push_back(Point_3(0.3 + 0.02 * i, 0.4, 0));
    spurious.normals.push_back({{down, tilted}});
  }
  const rc::Crease_model<K> model({spurious}, cloud.points, rc::Crease_model_options::for_spacing(s));
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
  const double s = 0.01;
  const int steps = 60;
  const double step_angle = 0.5 * s;
  Curve near_surface, with_far_vertex;
  for(int i = 0; i <= steps; ++i) {
    const double a = step_angle * i;
    // within a spacing of the sphere, on both sides
    const double r = 1 + ((i % 2) ? 0.8 : -0.8) * s;
    near_surface.points.push_back(Point_3(r * std::cos(a), r * std::sin(a), 0));
    // on the other side of the sphere (the cut reaches every curve within the margin), the
    // middle vertex 2.5 spacings out: its neighbours within the margin go too
    const double r_far = (i == steps / 2) ? 1 + 2.5 * s : 1.;
    with_far_vertex.points.push_back(Point_3(-r_far * std::cos(a), -r_far * std::sin(a), 1e-3));
  }
  std::vector<Curve> curves = {near_surface, with_far_vertex};
  const rc::Polyline_projection_settings settings = projection_settings(s);
  rc::Polyline_projection_counts counts;
  rc::project_polylines_onto_surface<K>(curves, sphere, settings, counts);
  CHECK(counts.cut_off_surface == 1);
  CHECK(counts.cut_near_other_sheet == 0);
  CHECK(counts.moved_onto_surface > std::size_t(steps));
  REQUIRE(curves.size() == 3);
  CHECK(curves[0].points.size() == near_surface.points.size());
  for(const Curve& c : curves)
    for(const Point_3& p : c.points)
      CHECK(std::abs(sphere(p)) < 1e-3 * s);
  // the two pieces keep the rest of the arc: all but the margin around the far vertex
  const Point_3 far_vertex = with_far_vertex.points[steps / 2];
  for(std::size_t piece = 1; piece < 3; ++piece) {
    for(const Point_3& p : curves[piece].points)
      CHECK(std::sqrt(CGAL::squared_distance(p, far_vertex)) > settings.cut_margin);
    CHECK(curves[piece].points.size() >= std::size_t(steps / 2 - 2 * settings.cut_margin / s));
  }
}

TEST_CASE("where a curve is not protectable next to a corner, every curve meeting there is cut a "
          "margin away, not only that one: no protected end stays at a corner whose other creases "
          "are not protected (Mesh_3 refines onto such a corner without end: pinion, 25k points, "
          "noise 0, seed 1)",
          "[meshing]")
{
  // the plane z = 0 as a signed distance; two curves leave the corner at the origin along x and
  // y, vertices s/2 apart; the first vertices of the first one, up to 1.5 s from the corner,
  // are 2.5 s above the plane, beyond the allowed move
  auto plane = [](const Point_3& x) { return x.z(); };
  const double s = 0.01;
  const rc::Polyline_projection_settings settings = projection_settings(s);
  const double step = 0.5 * s;
  const int steps = 40;
  Curve along_x, along_y;
  for(int i = 0; i <= steps; ++i) {
    const double lifted = (i > 0 && i * step <= 1.5 * s) ? 2.5 * s : 0.;
    along_x.points.push_back(Point_3(i * step, 0, lifted));
    along_y.points.push_back(Point_3(0, i * step, 0));
  }
  std::vector<Curve> curves = {along_x, along_y};
  rc::Polyline_projection_counts counts;
  rc::project_polylines_onto_surface<K>(curves, plane, settings, counts);
  CHECK(counts.cut_off_surface == 2);
  REQUIRE(curves.size() == 2);
  for(const Curve& c : curves)
    for(const Point_3& p : c.points)
      for(const Point_3& q : along_x.points)
        if(q.z() > 0)
          CHECK(std::sqrt(CGAL::squared_distance(p, q)) >= settings.cut_margin);
  // each keeps the rest of its length, up to its far end
  const double kept_length = steps * step - 1.5 * s - settings.cut_margin - step;
  CHECK(curves[0].points.back() == along_x.points.back());
  CHECK(curves[1].points.back() == along_y.points.back());
  for(const Curve& c : curves)
    CHECK(CGAL::Sharp_feature_extraction::internal::mesh_polylines::curve_length(c) >= kept_length);
}

TEST_CASE("a curve on a wall or across a gap narrower than the clearance (Mesh_3's protecting balls "
          "would reach the other side, and it would refine there without end) is dropped, and one on a "
          "wall or across a gap wider than twice the clearance is kept whole",
          "[meshing]")
{
  const double s = 0.01;
  const rc::Polyline_projection_settings settings = projection_settings(s);
  for(const double width : {2 * s, 8 * s})
    for(const bool wall : {true, false}) {
      // a slab |z| < width / 2 (a wall), or the space between two half-spaces (a gap); the curve
      // runs on the face z = width / 2
      auto function = [width, wall](const Point_3& x) {
        return (wall ? 1 : -1) * (std::abs(x.z()) - width / 2);
      };
      Curve curve;
      for(double x = 0; x <= 0.3; x += 0.5 * s)
        curve.points.push_back(Point_3(x, 0, width / 2));
      std::vector<Curve> curves = {curve};
      rc::Polyline_projection_counts counts;
      rc::project_polylines_onto_surface<K>(curves, function, settings, counts);
      INFO((wall ? "wall " : "gap ") << width / s << " s wide");
      const bool narrow = width < settings.clearance;
      CHECK(counts.cut_near_other_sheet == (narrow ? 1u : 0u));
      CHECK(curves.size() == (narrow ? 0u : 1u));
      if(!narrow)
        CHECK(curves.front().points.size() == curve.points.size());
    }
}

TEST_CASE("two curves that pass 2 s apart, on either side of the surface, cross once moved onto it "
          "(Mesh_3 fails on such curves): they are split where they cross, meet at one shared point, "
          "and pass the Mesh_3 check, and neither is dropped",
          "[meshing]")
{
  namespace mp = CGAL::Sharp_feature_extraction::internal::mesh_polylines;
  typedef rc::Reconstruction_constants C;
  const double s = 0.01;
  auto plane = [](const Point_3& x) { return x.z(); };
  const int half_steps = 40;
  const double step = 0.5 * s;
  Curve above, below;
  for(int i = -half_steps; i <= half_steps; ++i) {
    above.points.push_back(Point_3(step * i, 0, s));
    // a quarter step off, so that no vertex of one lands on a vertex of the other
    below.points.push_back(Point_3(0, step * (i + 0.25), -s));
  }
  std::vector<Curve> curves = {above, below};
  mp::Repair_settings repair;
  repair.tolerance = C::repair_tolerance * s;
  repair.minimum_length = C::minimum_polyline_length * s;
  const mp::Contract_tolerances tolerances{repair.tolerance, repair.maximum_angle};
  REQUIRE(mp::find_contract_violations(curves, tolerances).empty());
  CGAL::Surface_reconstruction_report<K> report;
  report.edge_size = 3 * s;
  rc::prepare_protected_polylines<K>(curves, plane, s, repair, report);
  CHECK(mp::find_contract_violations(curves, tolerances).empty());
  REQUIRE(curves.size() == 4);
  std::map<std::array<double, 3>, int> ends;
  double length = 0;
  for(const Curve& c : curves) {
    for(const Point_3& p : {c.points.front(), c.points.back()})
      ++ends[{p.x(), p.y(), p.z()}];
    for(const Point_3& p : c.points)
      CHECK(std::abs(p.z()) < 1e-3 * s);
    length += mp::curve_length(c);
  }
  // the four pieces meet at the crossing; their other ends are the curves' own
  REQUIRE(ends.size() == 5);
  const auto crossing = std::max_element(ends.begin(), ends.end(), [](const auto& a, const auto& b) {
    return a.second < b.second;
  });
  CHECK(crossing->second == 4);
  CHECK(std::hypot(crossing->first[0], crossing->first[1]) < step);
  // nothing but the moves at the crossing changed the length of the two curves
  CHECK(std::abs(length - 2 * mp::curve_length(above)) < step);
}

TEST_CASE("Mesh_3 stopped while it refines the facets, before it labels the cells inside (the time "
          "limit stopped it there on rotor, 25k points, 0.5% noise, seed 4), gives its partial surface "
          "facing outward: no facet is oriented by the infinite vertex, whose point is not a point",
          "[meshing]")
{
  // a unit sphere as a signed distance, meshed far finer than the vertex limit allows; away from
  // the origin, where the infinite vertex's unset point may be, so that a facet oriented by it
  // faces the wrong way if its point is not a NaN
  const Point_3 center(2, 1, 0.5);
  auto sphere = [&center](const Point_3& x) { return std::sqrt((x - center).squared_length()) - 1; };
  rc::Mesh_sizes sizes;
  sizes.facet_size = sizes.edge_size = 0.05;
  sizes.facet_distance = 0.005;
  rc::Surface_meshing_limits limits;
  // a few times Mesh_3's initial points: the facets of the convex hull are still on the surface
  limits.maximal_number_of_vertices = 100;
  const rc::Surface_meshing_result<Point_3> result =
    rc::mesh_implicit_surface<K>(sphere, K::Sphere_3(center, 4), std::vector<std::vector<Point_3>>(), sizes, limits);
  CHECK(result.stopped);
  REQUIRE_FALSE(result.surface.triangles.empty());
  for(const auto& t : result.surface.triangles) {
    const std::vector<Point_3>& p = result.surface.points;
    const K::Vector_3 normal = CGAL::cross_product(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
    CHECK(normal * (CGAL::centroid(p[t[0]], p[t[1]], p[t[2]]) - center) > 0);
  }
}

TEST_CASE("a chamfered box sampled with 20k points and meshed with its creases is closed, manifold "
          "and free of self-intersections, and against the same pipeline without creases the crease "
          "band error drops at least 3x, and it needs no more triangles",
          "[meshing][slow]")
{
  const Box_cloud& cloud = box_cloud(0);
  const CGAL::Feature_curve_network<K> network = cloud.network_with(cloud.box.creases(0.02));
  const Meshed with = reconstruct(cloud, network, true);
  const Meshed without = reconstruct(cloud, network, false);
  CHECK(with.report.protected_polylines.size() == 15);
  CHECK(without.report.protected_polylines.empty());
  CHECK(contract_problems(with.report).empty());
  CHECK_FALSE(with.report.stopped);
  CHECK(with.valid());
  CHECK(without.valid());
  CHECK(with.band_mean_distance * 3 <= without.band_mean_distance);
  CHECK(with.triangles.size() <= without.triangles.size());
}

TEST_CASE("broken curves (ends off their corners, an open loop, a stub, curves without normals) "
          "are repaired or dropped, never make Mesh_3 assert, and the mesh stays valid",
          "[meshing][slow]")
{
  const Box_cloud& cloud = box_cloud(0.002);
  std::vector<Curve> curves = cloud.box.creases(0.02);
  const double s = 0.02;
  curves[1].points.back() = curves[1].points.back() + K::Vector_3(0.5 * s, 0, 0);
  curves[2].points.front() = curves[2].points.front() + K::Vector_3(0, 0.3 * s, 0.3 * s);
  curves[4].normals.clear();
  Curve stub;
  stub.points = {Point_3(0.5, 0.0, 0.3), Point_3(0.5, 0.0, 0.3 + 0.2 * s)};
  curves.push_back(stub);
  const Meshed m = reconstruct(cloud, cloud.network_with(curves), true);
  INFO(m.report.repair.summary());
  const std::vector<CGAL::Mesh_3_polyline_problem> problems = contract_problems(m.report);
  for(const auto& problem : problems)
    std::cerr << "problem left: " << problem.description << std::endl;
  CHECK(m.report.repair.snapped_ends >= 2);
  CHECK(m.report.repair.dropped_short >= 1);
  CHECK(problems.empty());
  CHECK(m.valid());
}

TEST_CASE("the curves extracted from a sampled chamfered box mesh into a valid surface whose crease "
          "band error is at least 3x below the mesh without features",
          "[meshing][slow]")
{
  const Box_cloud& cloud = box_cloud(0);
  const Meshed with = reconstruct(cloud, cloud.extracted.network, true);
  const Meshed without = reconstruct(cloud, cloud.extracted.network, false);
  CHECK(with.valid());
  CHECK(with.band_mean_distance * 3 <= without.band_mean_distance);
}

TEST_CASE("a feature network without scales is refused with a documented exception", "[meshing]")
{
  const Box_cloud& cloud = box_cloud(0);
  CGAL::Feature_curve_network<K> network = cloud.extracted.network;
  network.scales.spacing = 0;
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  CHECK_THROWS_AS(CGAL::reconstruct_surface_with_sharp_features<CGAL::Sequential_tag>(cloud.points, network, points,
                                                                                      triangles),
                  CGAL::Surface_reconstruction_error);
}

TEST_CASE("a callback that returns false stops the reconstruction: the report says stopped and why, "
          "and no surface is returned when it stops before Mesh_3",
          "[meshing]")
{
  const Box_cloud& cloud = box_cloud(0);
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t calls = 0;
  const std::function<bool(double)> stop_at_once = [&calls](double) { return ++calls < 2; };
  const CGAL::Surface_reconstruction_report<K> report =
    CGAL::reconstruct_surface_with_sharp_features<CGAL::Sequential_tag>(
      cloud.points, cloud.extracted.network, points, triangles, CGAL::parameters::callback(stop_at_once));
  CHECK(report.stopped);
  CHECK(report.stop_reason == "cancelled by the callback");
  CHECK(triangles.empty());
  CHECK(report.seconds_meshing == 0);
}
