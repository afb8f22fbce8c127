// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Analytic test shapes whose sharp creases are known exactly, their uniform sampling (with a
// fixed seed and optional uniform noise), and the measures that compare an extracted curve
// network with the true creases: vertex distance, coverage, corner error, normal error.
// Everything here is plain double geometry, independent of the library under test, except the
// measure functions, which read the public result types.

#ifndef SFE_TEST_ANALYTIC_SHAPES_H
#define SFE_TEST_ANALYTIC_SHAPES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace sfe_test {

constexpr double pi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Vectors

struct Vec
{
  double x = 0, y = 0, z = 0;
  Vec() = default;
  Vec(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  Vec operator+(const Vec& o) const { return Vec(x + o.x, y + o.y, z + o.z); }
  Vec operator-(const Vec& o) const { return Vec(x - o.x, y - o.y, z - o.z); }
  Vec operator*(double s) const { return Vec(x * s, y * s, z * s); }
  Vec operator-() const { return Vec(-x, -y, -z); }
};

inline double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(const Vec& a, const Vec& b)
{
  return Vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
inline double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
inline Vec normalized(const Vec& a) { return a * (1. / norm(a)); }
inline double distance(const Vec& a, const Vec& b) { return norm(a - b); }
inline bool is_finite(const Vec& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

/// Angle in degrees between the lines spanned by two (not necessarily unit) vectors.
inline double line_angle_degrees(const Vec& a, const Vec& b)
{
  const double c = std::abs(dot(a, b)) / (norm(a) * norm(b));
  return std::acos((std::min)(1., c)) * 180. / pi;
}

template <typename P>
Vec to_vec(const P& p)
{
  return Vec(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// ---------------------------------------------------------------------------------------------
// Random numbers: our own conversion, so that the samples do not depend on the standard
// library's distributions (which differ between implementations).

class Random
{
public:
  explicit Random(std::uint64_t seed) : m_engine(seed) {}
  /// Uniform in [0, 1): the top 53 bits of one 64-bit draw, scaled by 2^-53.
  double uniform() { return double(m_engine() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// Uniform in the ball of radius `r` (rejection from the cube).
  Vec in_ball(double r)
  {
    for(;;)
    {
      const Vec v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if(dot(v, v) <= 1)
        return v * r;
    }
  }

private:
  std::mt19937_64 m_engine;
};

// ---------------------------------------------------------------------------------------------
// True creases

/// A true sharp crease: a segment or a circle, with the unit normals of the two smooth surfaces
/// that meet along it (constant for a segment; for a circle, one constant and one that points
/// away from `normal_center`: radial for a cylinder, from the sphere's centre for a sphere).
struct Crease
{
  bool circle = false;
  // Segment.
  Vec a, b;
  Vec normal_a, normal_b;
  // Circle: centre, unit axis, radius. normal_a is the constant (cap) normal; the other is
  // the direction from `normal_center` to the crease point.
  Vec center, axis, normal_center;
  double radius = 0;

  static Crease segment(const Vec& a, const Vec& b, const Vec& n1, const Vec& n2)
  {
    Crease c;
    c.a = a; c.b = b; c.normal_a = normalized(n1); c.normal_b = normalized(n2);
    return c;
  }
  static Crease ring(const Vec& center, const Vec& axis, double radius, const Vec& cap_normal)
  {
    return ring(center, axis, radius, cap_normal, center);
  }
  static Crease ring(const Vec& center, const Vec& axis, double radius, const Vec& cap_normal,
                     const Vec& normal_center)
  {
    Crease c;
    c.circle = true; c.center = center; c.axis = normalized(axis); c.radius = radius;
    c.normal_a = normalized(cap_normal);
    c.normal_center = normal_center;
    return c;
  }

  double length() const { return circle ? 2 * pi * radius : distance(a, b); }

  /// Point at arc length `s` in [0, length()].
  Vec point_at(double s) const
  {
    if(!circle)
      return a + (b - a) * (s / length());
    const Vec u = any_orthogonal(axis), v = cross(axis, u);
    const double t = s / radius;
    return center + u * (radius * std::cos(t)) + v * (radius * std::sin(t));
  }

  Vec closest_point(const Vec& p) const
  {
    if(!circle)
    {
      const Vec d = b - a;
      const double t = (std::max)(0., (std::min)(1., dot(p - a, d) / dot(d, d)));
      return a + d * t;
    }
    const Vec q = p - center;
    Vec radial = q - axis * dot(q, axis);
    if(norm(radial) == 0)
      radial = any_orthogonal(axis);
    return center + normalized(radial) * radius;
  }

  double distance_to(const Vec& p) const { return distance(p, closest_point(p)); }

  /// The two true surface normals at the crease point closest to `p`.
  std::array<Vec, 2> normals_near(const Vec& p) const
  {
    if(!circle)
      return {{normal_a, normal_b}};
    return {{normal_a, normalized(closest_point(p) - normal_center)}};
  }

  static Vec any_orthogonal(const Vec& n)
  {
    const Vec t = std::abs(n.x) < 0.9 ? Vec(1, 0, 0) : Vec(0, 1, 0);
    return normalized(cross(n, t));
  }
};

// ---------------------------------------------------------------------------------------------
// Shapes

/// A surface to sample: planar triangles and, for curved shapes, analytic pieces (each with
/// its area and a sampler), plus what a correct extraction must find.
struct Shape
{
  std::string name;
  struct Triangle { Vec a, b, c; };
  std::vector<Triangle> triangles;
  struct Curved_piece
  {
    double area;
    int kind;          // 0: cylinder side, 1: disk, 2: sphere
    Vec center, axis;  // axis: cylinder axis / disk normal / sphere pole
    double radius, height; // sphere: the part up to `height` along the axis from the centre
  };
  std::vector<Curved_piece> curved;

  std::vector<Crease> creases;
  std::vector<Vec> corners;
  Vec bbox_min, bbox_max;

  double bbox_diagonal() const { return distance(bbox_min, bbox_max); }
  double total_crease_length() const
  {
    double l = 0;
    for(const Crease& c : creases)
      l += c.length();
    return l;
  }
};

/// A prism: the simple polygon `profile` (counter-clockwise in the (u, v) plane) extruded by
/// `depth`. 3D point of profile point (u, v) at extrusion w: (u, w, v). Every profile vertex
/// gives one crease along the extrusion and two corners; every profile edge gives two creases
/// on the caps. The caps are fan-triangulated from profile vertex `fan_vertex` (the profile must
/// be star-shaped from it).
inline Shape make_prism(const std::string& name, const std::vector<std::array<double, 2>>& profile,
                        double depth, std::size_t fan_vertex = 0)
{
  Shape s;
  s.name = name;
  const std::size_t n = profile.size();
  auto at = [&](std::size_t k, double w) { return Vec(profile[k % n][0], w, profile[k % n][1]); };
  // Outward normal of the side face over profile edge k -> k+1 (profile counter-clockwise in (u, v)).
  std::vector<Vec> side_normal(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const double du = profile[(k + 1) % n][0] - profile[k][0], dv = profile[(k + 1) % n][1] - profile[k][1];
    side_normal[k] = normalized(Vec(dv, 0, -du));
  }
  const Vec front_normal(0, -1, 0), back_normal(0, 1, 0);
  for(std::size_t k = 0; k < n; ++k)
  {
    s.triangles.push_back({at(k, 0), at(k + 1, 0), at(k + 1, depth)});
    s.triangles.push_back({at(k, 0), at(k + 1, depth), at(k, depth)});
    s.creases.push_back(Crease::segment(at(k, 0), at(k, depth), side_normal[(k + n - 1) % n], side_normal[k]));
    s.creases.push_back(Crease::segment(at(k, 0), at(k + 1, 0), side_normal[k], front_normal));
    s.creases.push_back(Crease::segment(at(k, depth), at(k + 1, depth), side_normal[k], back_normal));
    s.corners.push_back(at(k, 0));
    s.corners.push_back(at(k, depth));
  }
  for(std::size_t k = 1; k + 1 < n; ++k)
  {
    const std::size_t i = fan_vertex, j = (fan_vertex + k) % n, l = (fan_vertex + k + 1) % n;
    s.triangles.push_back({at(i, 0), at(j, 0), at(l, 0)});
    s.triangles.push_back({at(i, depth), at(j, depth), at(l, depth)});
  }
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(const auto& p : profile)
    for(int c = 0; c < 2; ++c)
    {
      lo[c] = (std::min)(lo[c], p[c]);
      hi[c] = (std::max)(hi[c], p[c]);
    }
  s.bbox_min = Vec(lo[0], 0, lo[1]);
  s.bbox_max = Vec(hi[0], depth, hi[1]);
  return s;
}

/// The unit cube [0,1]^3: 12 creases (dihedral 90 degrees), 8 corners of valence 3.
inline Shape unit_cube() { return make_prism("unit cube", {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, 1); }

/// A 2 x 1 x 1 box with one long edge chamfered at 45 degrees (legs `chamfer`): 15 creases
/// (two of them with normals 45 degrees apart), 10 corners of valence 3.
inline Shape chamfered_box(double chamfer = 0.25)
{
  return make_prism("chamfered box",
                    {{{0, 0}, {2, 0}, {2, 1 - chamfer}, {2 - chamfer, 1}, {0, 1}}}, 1);
}

/// A 2 x 1 x 1 box with a step (an L-shaped prism): 18 creases, one of them concave, 12 corners.
inline Shape stepped_box()
{
  // Fan from the reflex vertex (1, 0.5), from which the L is star-shaped.
  return make_prism("stepped box", {{{0, 0}, {2, 0}, {2, 0.5}, {1, 0.5}, {1, 1}, {0, 1}}}, 1, 3);
}

/// A cylinder of radius 0.5 and height 1 with flat caps: 2 circular creases, no corner.
inline Shape capped_cylinder()
{
  Shape s;
  s.name = "capped cylinder";
  const double r = 0.5, h = 1;
  const Vec axis(0, 0, 1);
  s.curved.push_back({2 * pi * r * h, 0, Vec(0, 0, 0), axis, r, h});
  s.curved.push_back({pi * r * r, 1, Vec(0, 0, 0), Vec(0, 0, -1), r, 0});
  s.curved.push_back({pi * r * r, 1, Vec(0, 0, h), Vec(0, 0, 1), r, 0});
  s.creases.push_back(Crease::ring(Vec(0, 0, 0), axis, r, Vec(0, 0, -1)));
  s.creases.push_back(Crease::ring(Vec(0, 0, h), axis, r, Vec(0, 0, 1)));
  s.bbox_min = Vec(-r, -r, 0);
  s.bbox_max = Vec(r, r, h);
  return s;
}

/// The side of a cylinder of radius `radius` and height 1, without caps: smooth everywhere, no
/// crease (its borders are not creases).
inline Shape open_cylinder(double radius)
{
  Shape s;
  s.name = "open cylinder";
  const double h = 1;
  s.curved.push_back({2 * pi * radius * h, 0, Vec(0, 0, 0), Vec(0, 0, 1), radius, h});
  s.bbox_min = Vec(-radius, -radius, 0);
  s.bbox_max = Vec(radius, radius, h);
  return s;
}

/// A sphere of radius 0.5: smooth everywhere, no crease.
inline Shape sphere()
{
  Shape s;
  s.name = "sphere";
  const double r = 0.5;
  s.curved.push_back({4 * pi * r * r, 2, Vec(0, 0, 0), Vec(0, 0, 1), r, r});
  s.bbox_min = Vec(-r, -r, -r);
  s.bbox_max = Vec(r, r, r);
  return s;
}

/// A sphere of radius 0.5 with its top cut off by a plane, so that the normals of the sphere and
/// of the flat cap are `crease_degrees` apart along the circle where they meet: a shallow crease
/// between a curved and a flat surface. One closed crease, no corner.
inline Shape truncated_sphere(double crease_degrees)
{
  Shape s;
  s.name = "sphere cut at " + std::to_string(int(crease_degrees)) + " degrees";
  const double r = 0.5, a = crease_degrees * pi / 180;
  const double h = r * std::cos(a), rim = r * std::sin(a);
  const Vec up(0, 0, 1);
  s.curved.push_back({2 * pi * r * (r + h), 2, Vec(0, 0, 0), up, r, h});
  s.curved.push_back({pi * rim * rim, 1, Vec(0, 0, h), up, rim, 0});
  s.creases.push_back(Crease::ring(Vec(0, 0, h), up, rim, up, Vec(0, 0, 0)));
  s.bbox_min = Vec(-r, -r, -r);
  s.bbox_max = Vec(r, r, h);
  return s;
}

/// Two unit squares sharing the edge x = z = 0, y in [0, 1]: one in the plane z = 0 (x <= 0),
/// the other turned by `bend_degrees` about that edge, so that their normals are `bend_degrees`
/// apart (90: an L; 30: a shallow crease; 150: a thin 30-degree wedge). One open crease, no corner.
inline Shape two_planes(double bend_degrees)
{
  Shape s;
  s.name = "two planes bent by " + std::to_string(int(bend_degrees)) + " degrees";
  const double b = bend_degrees * pi / 180;
  const Vec d(std::cos(b), 0, std::sin(b));
  const Vec o(0, 0, 0), e(0, 1, 0), w(-1, 0, 0);
  s.triangles.push_back({o, e + w, e});
  s.triangles.push_back({o, w, e + w});
  s.triangles.push_back({o, e, e + d});
  s.triangles.push_back({o, e + d, d});
  s.creases.push_back(Crease::segment(o, e, Vec(0, 0, 1), Vec(-std::sin(b), 0, std::cos(b))));
  s.bbox_min = Vec((std::min)(-1., d.x), 0, (std::min)(0., d.z));
  s.bbox_max = Vec((std::max)(0., d.x), 1, (std::max)(0., d.z));
  return s;
}

/// A 1 x 0.3 x 1 block with a lip along one edge (an L-shaped prism): the lip rises 0.3 above
/// the block, `lip_base` thick at its foot and `lip_top` thick at its top, its outer face flush
/// with the block's side. Its top is the end of a thin wall: two creases `lip_top` apart at
/// z = 0.6 along y, between faces parallel (`lip_base` = `lip_top`) or in a narrow wedge.
/// 18 creases, 12 corners of valence 3.
inline Shape lipped_box(double lip_top, double lip_base)
{
  // Fan from the reflex vertex at the lip's foot, from which the profile is star-shaped.
  return make_prism("block with a lip " + std::to_string(lip_top) + " to " + std::to_string(lip_base) + " thick",
                    {{{0, 0}, {1, 0}, {1, 0.6}, {1 - lip_top, 0.6}, {1 - lip_base, 0.3}, {0, 0.3}}}, 1, 4);
}

/// The unit square z = 0: no crease (its border is not a crease).
inline Shape square_plane()
{
  Shape s;
  s.name = "plane";
  s.triangles.push_back({Vec(0, 0, 0), Vec(1, 0, 0), Vec(1, 1, 0)});
  s.triangles.push_back({Vec(0, 0, 0), Vec(1, 1, 0), Vec(0, 1, 0)});
  s.bbox_min = Vec(0, 0, 0);
  s.bbox_max = Vec(1, 1, 0);
  return s;
}

inline double triangle_area(const Shape::Triangle& t) { return 0.5 * norm(cross(t.b - t.a, t.c - t.a)); }

/// `n` points uniformly distributed over the area of `shape` (each point picks its piece with
/// probability proportional to area), each displaced uniformly in a ball of radius
/// `noise * bbox_diagonal`. Deterministic for a given seed.
inline std::vector<Vec> sample(const Shape& shape, std::size_t n, double noise, std::uint64_t seed = 20260101)
{
  std::vector<double> cumulative;
  double total = 0;
  for(const Shape::Triangle& t : shape.triangles)
    cumulative.push_back(total += triangle_area(t));
  for(const Shape::Curved_piece& c : shape.curved)
    cumulative.push_back(total += c.area);
  const double noise_radius = noise * shape.bbox_diagonal();
  Random random(seed);
  std::vector<Vec> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const double pick = random.uniform() * total;
    const std::size_t k = std::min<std::size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(), cumulative.size() - 1);
    Vec p;
    if(k < shape.triangles.size())
    {
      const Shape::Triangle& t = shape.triangles[k];
      const double r1 = std::sqrt(random.uniform()), r2 = random.uniform();
      p = t.a * (1 - r1) + t.b * (r1 * (1 - r2)) + t.c * (r1 * r2);
    }
    else
    {
      const Shape::Curved_piece& c = shape.curved[k - shape.triangles.size()];
      const Vec u = Crease::any_orthogonal(c.axis), v = cross(c.axis, u);
      const double angle = random.uniform(0, 2 * pi);
      if(c.kind == 0)
        p = c.center + c.axis * random.uniform(0, c.height)
          + (u * std::cos(angle) + v * std::sin(angle)) * c.radius;
      else if(c.kind == 1)
        p = c.center + (u * std::cos(angle) + v * std::sin(angle)) * (c.radius * std::sqrt(random.uniform()));
      else
      {
        // Uniform in z on a sphere is uniform in area (Archimedes).
        const double z = random.uniform(-1, c.height / c.radius), rho = std::sqrt((std::max)(0., 1 - z * z));
        p = c.center + (c.axis * z + (u * std::cos(angle) + v * std::sin(angle)) * rho) * c.radius;
      }
    }
    if(noise > 0)
      p = p + random.in_ball(noise_radius);
    points.push_back(p);
  }
  return points;
}

/// `points` followed by `fraction * points.size()` outliers uniform in the bounding box of
/// `shape` (as the benchmark's sampler adds them). Deterministic for a given seed.
inline std::vector<Vec> with_outliers(std::vector<Vec> points, const Shape& shape, double fraction,
                                      std::uint64_t seed = 20260102)
{
  Random random(seed);
  const std::size_t count = std::size_t(fraction * double(points.size()) + 0.5);
  for(std::size_t i = 0; i < count; ++i)
    points.emplace_back(random.uniform(shape.bbox_min.x, shape.bbox_max.x), random.uniform(shape.bbox_min.y, shape.bbox_max.y),
                        random.uniform(shape.bbox_min.z, shape.bbox_max.z));
  return points;
}

template <typename Point_3>
std::vector<Point_3> to_points(const std::vector<Vec>& v)
{
  std::vector<Point_3> out;
  out.reserve(v.size());
  for(const Vec& p : v)
    out.emplace_back(p.x, p.y, p.z);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Measures

/// Index of the true crease closest to `p`, and the distance.
inline std::pair<std::size_t, double> nearest_crease(const Shape& shape, const Vec& p)
{
  std::pair<std::size_t, double> best(0, std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < shape.creases.size(); ++i)
  {
    const double d = shape.creases[i].distance_to(p);
    if(d < best.second)
      best = {i, d};
  }
  return best;
}

inline double point_segment_distance(const Vec& p, const Vec& a, const Vec& b)
{
  return Crease::segment(a, b, Vec(1, 0, 0), Vec(0, 1, 0)).distance_to(p);
}

/// Distance from `p` to the nearest segment of the nearest polyline.
template <typename GT>
double distance_to_network(const CGAL::Feature_curve_network<GT>& net, const Vec& p)
{
  double best = std::numeric_limits<double>::infinity();
  for(const auto& pl : net.polylines)
  {
    if(pl.points.size() == 1)
      best = (std::min)(best, distance(p, to_vec(pl.points[0])));
    for(std::size_t i = 1; i < pl.points.size(); ++i)
      best = (std::min)(best, point_segment_distance(p, to_vec(pl.points[i - 1]), to_vec(pl.points[i])));
  }
  return best;
}

/// How an extracted curve network compares with the true creases of a shape.
struct Network_errors
{
  std::size_t polylines = 0, closed_polylines = 0, corners = 0, vertices = 0;
  /// Distance from curve vertices to the nearest true crease.
  double max_vertex_distance = 0, mean_vertex_distance = 0;
  /// Fraction of the true crease length within `coverage_radius` of a curve.
  double coverage = 1;
  /// Largest distance from a true corner to the nearest found corner, and the converse.
  double max_true_corner_error = 0, max_found_corner_error = 0;
  /// Largest angle (degrees) between a curve normal and the matching true normal (up to sign
  /// and order, against the crease the curve follows).
  double max_normal_error = 0, mean_normal_error = 0;
  /// Largest | |n| - 1 | over curve normals.
  double max_normal_length_error = 0;
  /// Smallest dot product of the same normal at consecutive vertices of a curve.
  double min_consecutive_normal_dot = 1;
  /// True creases followed by exactly one curve (by majority of its vertices), and curves
  /// sharing their crease with another curve.
  std::size_t creases_with_one_curve = 0, curves_on_shared_crease = 0;
  /// Any coordinate or normal NaN/inf.
  bool all_finite = true;

  std::string summary(const std::string& label, double diagonal) const
  {
    std::ostringstream os;
    os << std::setprecision(3) << label << ": " << polylines << " polylines (" << closed_polylines << " closed), "
       << corners << " corners, " << vertices << " vertices; vertex distance max " << 100 * max_vertex_distance / diagonal
       << "% mean " << 100 * mean_vertex_distance / diagonal << "% of dB; coverage " << 100 * coverage
       << "%; corner error true->found " << 100 * max_true_corner_error / diagonal << "% found->true "
       << 100 * max_found_corner_error / diagonal << "% of dB; normal error max " << max_normal_error << " mean "
       << mean_normal_error << " deg; min consecutive normal dot " << min_consecutive_normal_dot
       << "; creases with one curve " << creases_with_one_curve << ", curves on shared crease "
       << curves_on_shared_crease;
    return os.str();
  }
};

template <typename GT>
Network_errors measure(const Shape& shape, const CGAL::Feature_curve_network<GT>& net, double coverage_radius,
                       double coverage_step)
{
  Network_errors e;
  e.polylines = net.polylines.size();
  e.corners = net.corners.size();
  double distance_sum = 0, normal_sum = 0;
  std::size_t normal_count = 0;
  std::vector<std::size_t> curves_per_crease(shape.creases.size(), 0);
  for(const auto& pl : net.polylines)
  {
    if(pl.is_closed())
      ++e.closed_polylines;
    std::vector<std::size_t> votes(shape.creases.size(), 0);
    for(const auto& p : pl.points)
    {
      const Vec v = to_vec(p);
      e.all_finite = e.all_finite && is_finite(v);
      ++e.vertices;
      if(shape.creases.empty())
        continue;
      const auto nearest = nearest_crease(shape, v);
      ++votes[nearest.first];
      e.max_vertex_distance = (std::max)(e.max_vertex_distance, nearest.second);
      distance_sum += nearest.second;
    }
    if(shape.creases.empty())
      continue;
    const std::size_t crease = std::max_element(votes.begin(), votes.end()) - votes.begin();
    ++curves_per_crease[crease];
    for(std::size_t i = 0; i < pl.normals.size() && i < pl.points.size(); ++i)
    {
      const Vec n0 = to_vec(pl.normals[i][0]), n1 = to_vec(pl.normals[i][1]);
      e.all_finite = e.all_finite && is_finite(n0) && is_finite(n1);
      e.max_normal_length_error = (std::max)({e.max_normal_length_error, std::abs(norm(n0) - 1), std::abs(norm(n1) - 1)});
      const auto truth = shape.creases[crease].normals_near(to_vec(pl.points[i]));
      const double same = (std::max)(line_angle_degrees(n0, truth[0]), line_angle_degrees(n1, truth[1]));
      const double swapped = (std::max)(line_angle_degrees(n0, truth[1]), line_angle_degrees(n1, truth[0]));
      const double error = (std::min)(same, swapped);
      e.max_normal_error = (std::max)(e.max_normal_error, error);
      normal_sum += error;
      ++normal_count;
      if(i > 0)
      {
        const Vec m0 = to_vec(pl.normals[i - 1][0]), m1 = to_vec(pl.normals[i - 1][1]);
        e.min_consecutive_normal_dot = (std::min)({e.min_consecutive_normal_dot, dot(n0, m0), dot(n1, m1)});
      }
    }
  }
  for(std::size_t c : curves_per_crease)
  {
    if(c == 1)
      ++e.creases_with_one_curve;
    if(c > 1)
      e.curves_on_shared_crease += c;
  }
  e.mean_vertex_distance = e.vertices > 0 ? distance_sum / double(e.vertices) : 0;
  e.mean_normal_error = normal_count > 0 ? normal_sum / double(normal_count) : 0;

  double covered = 0, total = 0;
  for(const Crease& c : shape.creases)
  {
    const std::size_t steps = (std::max<std::size_t>)(1, std::size_t(std::ceil(c.length() / coverage_step)));
    const double step = c.length() / double(steps);
    for(std::size_t k = 0; k < steps; ++k)
    {
      total += step;
      if(distance_to_network(net, c.point_at((double(k) + 0.5) * step)) <= coverage_radius)
        covered += step;
    }
  }
  e.coverage = total > 0 ? covered / total : 1;

  for(const Vec& t : shape.corners)
  {
    double best = std::numeric_limits<double>::infinity();
    for(const auto& k : net.corners)
      best = (std::min)(best, distance(t, to_vec(k.point)));
    e.max_true_corner_error = (std::max)(e.max_true_corner_error, best);
  }
  for(const auto& k : net.corners)
  {
    e.all_finite = e.all_finite && is_finite(to_vec(k.point));
    double best = std::numeric_limits<double>::infinity();
    for(const Vec& t : shape.corners)
      best = (std::min)(best, distance(t, to_vec(k.point)));
    e.max_found_corner_error = (std::max)(e.max_found_corner_error, best);
  }
  return e;
}

/// The Mesh_3 contract of a network: closed loops repeat their first point exactly; a curve
/// that starts or ends at a corner starts or ends exactly at the corner point; every corner
/// lists exactly the curves that start or end at it. Returns an empty string when satisfied,
/// otherwise a description of the first violation.
template <typename GT>
std::string mesh_3_contract_violation(const CGAL::Feature_curve_network<GT>& net)
{
  typedef CGAL::Feature_polyline<GT> Polyline;
  std::ostringstream why;
  for(std::size_t c = 0; c < net.polylines.size(); ++c)
  {
    const Polyline& pl = net.polylines[c];
    if(pl.points.size() < 2)
      return (why << "curve " << c << " has " << pl.points.size() << " points", why.str());
    if(pl.normals.size() != pl.points.size())
      return (why << "curve " << c << " has " << pl.normals.size() << " normal pairs for " << pl.points.size()
                  << " points", why.str());
    for(std::size_t end = 0; end < 2; ++end)
    {
      const std::size_t k = end == 0 ? pl.front_corner : pl.back_corner;
      if(k == Polyline::no_corner)
        continue;
      if(k >= net.corners.size())
        return (why << "curve " << c << " refers to corner " << k << " of " << net.corners.size(), why.str());
      const auto& point = end == 0 ? pl.points.front() : pl.points.back();
      if(!(point == net.corners[k].point))
        return (why << "curve " << c << " does not end exactly at its corner " << k, why.str());
      const auto& inc = net.corners[k].incident_polylines;
      if(std::find(inc.begin(), inc.end(), c) == inc.end())
        return (why << "corner " << k << " does not list its incident curve " << c, why.str());
    }
  }
  for(std::size_t k = 0; k < net.corners.size(); ++k)
  {
    for(std::size_t c : net.corners[k].incident_polylines)
    {
      if(c >= net.polylines.size())
        return (why << "corner " << k << " lists curve " << c << " of " << net.polylines.size(), why.str());
      if(net.polylines[c].front_corner != k && net.polylines[c].back_corner != k)
        return (why << "corner " << k << " lists curve " << c << " which neither starts nor ends there", why.str());
    }
    std::vector<std::size_t> sorted = net.corners[k].incident_polylines;
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return (why << "corner " << k << " lists a curve twice", why.str());
  }
  return std::string();
}

/// Smallest distance between curve end points that are not the exact same point (0 would mean
/// two curves meeting at a corner without sharing it exactly). Infinity if none.
template <typename GT>
double smallest_gap_between_distinct_ends(const CGAL::Feature_curve_network<GT>& net)
{
  std::vector<Vec> ends;
  std::vector<typename GT::Point_3> exact;
  for(const auto& pl : net.polylines)
    if(!pl.points.empty() && !pl.is_closed())
    {
      exact.push_back(pl.points.front());
      exact.push_back(pl.points.back());
    }
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < exact.size(); ++i)
    for(std::size_t j = i + 1; j < exact.size(); ++j)
      if(!(exact[i] == exact[j]))
        best = (std::min)(best, distance(to_vec(exact[i]), to_vec(exact[j])));
  return best;
}

/// True if no coordinate, normal, residual or scale of any stage's output is NaN or infinite.
template <typename GT>
bool result_is_finite(const CGAL::Sharp_features<GT>& r)
{
  auto finite_scales = [](const auto& s) {
    for(double v : {CGAL::to_double(s.spacing), CGAL::to_double(s.noise), CGAL::to_double(s.residual_threshold),
                    CGAL::to_double(s.rmls_tolerance), CGAL::to_double(s.corner_radius),
                    CGAL::to_double(s.growth_radius), CGAL::to_double(s.completion_distance)})
      if(!std::isfinite(v))
        return false;
    return true;
  };
  auto finite_points = [](const CGAL::Feature_point_set<GT>& f) {
    for(const auto& e : f.edge_points)
      if(!is_finite(to_vec(e.point)) || !is_finite(to_vec(e.normals[0])) || !is_finite(to_vec(e.normals[1])))
        return false;
    for(const auto& c : f.corner_points)
      if(!is_finite(to_vec(c.point)) || !std::isfinite(CGAL::to_double(c.weight)))
        return false;
    return true;
  };
  auto finite_network = [](const CGAL::Feature_curve_network<GT>& n) {
    for(const auto& pl : n.polylines)
    {
      for(const auto& p : pl.points)
        if(!is_finite(to_vec(p)))
          return false;
      for(const auto& pair : pl.normals)
        if(!is_finite(to_vec(pair[0])) || !is_finite(to_vec(pair[1])))
          return false;
    }
    for(const auto& k : n.corners)
    {
      if(!is_finite(to_vec(k.point)))
        return false;
      for(const auto& v : k.normals)
        if(!is_finite(to_vec(v)))
          return false;
    }
    return true;
  };
  for(const auto& v : r.candidates.residuals)
    if(!std::isfinite(CGAL::to_double(v)))
      return false;
  return finite_scales(r.candidates.scales) && finite_scales(r.network.scales) && finite_points(r.projected)
      && finite_points(r.smoothed) && finite_network(r.grown) && finite_network(r.network);
}

} // namespace sfe_test

#endif // SFE_TEST_ANALYTIC_SHAPES_H
