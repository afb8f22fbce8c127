// Point cloud in, closed triangle mesh out, with or without the feature curves.
//
// The pipeline of `mesh_with_sharp_features`, kept in a header so that the test runs exactly
// the same code:
//   1. sampling spacing s of the cloud (it sets every size below);
//   2. repair of the curves for Mesh_3 (feature_curve_repair.h), then their interior vertices
//      moved onto the crease of the two surfaces fitted on either side (crease_model.h);
//   3. normals: jet estimation, orientation along the sheets of the surface
//      (orient_normals_along_sheets.h), then, near the curves, the normal of the
//      point's own side of the crease (crease_model.h);
//   4. Poisson implicit function from the oriented points, sharpened near the curves;
//   5. curve vertices off the zero set of that function moved onto it (a curve is cut where
//      it is not near it), then Mesh_3 on it, the curves protected (feature_protected_meshing.h).
// Without curves (or with every use of them switched off) the steps are identical, so the
// comparison isolates what the curves bring.

#ifndef SFE_MESHING_POINT_CLOUD_MESHING_H
#define SFE_MESHING_POINT_CLOUD_MESHING_H

#include "meshing/crease_model.h"
#include "meshing/feature_curve_repair.h"
#include "meshing/feature_protected_meshing.h"
#include "meshing/orient_normals_along_sheets.h"

#include <CGAL/Poisson_reconstruction_function.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sfe_meshing {

/// Options of `mesh_point_cloud()`. Sizes are multiples of the sampling spacing s unless the
/// absolute override is set (> 0).
struct Point_cloud_meshing_options
{
  /// Protect the curves in Mesh_3.
  bool protect_curves = true;
  /// Give points near a curve the normal of their own side.
  bool correct_normals = true;
  /// Replace the implicit function near the curves by the two-sided crease model.
  bool sharpen_creases = true;

  /// Mesh sizes relative to s (defaults measured on the benchmark: see meshing.md).
  double facet_size = 3;
  double facet_distance = 0.1;
  double edge_size = 3;
  double facet_angle = 25;
  /// The facet distance is at least this multiple of the cloud's noise scale.
  double facet_distance_per_noise = 1;
  /// Absolute overrides (0: use the relative value).
  double spacing = 0, absolute_facet_size = 0, absolute_facet_distance = 0, absolute_edge_size = 0;

  /// Neighbours for jet normal estimation and orientation (CGAL's usual 18).
  unsigned normal_neighbors = 18;
  /// Curves are snapped and dropped at these multiples of s (feature_curve_repair.h).
  double snap_tolerance = 1.5;
  double minimum_curve_length = 3;
  /// A curve is cut where a vertex is farther than this from the implicit surface
  /// (`project_feature_curves_onto_surface()`). Measured at 0.5% noise (25k points, joint):
  /// vertices of curves on true creases are up to 1.5 s off (at the shared corners, where a
  /// third surface rounds the two-surface model), those of curves 3 s or more from any true
  /// crease up to 38 s, or find no zero at all.
  double maximal_curve_move_onto_surface = 2;
  /// The pieces of a cut curve end this far from the cut, two snap tolerances: a curve that
  /// leaves the cut point at 30 degrees or more passes their new ends farther than one.
  double curve_cut_margin = 3;
  /// Step of the central differences of that projection: small against every feature of the
  /// surface, large against the solver's noise.
  double surface_projection_step = 0.05;
  /// Mesh_3 is stopped when its triangulation holds more vertices than this many per input
  /// point (unless `limits` sets a vertex limit). A mesh finer than the sampling is not
  /// supported by the data: the refinement is running away (a valid benchmark mesh needs
  /// about 0.35 vertices per point), and the limit bounds the time whatever the machine.
  double maximal_vertices_per_point = 2;

  Surface_meshing_limits limits;
};

template <typename GeomTraits>
struct Point_cloud_meshing_result
{
  typedef typename GeomTraits::Point_3 Point_3;
  Triangle_soup_3<Point_3> surface;
  std::string error; ///< empty on success
  bool stopped = false;
  double spacing = 0;
  double noise = 0; ///< noise scale (RMS distance to local planes, median)
  double far_field = 0; ///< lift of the implicit function (a distance: see `mesh_implicit_surface()`)
  Mesh_sizes sizes;
  Curve_repair_report repair;
  std::vector<CGAL::Feature_polyline<GeomTraits>> curves; ///< the curves after the repair
  std::vector<std::string> curve_problems; ///< what is still wrong after the repair
  std::size_t protected_curves = 0, protected_vertices = 0;
  std::size_t corrected_normals = 0, unoriented_points = 0;
  std::size_t projected_vertices = 0; ///< curve vertices moved onto the fitted crease
  double seconds_normals = 0, seconds_poisson = 0, seconds_meshing = 0;
};

/// Progress: the stage name and its completed fraction in [0, 1], or -1 when a stage cannot
/// tell (then the second argument of the call is the elapsed time of the stage in seconds).
typedef std::function<void(const std::string& stage, double fraction, double seconds)> Meshing_progress;

namespace meshing_internal {

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// median over (a subset of) the points of |f(p + h n) - f(p - h n)| / 2h: the gradient norm
/// of the Poisson function near the surface, to express it as a distance.
template <typename Function, typename Point_with_normal>
double gradient_norm(const Function& f, const std::vector<Point_with_normal>& pwn, double h)
{
  std::vector<double> g;
  const std::size_t step = (std::max)(std::size_t(1), pwn.size() / 2000);
  for(std::size_t i = 0; i < pwn.size(); i += step) {
    const auto& p = pwn[i].first;
    const auto& n = pwn[i].second;
    g.push_back(std::abs(CGAL::to_double(f(p + h * n) - f(p - h * n))) / (2 * h));
  }
  if(g.empty())
    return 1;
  std::nth_element(g.begin(), g.begin() + g.size() / 2, g.end());
  return g[g.size() / 2] > 0 ? g[g.size() / 2] : 1;
}

/// noise scale of the cloud: median, over up to 2000 evenly spread points, of the RMS distance
/// of their neighbours within 3 s to their best-fit plane. On smooth parts that is the normal
/// noise (plus a little curvature); creases are few and do not move the median.
template <typename Point_3>
double noise_scale(const std::vector<Point_3>& points, double s)
{
  const double radius = 3 * s;
  Spatial_grid<Point_3> grid(radius);
  for(std::size_t i = 0; i < points.size(); ++i)
    grid.insert(points[i], i);
  std::vector<double> rms;
  const std::size_t step = (std::max)(std::size_t(1), points.size() / 2000);
  for(std::size_t i = 0; i < points.size(); i += step) {
    std::vector<std::size_t> near;
    grid.for_each_within(points[i], radius, [&](std::size_t j, double) { near.push_back(j); });
    if(near.size() < 6)
      continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(std::size_t j : near)
      mean += Eigen::Vector3d(CGAL::to_double(points[j].x()), CGAL::to_double(points[j].y()),
                              CGAL::to_double(points[j].z()));
    mean /= double(near.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(std::size_t j : near) {
      const Eigen::Vector3d d = Eigen::Vector3d(CGAL::to_double(points[j].x()), CGAL::to_double(points[j].y()),
                                                CGAL::to_double(points[j].z())) - mean;
      covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance / double(near.size()));
    rms.push_back(std::sqrt((std::max)(0., eigen.eigenvalues()(0))));
  }
  if(rms.empty())
    return 0;
  std::nth_element(rms.begin(), rms.begin() + rms.size() / 2, rms.end());
  return rms[rms.size() / 2];
}

} // namespace meshing_internal

/// meshes the surface sampled by `points`, protecting `curves` (extracted feature curves,
/// ideally with their two normals per vertex; they are repaired here) unless the options say
/// otherwise. Never asserts on bad curves: what cannot be repaired is dropped and reported.
template <typename GeomTraits, typename ConcurrencyTag = CGAL::Sequential_tag>
Point_cloud_meshing_result<GeomTraits>
mesh_point_cloud(const std::vector<typename GeomTraits::Point_3>& points,
                 std::vector<CGAL::Feature_polyline<GeomTraits>> curves,
                 const Point_cloud_meshing_options& options, const Meshing_progress& progress = {},
                 const std::vector<typename GeomTraits::Point_3>& corner_hints = {})
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef std::pair<Point_3, Vector_3> Point_with_normal;
  typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
  typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
  using meshing_internal::seconds_since;

  auto report = [&](const std::string& stage, double fraction, double seconds) {
    if(progress)
      progress(stage, fraction, seconds);
  };

  Point_cloud_meshing_result<GeomTraits> result;
  if(points.size() < 100) {
    result.error = "too few points to mesh (" + std::to_string(points.size()) + ")";
    return result;
  }

  // 1. the scale of everything
  auto start = std::chrono::steady_clock::now();
  report("normals", 0, 0);
  const double s = options.spacing > 0 ? options.spacing
                   : CGAL::to_double(CGAL::compute_average_spacing<ConcurrencyTag>(points, 6));
  result.spacing = s;
  if(!(s > 0) || !std::isfinite(s)) {
    result.error = "cannot compute the sampling spacing (duplicate points only?)";
    return result;
  }
  auto pick = [s](double absolute, double relative) { return absolute > 0 ? absolute : relative * s; };
  result.sizes.facet_size = pick(options.absolute_facet_size, options.facet_size);
  // on a noisy cloud the implicit surface keeps bumps of about the noise: a facet distance
  // below them would chase the bumps with ever smaller facets
  result.noise = meshing_internal::noise_scale(points, s);
  result.sizes.facet_distance = options.absolute_facet_distance > 0
    ? options.absolute_facet_distance
    : (std::max)(options.facet_distance * s, options.facet_distance_per_noise * result.noise);
  result.sizes.edge_size = pick(options.absolute_edge_size, options.edge_size);
  result.sizes.facet_angle = options.facet_angle;

  // 2. curves Mesh_3 accepts
  const bool use_curves = options.protect_curves || options.correct_normals || options.sharpen_creases;
  if(!use_curves)
    curves.clear();
  Curve_repair_options repair_options;
  repair_options.snap_tolerance = options.snap_tolerance * s;
  repair_options.minimum_length = options.minimum_curve_length * s;
  result.repair = repair_feature_curves_for_mesh_3(curves, repair_options, corner_hints);

  // 3. oriented normals, corrected near the creases
  std::vector<Point_with_normal> pwn;
  pwn.reserve(points.size());
  for(const Point_3& p : points)
    pwn.push_back(Point_with_normal(p, CGAL::NULL_VECTOR));
  CGAL::jet_estimate_normals<ConcurrencyTag>(
    pwn, options.normal_neighbors,
    CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).callback([&](double f) {
      report("normals", 0.5 * f, seconds_since(start));
      return true;
    }));
  report("normals", 0.5, seconds_since(start));
  {
    std::vector<Point_3> sample_points;
    std::vector<Vector_3> sample_normals;
    for(const Point_with_normal& p : pwn) {
      sample_points.push_back(p.first);
      sample_normals.push_back(p.second);
    }
    const std::vector<bool> oriented =
      orient_normals_along_sheets<GeomTraits>(sample_points, sample_normals, options.normal_neighbors);
    pwn.clear();
    for(std::size_t i = 0; i < sample_points.size(); ++i)
      if(oriented[i])
        pwn.push_back(Point_with_normal(sample_points[i], sample_normals[i]));
    result.unoriented_points = sample_points.size() - pwn.size();
  }
  report("normals", 0.8, seconds_since(start));

  const Crease_model_options model_options = Crease_model_options::for_spacing(s);
  Crease_model<GeomTraits> creases(options.correct_normals || options.sharpen_creases
                                     ? curves : std::vector<CGAL::Feature_polyline<GeomTraits>>(),
                                   points, model_options);
  // the curves onto the crease of the fitted patches (ends stay: they may be shared)
  if(options.sharpen_creases) {
    for(auto& c : curves)
      if(c.normals.size() == c.points.size())
        for(std::size_t i = 1; i + 1 < c.points.size(); ++i)
          if(creases.project_onto_crease(c.points[i], s))
            ++result.projected_vertices;
  }
  if(options.correct_normals) {
    for(Point_with_normal& p : pwn) {
      Vector_3 n;
      if(!creases.side_normal(p.first, n))
        continue;
      // the jet normal is the average of the two sides: it tells the orientation
      p.second = (n * p.second < 0) ? -n : n;
      ++result.corrected_normals;
    }
  }
  {
    std::vector<Point_3> oriented_points;
    std::vector<Vector_3> oriented_normals;
    for(const Point_with_normal& p : pwn) {
      oriented_points.push_back(p.first);
      oriented_normals.push_back(p.second);
    }
    creases.orient(oriented_points, oriented_normals);
  }
  result.seconds_normals = seconds_since(start);
  report("normals", 1, result.seconds_normals);

  // 4. the implicit surface
  start = std::chrono::steady_clock::now();
  report("poisson", -1, 0);
  CGAL::Poisson_reconstruction_function<GeomTraits> poisson(pwn.begin(), pwn.end(), Point_map(), Normal_map());
  if(!poisson.compute_implicit_function()) {
    result.error = "Poisson reconstruction failed (the linear solver did not converge)";
    return result;
  }
  Crease_sharpened_function<GeomTraits, CGAL::Poisson_reconstruction_function<GeomTraits>> function;
  function.base = &poisson;
  function.creases = options.sharpen_creases ? &creases : nullptr;
  function.base_scale = 1. / meshing_internal::gradient_norm(poisson, pwn, s);

  // the protected vertices onto the surface Mesh_3 will mesh
  if(options.protect_curves) {
    project_feature_curves_onto_surface(curves, function, options.surface_projection_step * s,
                                        options.maximal_curve_move_onto_surface * s,
                                        options.curve_cut_margin * s, repair_options.minimum_length,
                                        result.repair);
    // a moved vertex may now come too close to another curve
    drop_feature_curves_in_contact(curves, repair_options.snap_tolerance, result.repair);
  }
  result.curve_problems = find_mesh_3_feature_problems(curves, repair_options.snap_tolerance);

  // Mesh_3's domain: a sphere around the cloud (its bounding cube, in fact). Mesh_3 finds its
  // first surface points along segments from the sphere's centre to its boundary: from a
  // centre outside the solid (a non-convex part, or a noisy function near the box centre) no
  // segment changes sign and no surface is found. So the centre is a point inside, the one
  // nearest to the box centre among the points `inside_depth` below the samples, and the
  // sphere grows to hold the same box.
  CGAL::Bbox_3 box;
  for(const Point_3& p : points)
    box += p.bbox();
  const Point_3 box_center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                           (box.zmin() + box.zmax()) / 2);
  Point_3 center = box_center;
  if(!(function(center) < 0)) {
    // two spacings below an oriented sample: inside, clear of the noise of the surface
    const double inside_depth = 2 * s;
    double nearest = std::numeric_limits<double>::infinity();
    const std::size_t step = (std::max)(std::size_t(1), pwn.size() / 2000);
    for(std::size_t i = 0; i < pwn.size(); i += step) {
      const Point_3 q = pwn[i].first - inside_depth * pwn[i].second;
      const double d2 = CGAL::to_double(CGAL::squared_distance(q, box_center));
      if(d2 < nearest && function(q) < 0) {
        nearest = d2;
        center = q;
      }
    }
  }
  const double half_diagonal = 0.5 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                               CGAL::square(box.ymax() - box.ymin()) +
                                               CGAL::square(box.zmax() - box.zmin()));
  const double radius = std::sqrt(CGAL::to_double(CGAL::squared_distance(center, box_center))) +
                        1.1 * half_diagonal + 5 * s;

  result.seconds_poisson = seconds_since(start);
  report("poisson", 1, result.seconds_poisson);

  // 5. the mesh
  start = std::chrono::steady_clock::now();
  report("meshing", -1, 0);
  std::vector<std::vector<Point_3>> features;
  if(options.protect_curves)
    for(const auto& c : curves)
      features.push_back(c.points);
  result.protected_curves = features.size();
  Surface_meshing_limits limits = options.limits;
  if(limits.maximal_number_of_vertices == 0)
    limits.maximal_number_of_vertices =
      static_cast<std::size_t>(options.maximal_vertices_per_point * static_cast<double>(points.size()));
  Surface_meshing_result<Point_3> mesh = mesh_implicit_surface<GeomTraits>(
    function, typename GeomTraits::Sphere_3(center, radius * radius), features, result.sizes,
    limits, [&](double seconds) { report("meshing", -1, seconds); });
  result.seconds_meshing = seconds_since(start);
  report("meshing", 1, result.seconds_meshing);
  result.surface = std::move(mesh.surface);
  result.curves = std::move(curves);
  result.protected_vertices = mesh.protected_vertices;
  result.far_field = mesh.far_field;
  result.stopped = mesh.stopped;
  result.error = mesh.error;
  return result;
}

} // namespace sfe_meshing

#endif // SFE_MESHING_POINT_CLOUD_MESHING_H
