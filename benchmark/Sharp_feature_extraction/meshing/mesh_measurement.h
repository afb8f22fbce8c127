// How close a reconstructed mesh is to the true mesh, everywhere and near the true creases.
//
// All distances are fractions of the true mesh's bounding-box diagonal dB, all angles are in
// degrees. The true creases are the true mesh's edges whose two facets' normals differ by more
// than a threshold (30 degrees, as in BENCHMARK_DATA.md).
//  - distance: from area-uniform samples of the output mesh (and its vertices) to the truth;
//  - band: the same, restricted to samples within `band` (2% dB) of a true crease, plus the
//    angle between the output facet normal and the normal of the nearest true facet;
//  - dihedral: along the true creases, the angle between the output normals found a small
//    step (`dihedral_offset`, 0.5% dB) into each of the two faces, against the true angle.
//    A rounded crease spreads its turn over a wide strip and scores a flatter angle.

#ifndef SFE_MESHING_MESH_MEASUREMENT_H
#define SFE_MESHING_MESH_MEASUREMENT_H

#include "utilities/surface_mesh_checks.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace sfe_meshing {

struct Measurement_options
{
  double crease_angle = 30;       ///< degrees between facet normals that make a true crease
  double band = 0.02;             ///< half-width of the crease band, fraction of dB
  double dihedral_offset = 0.005; ///< step into each face for the dihedral angle, fraction of dB
  std::size_t samples = 200000;   ///< area-uniform samples of the measured mesh
  unsigned seed = 1;
};

struct Mesh_quality
{
  std::size_t triangles = 0;
  double mean_distance = 0, max_distance = 0;           ///< fraction of dB
  double band_mean_distance = 0, band_max_distance = 0; ///< fraction of dB
  double band_mean_normal_angle = 0;                    ///< degrees
  double band_fraction = 0;                             ///< share of the samples in the band
  double crease_true_angle = 0;    ///< mean true turning angle of the normals across the creases
  double crease_reached_angle = 0; ///< mean turning angle of the output normals there
  double crease_angle_error = 0;   ///< mean |reached - true|
  double crease_within_10 = 0;     ///< share of crease samples reproduced within 10 degrees
  std::size_t crease_samples = 0;
};

/// The true mesh with everything the measurements look up: facets and their normals in an
/// AABB tree, crease edges with the two facet normals, and a grid over points sampled on the
/// creases for the band test.
template <typename GeomTraits>
class True_surface
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  typedef typename std::vector<Triangle_3>::const_iterator Triangle_iterator;
  typedef CGAL::AABB_triangle_primitive<GeomTraits, Triangle_iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, Primitive>> Tree;

  struct Crease_edge
  {
    Point_3 a, b;
    std::array<Vector_3, 2> normals; ///< outward normals of the two facets
    std::array<Vector_3, 2> inward;  ///< unit directions, normal to the edge, into each facet
    double angle = 0;                ///< angle between the normals, degrees
  };

  True_surface(const std::vector<Point_3>& points, const std::vector<Triangle_indices>& triangles,
               double crease_angle_degrees)
    : m_points(points)
  {
    CGAL::Bbox_3 box;
    for(const Point_3& p : points)
      box += p.bbox();
    m_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                           CGAL::square(box.zmax() - box.zmin()));
    for(const Triangle_indices& t : triangles) {
      const Triangle_3 tri(points[t[0]], points[t[1]], points[t[2]]);
      if(tri.is_degenerate())
        continue;
      m_triangles.push_back(tri);
      m_indices.push_back(t);
      m_normals.push_back(unit(CGAL::normal(tri[0], tri[1], tri[2])));
    }
    orient_outward();
    m_tree.insert(m_triangles.begin(), m_triangles.end());
    m_tree.accelerate_distance_queries();
    find_creases(crease_angle_degrees);
  }

  True_surface(const True_surface&) = delete; // the tree points into the triangle vector
  True_surface& operator=(const True_surface&) = delete;

  double diagonal() const { return m_diagonal; }
  const std::vector<Crease_edge>& creases() const { return m_creases; }
  /// the crease vertices where the number of crease edges is not 2 (corners, ends).
  const std::vector<Point_3>& crease_junctions() const { return m_junctions; }
  const Tree& tree() const { return m_tree; }
  const std::vector<Triangle_3>& triangles() const { return m_triangles; }
  const Vector_3& normal(std::size_t facet) const { return m_normals[facet]; }
  std::size_t facet_of(Triangle_iterator it) const { return static_cast<std::size_t>(it - m_triangles.begin()); }

  /// distance from `p` to the nearest true crease, if it is below `radius`; else `radius`.
  double distance_to_creases(const Point_3& p, double radius) const
  {
    if(m_crease_samples.empty())
      return radius;
    Crease_search nearest(m_crease_samples, p, 1);
    const double d = std::sqrt(CGAL::to_double(nearest.begin()->second));
    return (std::min)(d, radius);
  }

  /// samples the true creases: call once with the band radius before `distance_to_creases()`.
  void prepare_band(double radius)
  {
    m_crease_samples.clear();
    // samples dense enough that the nearest sample is within 2% of the radius of the nearest point
    const double step = 0.04 * radius;
    for(const Crease_edge& e : m_creases) {
      const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(e.a, e.b)));
      const std::size_t n = (std::max)(std::size_t(1), static_cast<std::size_t>(std::ceil(l / step)));
      for(std::size_t i = 0; i <= n; ++i)
        m_crease_samples.insert(e.a + (double(i) / n) * (e.b - e.a));
    }
    m_crease_samples.build();
  }

  static Vector_3 unit(const Vector_3& v)
  {
    const double l = std::sqrt(CGAL::to_double(v.squared_length()));
    return l > 0 ? v / l : v;
  }

private:
  void orient_outward()
  {
    // signed volume: negative means the facets face inward
    double volume = 0;
    for(const Triangle_3& t : m_triangles)
      volume += CGAL::to_double(CGAL::scalar_product(t[0] - CGAL::ORIGIN,
                                                    CGAL::cross_product(t[1] - CGAL::ORIGIN, t[2] - CGAL::ORIGIN)));
    if(volume < 0)
      for(Vector_3& n : m_normals)
        n = -n;
  }

  void find_creases(double crease_angle_degrees)
  {
    const double cos_limit = std::cos(crease_angle_degrees * 3.14159265358979323846 / 180.);
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, std::size_t>>> edges;
    for(std::size_t f = 0; f < m_indices.size(); ++f)
      for(int i = 0; i < 3; ++i) {
        const std::size_t a = m_indices[f][i], b = m_indices[f][(i + 1) % 3];
        edges[std::make_pair((std::min)(a, b), (std::max)(a, b))].push_back(
          std::make_pair(f, m_indices[f][(i + 2) % 3]));
      }
    std::map<std::size_t, int> valence;
    for(const auto& e : edges) {
      if(e.second.size() != 2)
        continue;
      const std::size_t f0 = e.second[0].first, f1 = e.second[1].first;
      const double c = CGAL::to_double(m_normals[f0] * m_normals[f1]);
      if(c > cos_limit)
        continue;
      Crease_edge crease;
      crease.a = m_points[e.first.first];
      crease.b = m_points[e.first.second];
      const Vector_3 along = unit(crease.b - crease.a);
      for(int k = 0; k < 2; ++k) {
        const std::size_t f = e.second[k].first;
        crease.normals[k] = m_normals[f];
        Vector_3 d = unit(CGAL::cross_product(m_normals[f], along));
        if(CGAL::to_double(d * (m_points[e.second[k].second] - crease.a)) < 0)
          d = -d;
        crease.inward[k] = d;
      }
      crease.angle = std::acos((std::max)(-1., (std::min)(1., c))) * 180. / 3.14159265358979323846;
      m_creases.push_back(crease);
      ++valence[e.first.first];
      ++valence[e.first.second];
    }
    for(const auto& v : valence)
      if(v.second != 2)
        m_junctions.push_back(m_points[v.first]);
  }

  std::vector<Point_3> m_points;
  std::vector<Triangle_3> m_triangles;
  std::vector<Triangle_indices> m_indices;
  std::vector<Vector_3> m_normals;
  std::vector<Crease_edge> m_creases;
  std::vector<Point_3> m_junctions;
  Tree m_tree;
  typedef CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_3<GeomTraits>> Crease_search;
  typename Crease_search::Tree m_crease_samples;
  double m_diagonal = 1;
};

/// measures `mesh` (a closed triangle mesh, either orientation) against `truth`.
template <typename GeomTraits>
Mesh_quality measure_against_truth(const std::vector<typename GeomTraits::Point_3>& points,
                                   const std::vector<Triangle_indices>& triangles,
                                   True_surface<GeomTraits>& truth, const Measurement_options& options)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  typedef True_surface<GeomTraits> Truth;

  Mesh_quality q;
  const double dB = truth.diagonal();
  const double band = options.band * dB;
  truth.prepare_band(band);

  // the measured mesh, its normals made outward like the truth's
  std::vector<Triangle_3> facets;
  std::vector<Vector_3> normals;
  std::vector<double> areas;
  double volume = 0;
  for(const Triangle_indices& t : triangles) {
    const Triangle_3 tri(points[t[0]], points[t[1]], points[t[2]]);
    if(tri.is_degenerate())
      continue;
    facets.push_back(tri);
    normals.push_back(Truth::unit(CGAL::normal(tri[0], tri[1], tri[2])));
    areas.push_back(std::sqrt(CGAL::to_double(tri.squared_area())));
    volume += CGAL::to_double(CGAL::scalar_product(tri[0] - CGAL::ORIGIN,
                                                  CGAL::cross_product(tri[1] - CGAL::ORIGIN, tri[2] - CGAL::ORIGIN)));
  }
  q.triangles = triangles.size();
  if(facets.empty())
    return q;
  if(volume < 0)
    for(Vector_3& n : normals)
      n = -n;

  // area-uniform samples (the same seed gives the same samples for the same mesh)
  std::mt19937_64 generator(options.seed);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::vector<double> cumulative(areas.size());
  std::partial_sum(areas.begin(), areas.end(), cumulative.begin());
  double sum = 0, band_sum = 0, band_angle_sum = 0;
  std::size_t band_count = 0;
  auto visit = [&](const Point_3& p, std::size_t facet, bool counted) {
    const auto hit = truth.tree().closest_point_and_primitive(p);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, hit.first))) / dB;
    q.max_distance = (std::max)(q.max_distance, d);
    const bool in_band = truth.distance_to_creases(p, band) < band;
    if(in_band)
      q.band_max_distance = (std::max)(q.band_max_distance, d);
    if(!counted)
      return;
    sum += d;
    if(in_band) {
      ++band_count;
      band_sum += d;
      const double c = CGAL::to_double(normals[facet] * truth.normal(truth.facet_of(hit.second)));
      band_angle_sum += std::acos((std::max)(-1., (std::min)(1., c))) * 180. / 3.14159265358979323846;
    }
  };
  for(std::size_t i = 0; i < options.samples; ++i) {
    const double r = uniform(generator) * cumulative.back();
    const std::size_t f = std::min<std::size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin(), facets.size() - 1);
    double a = uniform(generator), b = uniform(generator);
    if(a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    const Triangle_3& t = facets[f];
    visit(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]), f, true);
  }
  for(const Triangle_3& t : facets) // vertices count for the maxima only
    for(int i = 0; i < 3; ++i)
      visit(t[i], 0, false);
  q.mean_distance = sum / options.samples;
  q.band_fraction = double(band_count) / options.samples;
  if(band_count > 0) {
    q.band_mean_distance = band_sum / band_count;
    q.band_mean_normal_angle = band_angle_sum / band_count;
  }

  // dihedral angles along the creases, away from corners and ends
  typedef CGAL::AABB_triangle_primitive<GeomTraits, typename std::vector<Triangle_3>::const_iterator> Primitive;
  CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, Primitive>> tree(facets.begin(), facets.end());
  tree.accelerate_distance_queries();
  const double offset = options.dihedral_offset * dB;
  const double step = 0.5 * offset;
  double true_sum = 0, reached_sum = 0, error_sum = 0;
  std::size_t within = 0;
  for(const auto& e : truth.creases()) {
    const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(e.a, e.b)));
    const std::size_t n = (std::max)(std::size_t(1), static_cast<std::size_t>(std::ceil(l / step)));
    for(std::size_t i = 0; i < n; ++i) {
      const Point_3 p = e.a + ((i + 0.5) / n) * (e.b - e.a);
      bool near_junction = false;
      for(const Point_3& j : truth.crease_junctions())
        if(CGAL::to_double(CGAL::squared_distance(p, j)) < CGAL::square(3 * offset)) {
          near_junction = true;
          break;
        }
      if(near_junction)
        continue;
      std::array<Vector_3, 2> m;
      for(int k = 0; k < 2; ++k) {
        const auto hit = tree.closest_point_and_primitive(p + offset * e.inward[k]);
        m[k] = normals[static_cast<std::size_t>(hit.second - facets.begin())];
      }
      const double c = CGAL::to_double(m[0] * m[1]);
      const double reached = std::acos((std::max)(-1., (std::min)(1., c))) * 180. / 3.14159265358979323846;
      true_sum += e.angle;
      reached_sum += reached;
      error_sum += std::abs(reached - e.angle);
      within += std::abs(reached - e.angle) <= 10 ? 1 : 0;
      ++q.crease_samples;
    }
  }
  if(q.crease_samples > 0) {
    q.crease_true_angle = true_sum / q.crease_samples;
    q.crease_reached_angle = reached_sum / q.crease_samples;
    q.crease_angle_error = error_sum / q.crease_samples;
    q.crease_within_10 = double(within) / q.crease_samples;
  }
  return q;
}

} // namespace sfe_meshing

#endif // SFE_MESHING_MESH_MEASUREMENT_H
