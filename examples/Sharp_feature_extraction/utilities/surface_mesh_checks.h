// Validity checks on a triangulated surface: closed, manifold, free of self-intersections.
//
// The checks run on the triangle soup (indices into a point array) exactly as the mesher
// produced it or as read from a file, before any repair: building a halfedge mesh first would
// silently duplicate non-manifold vertices and hide the very defects we look for.

#ifndef SFE_MESHING_SURFACE_MESH_CHECKS_H
#define SFE_MESHING_SURFACE_MESH_CHECKS_H

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sfe_meshing {

typedef std::array<std::size_t, 3> Triangle_indices;

/// Result of `check_triangle_soup()`.
struct Surface_check
{
  std::size_t vertices = 0, triangles = 0;
  std::size_t degenerate_triangles = 0;  ///< triangles repeating a vertex index
  std::size_t boundary_edges = 0;        ///< edges with one triangle
  std::size_t non_manifold_edges = 0;    ///< edges with three or more triangles
  std::size_t non_manifold_vertices = 0; ///< vertices whose triangles do not form one fan
  std::size_t self_intersecting_pairs = 0;
  bool self_intersections_tested = false;

  bool closed() const { return triangles > 0 && boundary_edges == 0; }
  bool manifold() const
  {
    return degenerate_triangles == 0 && non_manifold_edges == 0 && non_manifold_vertices == 0;
  }
  bool self_intersecting() const { return self_intersecting_pairs > 0; }
  bool valid() const { return closed() && manifold() && self_intersections_tested && !self_intersecting(); }

  std::string summary() const
  {
    std::ostringstream out;
    out << triangles << " triangles, " << vertices << " vertices: "
        << (closed() ? "closed" : "NOT closed (" + std::to_string(boundary_edges) + " border edges)") << ", "
        << (manifold() ? "manifold"
                       : "NOT manifold (" + std::to_string(non_manifold_edges) + " edges, " +
                           std::to_string(non_manifold_vertices) + " vertices, " +
                           std::to_string(degenerate_triangles) + " degenerate triangles)") << ", "
        << (!self_intersections_tested ? "self-intersections not tested"
            : self_intersecting() ? "SELF-INTERSECTING (" + std::to_string(self_intersecting_pairs) + " pairs)"
                                  : "no self-intersection");
    return out.str();
  }
};

/// checks the soup: every edge in exactly two triangles (closed, edge-manifold), the triangles
/// around every vertex form a single fan (vertex-manifold), and no two triangles intersect
/// other than along a shared edge or vertex (`CGAL::Polygon_mesh_processing`).
template <typename Point_3>
Surface_check check_triangle_soup(const std::vector<Point_3>& points,
                                  const std::vector<Triangle_indices>& triangles,
                                  bool test_self_intersections = true)
{
  Surface_check check;
  check.triangles = triangles.size();
  std::vector<bool> used(points.size(), false);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_use;
  // the link of each vertex: the edges opposite to it in its triangles
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> links(points.size());
  for(const Triangle_indices& t : triangles) {
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++check.degenerate_triangles;
      continue;
    }
    for(int i = 0; i < 3; ++i) {
      const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      used[a] = true;
      ++edge_use[std::make_pair((std::min)(a, b), (std::max)(a, b))];
      links[a].push_back(std::make_pair(b, c));
    }
  }
  for(bool u : used)
    check.vertices += u ? 1 : 0;
  for(const auto& e : edge_use) {
    if(e.second == 1)
      ++check.boundary_edges;
    else if(e.second > 2)
      ++check.non_manifold_edges;
  }
  // a manifold vertex's link edges form one connected chain (a cycle when closed)
  for(std::size_t v = 0; v < points.size(); ++v) {
    const auto& link = links[v];
    if(link.empty())
      continue;
    std::map<std::size_t, std::size_t> parent;
    std::function<std::size_t(std::size_t)> find = [&](std::size_t x) -> std::size_t {
      auto it = parent.find(x);
      if(it == parent.end() || it->second == x) {
        parent[x] = x;
        return x;
      }
      return it->second = find(it->second);
    };
    for(const auto& e : link)
      parent[find(e.first)] = find(e.second);
    std::size_t components = 0;
    for(const auto& p : parent)
      components += (find(p.first) == p.first) ? 1 : 0;
    if(components > 1)
      ++check.non_manifold_vertices;
  }

  if(test_self_intersections && !triangles.empty()) {
    std::vector<std::vector<std::size_t>> polygons;
    for(const Triangle_indices& t : triangles)
      if(!(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]))
        polygons.push_back(std::vector<std::size_t>(t.begin(), t.end()));
    std::vector<Point_3> soup_points = points;
    namespace PMP = CGAL::Polygon_mesh_processing;
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      PMP::orient_polygon_soup(soup_points, polygons); // duplicates non-manifold vertices
    CGAL::Surface_mesh<Point_3> mesh;
    PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, mesh);
    typedef typename boost::graph_traits<CGAL::Surface_mesh<Point_3>>::face_descriptor Face;
    std::vector<std::pair<Face, Face>> pairs;
    PMP::self_intersections(mesh, std::back_inserter(pairs));
    check.self_intersecting_pairs = pairs.size();
    check.self_intersections_tested = true;
  }
  return check;
}

} // namespace sfe_meshing

#endif // SFE_MESHING_SURFACE_MESH_CHECKS_H
