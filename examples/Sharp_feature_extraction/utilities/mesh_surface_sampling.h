// Uniform random sampling of a triangle mesh surface, with optional noise, outliers and a
// density change: the synthetic point clouds of the demo, the tests and the benchmark.
//
// The samples depend only on the seed and the input, not on the standard library: we draw raw
// 64-bit words from std::mt19937_64 (whose output the C++ standard fixes) and turn them into
// numbers ourselves, since std::uniform_real_distribution differs between implementations.
// (Only IEEE arithmetic is involved; a compiler that fuses multiply-adds, as is usual on ARM,
// may still change the last bits of the coordinates.)

#ifndef SFE_UTILITIES_MESH_SURFACE_SAMPLING_H
#define SFE_UTILITIES_MESH_SURFACE_SAMPLING_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace sfe_utilities {

/// Triangles given by indices into `vertices`.
struct Triangle_soup
{
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// reads an OFF, PLY, OBJ (or STL) polygon mesh with `CGAL::IO::read_polygon_soup()` and splits
/// every polygon into a fan of triangles around its first vertex.
/// Throws `std::runtime_error` with a one-line message if the file cannot be opened or parsed,
/// refers to missing vertices, or has no triangle.
inline Triangle_soup read_triangle_soup(const std::string& path)
{
  if(!std::ifstream(path))
    throw std::runtime_error("cannot open mesh file '" + path + "'");
  const std::size_t dot = path.find_last_of('.');
  std::string extension = (dot == std::string::npos) ? std::string() : path.substr(dot + 1);
  for(char& c : extension)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  if(extension != "off" && extension != "ply" && extension != "obj" && extension != "stl")
    throw std::runtime_error("cannot read mesh file '" + path +
                             "': unsupported file extension (expected .off, .ply, .obj or .stl)");

  using Kernel_point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Kernel_point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    throw std::runtime_error("cannot read a polygon mesh from '" + path + "' (malformed " + extension + " file?)");

  Triangle_soup soup;
  soup.vertices.reserve(points.size());
  for(const Kernel_point& p : points)
    soup.vertices.push_back({p.x(), p.y(), p.z()});
  for(const std::vector<std::size_t>& polygon : polygons) {
    for(std::size_t v : polygon)
      if(v >= points.size())
        throw std::runtime_error("mesh file '" + path + "' has a face with vertex index " +
                                 std::to_string(v) + " but only " + std::to_string(points.size()) +
                                 " vertices");
    for(std::size_t i = 1; i + 1 < polygon.size(); ++i)
      soup.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
  }
  if(soup.triangles.empty())
    throw std::runtime_error("mesh file '" + path + "' contains no triangle");
  return soup;
}

/// returns the length of the diagonal of the axis-aligned bounding box (0 for no point).
inline double bounding_box_diagonal(const std::vector<std::array<double, 3>>& points)
{
  if(points.empty())
    return 0;
  std::array<double, 3> lo = points.front(), hi = points.front();
  for(const std::array<double, 3>& p : points)
    for(std::size_t c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

struct Sampling_options
{
  /// number of points on the surface (outliers come in addition).
  std::size_t number_of_points = 100000;
  /// radius of the uniform noise in a ball, as a fraction of the bounding-box diagonal.
  double noise = 0;
  /// extra points uniform in the bounding box, as a fraction of `number_of_points`.
  double outlier_fraction = 0;
  /// if > 1: points with x above the bounding-box centre are that many times denser.
  double denser_half_factor = 1;
  unsigned seed = 1;
};

namespace sampling_internal {

using Point = std::array<double, 3>;

// The 53 high bits of a 64-bit word, scaled to a double in [0,1) exactly (no rounding).
inline double uniform_01(std::mt19937_64& generator)
{
  return static_cast<double>(generator() >> 11) * (1. / 9007199254740992.); // 2^-53
}

inline double uniform(std::mt19937_64& generator, double lo, double hi)
{
  return lo + (hi - lo) * uniform_01(generator);
}

inline double triangle_area(const Point& a, const Point& b, const Point& c)
{
  const Point u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Point v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const Point n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Uniform point in triangle abc: a point of the unit parallelogram, folded back into the
// triangle when it falls in the other half.
inline Point uniform_in_triangle(std::mt19937_64& generator, const Point& a, const Point& b, const Point& c)
{
  double s = uniform_01(generator);
  double t = uniform_01(generator);
  if(s + t > 1) {
    s = 1 - s;
    t = 1 - t;
  }
  return {a[0] + s * (b[0] - a[0]) + t * (c[0] - a[0]),
          a[1] + s * (b[1] - a[1]) + t * (c[1] - a[1]),
          a[2] + s * (b[2] - a[2]) + t * (c[2] - a[2])};
}

// Uniform offset in the ball of the given radius, by rejection from the enclosing cube
// (accepts about 52% of the draws).
inline Point uniform_in_ball(std::mt19937_64& generator, double radius)
{
  for(;;) {
    const Point v = {uniform(generator, -1, 1), uniform(generator, -1, 1), uniform(generator, -1, 1)};
    if(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= 1)
      return {radius * v[0], radius * v[1], radius * v[2]};
  }
}

inline void check_option(bool valid, const std::string& message)
{
  if(!valid)
    throw std::invalid_argument("sample_triangle_soup: " + message);
}

// Chooses a triangle with probability proportional to its area: binary search of a uniform
// number in [0, total area) among the cumulative areas.
class Area_weighted_triangles
{
public:
  explicit Area_weighted_triangles(const Triangle_soup& soup) : m_soup(soup)
  {
    m_cumulative_area.reserve(soup.triangles.size());
    double total = 0;
    for(const auto& triangle : soup.triangles) {
      for(std::size_t v : triangle)
        check_option(v < soup.vertices.size(), "a triangle refers to a missing vertex");
      total += triangle_area(soup.vertices[triangle[0]], soup.vertices[triangle[1]], soup.vertices[triangle[2]]);
      m_cumulative_area.push_back(total);
    }
    check_option(total > 0, "the triangles have zero total area");
  }

  Point sample(std::mt19937_64& generator) const
  {
    const double target = uniform_01(generator) * m_cumulative_area.back();
    const auto found = std::upper_bound(m_cumulative_area.begin(), m_cumulative_area.end(), target);
    const std::size_t t = std::min(static_cast<std::size_t>(found - m_cumulative_area.begin()),
                                   m_cumulative_area.size() - 1);
    const auto& triangle = m_soup.triangles[t];
    return uniform_in_triangle(generator, m_soup.vertices[triangle[0]], m_soup.vertices[triangle[1]],
                               m_soup.vertices[triangle[2]]);
  }

private:
  const Triangle_soup& m_soup;
  std::vector<double> m_cumulative_area;
};

// Bounding box of the vertices that the triangles use (unused vertices do not count).
inline std::array<Point, 2> triangles_bounding_box(const Triangle_soup& soup)
{
  std::array<Point, 2> box = {soup.vertices[soup.triangles.front()[0]], soup.vertices[soup.triangles.front()[0]]};
  for(const auto& triangle : soup.triangles)
    for(std::size_t v : triangle)
      for(std::size_t c = 0; c < 3; ++c) {
        box[0][c] = std::min(box[0][c], soup.vertices[v][c]);
        box[1][c] = std::max(box[1][c], soup.vertices[v][c]);
      }
  return box;
}

} // namespace sampling_internal

/// returns `options.number_of_points` points drawn uniformly on the triangles (area-weighted),
/// each moved by a uniform offset in a ball of radius `options.noise` x bbox diagonal, followed
/// by `options.outlier_fraction` x `options.number_of_points` points uniform in the bounding box
/// of the triangles. The result depends only on the inputs and `options.seed`.
/// Throws `std::invalid_argument` for a negative or non-finite option, a triangle with a missing
/// vertex, or triangles of zero total area.
inline std::vector<std::array<double, 3>> sample_triangle_soup(const Triangle_soup& soup,
                                                               const Sampling_options& options)
{
  using namespace sampling_internal;
  check_option(std::isfinite(options.noise) && options.noise >= 0, "noise must be >= 0");
  check_option(std::isfinite(options.outlier_fraction) && options.outlier_fraction >= 0,
               "outlier fraction must be >= 0");
  check_option(std::isfinite(options.denser_half_factor) && options.denser_half_factor > 0,
               "denser-half factor must be > 0");
  check_option(!soup.triangles.empty(), "no triangle to sample");

  const Area_weighted_triangles triangles(soup);
  const std::array<Point, 2> box = triangles_bounding_box(soup);
  const double noise_radius = options.noise * bounding_box_diagonal({box[0], box[1]});
  const double centre_x = 0.5 * (box[0][0] + box[1][0]);
  // Rejection keeps a sample with probability proportional to the wanted density at its place.
  const double max_density = std::max(1., options.denser_half_factor);
  const std::size_t number_of_outliers = static_cast<std::size_t>(
    std::llround(options.outlier_fraction * static_cast<double>(options.number_of_points)));

  std::mt19937_64 generator(options.seed);
  std::vector<Point> points;
  points.reserve(options.number_of_points + number_of_outliers);
  while(points.size() < options.number_of_points) {
    Point p = triangles.sample(generator);
    if(options.denser_half_factor != 1) {
      const double density = (p[0] > centre_x) ? options.denser_half_factor : 1.;
      if(uniform_01(generator) * max_density >= density)
        continue;
    }
    if(noise_radius > 0) {
      const Point offset = uniform_in_ball(generator, noise_radius);
      for(std::size_t c = 0; c < 3; ++c)
        p[c] += offset[c];
    }
    points.push_back(p);
  }
  for(std::size_t i = 0; i < number_of_outliers; ++i) {
    Point p;
    for(std::size_t c = 0; c < 3; ++c)
      p[c] = uniform(generator, box[0][c], box[1][c]);
    points.push_back(p);
  }
  return points;
}

/// writes one point per line, `x y z` with 17 significant digits (doubles survive the round
/// trip exactly). Throws `std::runtime_error` if the file cannot be written.
inline void write_xyz(const std::string& path, const std::vector<std::array<double, 3>>& points)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot open '" + path + "' for writing");
  out << std::setprecision(17);
  for(const std::array<double, 3>& p : points)
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  out.close();
  if(!out)
    throw std::runtime_error("error while writing '" + path + "'");
}

} // namespace sfe_utilities

#endif // SFE_UTILITIES_MESH_SURFACE_SAMPLING_H
