// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Ground truth for the benchmark: the sharp creases of a CAD triangle mesh, as polylines
// and corners, plus the plain-text formats the benchmark programs exchange them in.
//
// A mesh edge is sharp when the normals of its two faces differ by more than a given
// angle (30 degrees by default). Sharp edges are chained into curves that break at every
// vertex where the number of incident sharp edges is not 2; corners are the vertices with
// 3 or more. A chain whose vertices all have exactly 2 sharp edges is a closed curve: it
// repeats its first point at the end.

#ifndef SFE_BENCHMARK_GROUND_TRUTH_H
#define SFE_BENCHMARK_GROUND_TRUTH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sfe_bench {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef std::vector<Point> Polyline;

/// The creases of a mesh: what a feature extractor should find.
struct Ground_truth
{
  std::vector<Polyline> curves;
  std::vector<Point> corners;
  /// Bounding-box diagonal of the mesh vertices (dB): every tolerance is relative to it.
  double diagonal = 0;
  std::size_t sharp_edges = 0;
  /// Edges with one face (border) or more than two (non-manifold): counted as sharp.
  std::size_t irregular_edges = 0;
  /// Edges whose two faces traverse them in the same direction (inconsistent orientation).
  std::size_t misoriented_edges = 0;
  /// Vertices with exactly one sharp edge: a crease that fades out.
  std::size_t dangling_ends = 0;
};

/// A mesh as indexed faces, with coincident vertices merged.
struct Indexed_mesh
{
  std::vector<Point> vertices;
  std::vector<std::vector<std::size_t>> faces;
};

inline Indexed_mesh read_indexed_mesh(const std::string& path)
{
  std::vector<Point> soup_points;
  std::vector<std::vector<std::size_t>> soup_faces;
  if(!CGAL::IO::read_polygon_soup(path, soup_points, soup_faces) || soup_faces.empty())
    throw std::runtime_error("cannot read a polygon mesh from " + path);

  // OFF files from CAD exporters sometimes repeat a vertex per face: merge exact duplicates
  // so that the edges of neighbouring faces are shared.
  Indexed_mesh mesh;
  std::map<Point, std::size_t> index_of;
  std::vector<std::size_t> remap(soup_points.size());
  for(std::size_t i = 0; i < soup_points.size(); ++i)
  {
    auto inserted = index_of.emplace(soup_points[i], mesh.vertices.size());
    if(inserted.second)
      mesh.vertices.push_back(soup_points[i]);
    remap[i] = inserted.first->second;
  }
  for(const std::vector<std::size_t>& face : soup_faces)
  {
    std::vector<std::size_t> merged;
    for(std::size_t v : face)
      if(merged.empty() || merged.back() != remap[v])
        merged.push_back(remap[v]);
    if(merged.size() > 1 && merged.front() == merged.back())
      merged.pop_back();
    if(merged.size() >= 3)
      mesh.faces.push_back(merged);
  }
  return mesh;
}

inline double bounding_box_diagonal(const std::vector<Point>& points)
{
  if(points.empty())
    return 0;
  std::array<double, 3> lo{{points[0].x(), points[0].y(), points[0].z()}}, hi = lo;
  for(const Point& p : points)
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = (std::min)(lo[i], p[i]);
      hi[i] = (std::max)(hi[i], p[i]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

namespace internal {

// Newell's normal: robust for any planar polygon, zero for a degenerate one.
inline Vector face_normal(const Indexed_mesh& mesh, const std::vector<std::size_t>& face)
{
  double n[3] = {0, 0, 0};
  for(std::size_t i = 0; i < face.size(); ++i)
  {
    const Point& a = mesh.vertices[face[i]];
    const Point& b = mesh.vertices[face[(i + 1) % face.size()]];
    n[0] += (a.y() - b.y()) * (a.z() + b.z());
    n[1] += (a.z() - b.z()) * (a.x() + b.x());
    n[2] += (a.x() - b.x()) * (a.y() + b.y());
  }
  return Vector(n[0], n[1], n[2]);
}

inline double angle_in_degrees(const Vector& a, const Vector& b)
{
  const double la = std::sqrt(a.squared_length()), lb = std::sqrt(b.squared_length());
  if(la == 0 || lb == 0)
    return 0; // a degenerate face defines no crease
  double c = (a * b) / (la * lb);
  c = (std::max)(-1.0, (std::min)(1.0, c));
  return std::acos(c) * 180.0 / CGAL_PI;
}

} // namespace internal

/// Extracts the creases of `mesh`: edges whose face normals differ by more than
/// `angle_degrees`, chained into curves, and the corners where 3 or more meet.
inline Ground_truth compute_ground_truth(const Indexed_mesh& mesh, double angle_degrees = 30.)
{
  Ground_truth truth;
  truth.diagonal = bounding_box_diagonal(mesh.vertices);

  std::vector<Vector> normals;
  normals.reserve(mesh.faces.size());
  for(const std::vector<std::size_t>& face : mesh.faces)
    normals.push_back(internal::face_normal(mesh, face));

  // Each undirected edge with the faces on it and whether each face runs it as (min, max).
  typedef std::pair<std::size_t, std::size_t> Edge;
  std::map<Edge, std::vector<std::pair<std::size_t, bool>>> faces_of_edge;
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const std::vector<std::size_t>& face = mesh.faces[f];
    for(std::size_t i = 0; i < face.size(); ++i)
    {
      const std::size_t a = face[i], b = face[(i + 1) % face.size()];
      faces_of_edge[Edge((std::min)(a, b), (std::max)(a, b))].emplace_back(f, a < b);
    }
  }

  std::vector<std::vector<std::size_t>> sharp_neighbors(mesh.vertices.size());
  for(const auto& entry : faces_of_edge)
  {
    const auto& incident = entry.second;
    bool sharp = false;
    if(incident.size() != 2)
    {
      ++truth.irregular_edges;
      sharp = true;
    }
    else
    {
      if(incident[0].second == incident[1].second)
        ++truth.misoriented_edges;
      sharp = internal::angle_in_degrees(normals[incident[0].first], normals[incident[1].first]) >
              angle_degrees;
    }
    if(sharp)
    {
      ++truth.sharp_edges;
      sharp_neighbors[entry.first.first].push_back(entry.first.second);
      sharp_neighbors[entry.first.second].push_back(entry.first.first);
    }
  }

  for(std::size_t v = 0; v < mesh.vertices.size(); ++v)
  {
    if(sharp_neighbors[v].size() >= 3)
      truth.corners.push_back(mesh.vertices[v]);
    if(sharp_neighbors[v].size() == 1)
      ++truth.dangling_ends;
  }

  // Walk the sharp edges. First from every curve end (degree != 2), then the remaining
  // edges form closed loops through degree-2 vertices only.
  std::map<Edge, bool> visited;
  auto edge_key = [](std::size_t a, std::size_t b) { return Edge((std::min)(a, b), (std::max)(a, b)); };
  auto walk = [&](std::size_t start, std::size_t next) {
    Polyline curve{mesh.vertices[start]};
    std::size_t previous = start, current = next;
    visited[edge_key(start, next)] = true;
    for(;;)
    {
      curve.push_back(mesh.vertices[current]);
      if(current == start || sharp_neighbors[current].size() != 2)
        break;
      const std::size_t following = sharp_neighbors[current][0] == previous
                                        ? sharp_neighbors[current][1]
                                        : sharp_neighbors[current][0];
      if(visited[edge_key(current, following)])
        break;
      visited[edge_key(current, following)] = true;
      previous = current;
      current = following;
    }
    truth.curves.push_back(curve);
  };
  for(std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if(sharp_neighbors[v].size() != 2)
      for(std::size_t w : sharp_neighbors[v])
        if(!visited[edge_key(v, w)])
          walk(v, w);
  for(std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for(std::size_t w : sharp_neighbors[v])
      if(!visited[edge_key(v, w)])
        walk(v, w);
  return truth;
}

// ---------------------------------------------------------------------------------------
// Plain-text formats.
// Polylines: CGAL's format, one curve per line: "n x1 y1 z1 ... xn yn zn".
// Points (corners, clouds): one "x y z" per line.
// ---------------------------------------------------------------------------------------

inline void write_polylines(const std::string& path, const std::vector<Polyline>& curves)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path);
  out << std::setprecision(17);
  for(const Polyline& curve : curves)
  {
    out << curve.size();
    for(const Point& p : curve)
      out << ' ' << p.x() << ' ' << p.y() << ' ' << p.z();
    out << '\n';
  }
}

inline std::vector<Polyline> read_polylines(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot read " + path);
  std::vector<Polyline> curves;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream fields(line);
    std::size_t n = 0;
    if(!(fields >> n))
      continue;
    Polyline curve;
    double x, y, z;
    for(std::size_t i = 0; i < n && (fields >> x >> y >> z); ++i)
      curve.emplace_back(x, y, z);
    if(curve.size() != n)
      throw std::runtime_error("truncated polyline in " + path);
    curves.push_back(curve);
  }
  return curves;
}

inline void write_points(const std::string& path, const std::vector<Point>& points)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path);
  out << std::setprecision(17);
  for(const Point& p : points)
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

inline std::vector<Point> read_points(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot read " + path);
  std::vector<Point> points;
  double x, y, z;
  while(in >> x >> y >> z)
    points.emplace_back(x, y, z);
  return points;
}

/// Ground truth as written by `sfe_ground_truth`: PREFIX.polylines.txt, PREFIX.corners.xyz and
/// PREFIX.diagonal (one number: the bounding-box diagonal of the mesh).
inline Ground_truth read_ground_truth(const std::string& prefix)
{
  Ground_truth truth;
  truth.curves = read_polylines(prefix + ".polylines.txt");
  truth.corners = read_points(prefix + ".corners.xyz");
  std::ifstream in(prefix + ".diagonal");
  if(!(in >> truth.diagonal) || !(truth.diagonal > 0))
    throw std::runtime_error("cannot read " + prefix + ".diagonal");
  return truth;
}

inline void write_ground_truth(const std::string& prefix, const Ground_truth& truth)
{
  write_polylines(prefix + ".polylines.txt", truth.curves);
  write_points(prefix + ".corners.xyz", truth.corners);
  std::ofstream out(prefix + ".diagonal");
  out << std::setprecision(17) << truth.diagonal << '\n';
}

} // namespace sfe_bench

#endif // SFE_BENCHMARK_GROUND_TRUTH_H
