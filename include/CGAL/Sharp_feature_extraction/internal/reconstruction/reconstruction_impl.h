// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The pipeline of `reconstruct_surface_with_sharp_features()`:
//   1. the scales of the feature network set every size;
//   2. repair of the polylines for Mesh_3 (Mesh_polyline_repair.h), then their interior
//      vertices moved onto the crease of the two surfaces fitted on either side (Crease_model.h);
//   3. normals: jet estimation, orientation along the sheets of the surface
//      (orient_normals_along_sheets.h), then, near the polylines, the normal of the point's own
//      side of the crease (Crease_model.h);
//   4. Poisson implicit function from the oriented points, sharpened near the polylines;
//   5. polyline vertices off the zero set of that function moved onto it (a polyline is cut
//      where it is not near it), the repair run again where that undid it, then Mesh_3 on it,
//      the polylines protected (mesh_implicit_surface.h).
// Without polylines (or with every use of them switched off) the steps are identical, so the
// comparison isolates what the curves bring.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_RECONSTRUCTION_IMPL_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_RECONSTRUCTION_IMPL_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/Surface_reconstruction_report.h>
#include <CGAL/Sharp_feature_extraction/find_mesh_3_polyline_problems.h>
#include <CGAL/Sharp_feature_extraction/internal/Mesh_polyline_repair.h>
#include <CGAL/Sharp_feature_extraction/internal/reconstruction/Crease_model.h>
#include <CGAL/Sharp_feature_extraction/internal/reconstruction/mesh_implicit_surface.h>
#include <CGAL/Sharp_feature_extraction/internal/reconstruction/orient_normals_along_sheets.h>
#include <CGAL/Sharp_feature_extraction/internal/reconstruction/project_polylines_onto_surface.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Poisson_reconstruction_function.h>
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

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {
namespace reconstruction {

/// The numbers of the reconstruction. Distances are multiples of s, an estimate of the mean
/// distance of a point to its 6 nearest neighbours (what `CGAL::compute_average_spacing()`
/// returns, and what these numbers were measured against on the meshing benchmark).
struct Reconstruction_constants
{
  /// The network's spacing (mean distance to the 6th nearest neighbour) over s: 1.61 on
  /// fandisk, 25k points, no noise; 1.54 at 0.5% noise (a ball of 0.5% of the diagonal).
  static constexpr double spacing_per_s = 1.6;
  /// Mesh sizes, in s (measured on the benchmark: see the user manual).
  static constexpr double facet_size = 3;
  static constexpr double facet_distance = 0.1;
  static constexpr double edge_size = 3;
  static constexpr double facet_angle = 25;
  /// The facet distance is at least this multiple of the noise scale: on a noisy cloud the
  /// implicit surface keeps bumps of about the noise, and a facet distance below them would
  /// chase the bumps with ever smaller facets.
  static constexpr double facet_distance_per_noise = 1;
  /// Neighbours for jet normal estimation and orientation (CGAL's usual 18).
  static constexpr unsigned normal_neighbors = 18;
  /// The repair's tolerance and minimum length, in s.
  static constexpr double repair_tolerance = 1.5;
  static constexpr double minimum_polyline_length = 3;
  /// A polyline is cut where a vertex is farther than this from the implicit surface.
  /// Measured at 0.5% noise (25k points, joint): vertices of curves on true creases are up to
  /// 1.5 s off (at the shared corners, where a third surface rounds the two-surface model),
  /// those of curves 3 s or more from any true crease up to 38 s, or find no zero at all.
  static constexpr double maximal_move_onto_surface = 2;
  /// Step of the central differences of that projection: small against every feature of the
  /// surface, large against the solver's noise.
  static constexpr double surface_projection_step = 0.05;
  /// A curve is cut where the implicit surface has another sheet nearer than this many edge
  /// sizes to a vertex (along its normal). Mesh_3's protecting balls have radii up to the edge
  /// size, and a ball that reaches another sheet makes Mesh_3 shrink the balls and refine the
  /// facets between them without end: rotor, 25k points, 0.5% noise, seeds 4 and 5, curves
  /// along walls about 2 s thick with an edge size of 3 s, shortest mesh edges 3e-5 and 2e-9.
  static constexpr double clearance_per_edge_size = 1;
  /// The step of the search for that sheet: a quarter of s, a wall thinner than that between
  /// two samples being no wall the sampling resolves.
  static constexpr double clearance_step = 0.25;
  /// The most passes of the repair and projection of the protected polylines (see
  /// `prepare_protected_polylines()`): a pass moves only the vertices the repair moved, by
  /// less than a repair tolerance, so the first pass leaves little for a second one.
  static constexpr int contract_passes = 3;
  /// Mesh_3 is stopped when its triangulation holds more vertices than this many per input
  /// point. A mesh finer than the sampling is not supported by the data: the refinement is
  /// running away (a valid benchmark mesh needs about 0.35 vertices per point), and the limit
  /// bounds the time whatever the machine.
  static constexpr double maximal_vertices_per_point = 2;
  /// Mesh_3's bounding sphere is centred on a point this deep below an oriented sample:
  /// inside, clear of the noise of the surface.
  static constexpr double inside_depth = 2;
  /// ... and reaches this far beyond the bounding box of the points.
  static constexpr double sphere_margin = 5;
  /// Fewer points than this do not make a surface.
  static constexpr std::size_t minimum_points = 100;
};

/// The choices of the caller (from the named parameters).
struct Reconstruction_settings
{
  bool protect_polylines = true;
  bool correct_normals = true;
  bool sharpen_creases = true;
  /// Absolute sizes; 0: the default multiple of s.
  double facet_size = 0, facet_distance = 0, edge_size = 0;
  double facet_angle = Reconstruction_constants::facet_angle;
  double time_limit = 0;
  unsigned seed = 0;
  std::function<bool(double)> callback;
  std::function<void(double)> unresponsive_handler;

  bool uses_polylines() const { return protect_polylines || correct_normals || sharpen_creases; }
};

/// Progress of the whole reconstruction: each step reports into its share of [0, 1].
struct Progress_shares
{
  static constexpr double jet_normals = 0.15, oriented_normals = 0.24, normals = 0.3, poisson = 0.5;
};

template <typename Point_3>
using Point_with_normal = std::pair<Point_3, typename Kernel_traits<Point_3>::Kernel::Vector_3>;

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Reports progress; remembers a cancellation.
struct Progress_reporter
{
  const std::function<bool(double)>* callback = nullptr;
  bool cancelled = false;

  bool operator()(double fraction)
  {
    if(callback != nullptr && *callback && !(*callback)(fraction))
      cancelled = true;
    return !cancelled;
  }
};

template <typename GeomTraits>
void choose_mesh_sizes(const Reconstruction_settings& settings, double s, double noise,
                       Surface_reconstruction_report<GeomTraits>& report)
{
  typedef Reconstruction_constants C;
  report.facet_size = settings.facet_size > 0 ? settings.facet_size : C::facet_size * s;
  report.facet_distance = settings.facet_distance > 0
                            ? settings.facet_distance
                            : (std::max)(C::facet_distance * s, C::facet_distance_per_noise * noise);
  report.edge_size = settings.edge_size > 0 ? settings.edge_size : C::edge_size * s;
  report.facet_angle = settings.facet_angle;
}

/// median over (a subset of) the points of |f(p + h n) - f(p - h n)| / 2h: the gradient norm
/// of the Poisson function near the surface, to express it as a distance.
template <typename Function, typename Point_3>
double gradient_norm(const Function& f, const std::vector<Point_with_normal<Point_3>>& pwn, double h)
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

/// jet normals, oriented along the sheets of the surface; the points that could not be
/// oriented are left out.
template <typename GeomTraits, typename ConcurrencyTag>
std::vector<Point_with_normal<typename GeomTraits::Point_3>>
oriented_normals(const std::vector<typename GeomTraits::Point_3>& points, Progress_reporter& progress,
                 Surface_reconstruction_report<GeomTraits>& report)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef Point_with_normal<Point_3> Pwn;
  std::vector<Pwn> pwn;
  pwn.reserve(points.size());
  for(const Point_3& p : points)
    pwn.push_back(Pwn(p, CGAL::NULL_VECTOR));
  CGAL::jet_estimate_normals<ConcurrencyTag>(
    pwn, Reconstruction_constants::normal_neighbors,
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pwn>())
      .normal_map(CGAL::Second_of_pair_property_map<Pwn>())
      .callback([&](double f) { return progress(Progress_shares::jet_normals * f); }));
  std::vector<Vector_3> normals;
  for(const Pwn& p : pwn)
    normals.push_back(p.second);
  const std::vector<bool> oriented =
    orient_normals_along_sheets<GeomTraits>(points, normals, Reconstruction_constants::normal_neighbors);
  pwn.clear();
  for(std::size_t i = 0; i < points.size(); ++i)
    if(oriented[i])
      pwn.push_back(Pwn(points[i], normals[i]));
  report.unoriented_points = points.size() - pwn.size();
  progress(Progress_shares::oriented_normals);
  return pwn;
}

/// the polylines onto the crease of the fitted patches (ends stay: they may be shared), and the
/// normals near them replaced by the normals of their own side.
template <typename GeomTraits>
void use_crease_model(Crease_model<GeomTraits>& creases, std::vector<Feature_polyline<GeomTraits>>& curves,
                      std::vector<Point_with_normal<typename GeomTraits::Point_3>>& pwn, double s,
                      const Reconstruction_settings& settings, Surface_reconstruction_report<GeomTraits>& report)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  if(settings.sharpen_creases)
    for(auto& c : curves)
      if(c.normals.size() == c.points.size())
        for(std::size_t i = 1; i + 1 < c.points.size(); ++i)
          if(creases.project_onto_crease(c.points[i], s))
            ++report.projected_onto_creases;
  if(settings.correct_normals)
    for(auto& p : pwn) {
      Vector_3 n;
      if(!creases.side_normal(p.first, n))
        continue;
      // the jet normal is the average of the two sides: it tells the orientation
      p.second = (n * p.second < 0) ? -n : n;
      ++report.corrected_normals;
    }
  std::vector<Point_3> oriented_points;
  std::vector<Vector_3> oriented_normals;
  for(const auto& p : pwn) {
    oriented_points.push_back(p.first);
    oriented_normals.push_back(p.second);
  }
  creases.orient(oriented_points, oriented_normals);
}

/// Mesh_3's domain: a sphere around the cloud (its bounding cube, in fact). Mesh_3 finds its
/// first surface points along segments from the sphere's centre to its boundary: from a
/// centre outside the solid (a non-convex part, or a noisy function near the box centre) no
/// segment changes sign and no surface is found. So the centre is a point inside, the one
/// nearest to the box centre among the points `inside_depth` below the samples, and the
/// sphere grows to hold the same box.
template <typename GeomTraits, typename Function>
typename GeomTraits::Sphere_3
bounding_sphere(const std::vector<typename GeomTraits::Point_3>& points, const Function& function,
                const std::vector<Point_with_normal<typename GeomTraits::Point_3>>& pwn, double s)
{
  typedef typename GeomTraits::Point_3 Point_3;
  CGAL::Bbox_3 box;
  for(const Point_3& p : points)
    box += p.bbox();
  const Point_3 box_center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                           (box.zmin() + box.zmax()) / 2);
  Point_3 center = box_center;
  if(!(function(center) < 0)) {
    const double depth = Reconstruction_constants::inside_depth * s;
    double nearest = std::numeric_limits<double>::infinity();
    const std::size_t step = (std::max)(std::size_t(1), pwn.size() / 2000);
    for(std::size_t i = 0; i < pwn.size(); i += step) {
      const Point_3 q = pwn[i].first - depth * pwn[i].second;
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
                        1.1 * half_diagonal + Reconstruction_constants::sphere_margin * s;
  return typename GeomTraits::Sphere_3(center, radius * radius);
}

/// adds the changes of one repair pass to `total` (the polyline counts are left to the caller).
inline void add_repair_pass(Mesh_3_polyline_repair_report& total, const Mesh_3_polyline_repair_report& pass)
{
  total.removed_points += pass.removed_points;
  total.inserted_points += pass.inserted_points;
  total.snapped_ends += pass.snapped_ends;
  total.closed_loops += pass.closed_loops;
  total.junction_splits += pass.junction_splits;
  total.sharp_turn_splits += pass.sharp_turn_splits;
  total.dropped_short += pass.dropped_short;
  total.dropped_duplicates += pass.dropped_duplicates;
  total.dropped_in_contact += pass.dropped_in_contact;
  total.discarded_normals += pass.discarded_normals;
}

/// The protected vertices onto the surface Mesh_3 will mesh, the curves cut where they are off
/// it or too near another sheet of it (see `project_polylines_onto_surface()`). The repair of
/// the curves ran before: moving their vertices (onto the fitted creases, then onto the
/// implicit surface) and cutting them can undo it (ends of pieces near other curves, vertices
/// of two curves moved within the tolerance of each other, sharp turns), and Mesh_3 then fails
/// an assertion (pinion, 25k points, noise 0, seed 3: 8 unshared ends and 12 unshared contacts
/// where four cut pieces meet, 27 sharp turns; seed 1: 27 sharp turns). So while the curves
/// fail the check, the repair runs again on them and the vertices it moved are projected again
/// (the others are on the surface already and stay exactly where they are, so shared points
/// stay shared); of the curves still named by a problem after
/// `Reconstruction_constants::contract_passes` passes, the shorter of each problem is dropped.
template <typename GeomTraits, typename Function>
void prepare_protected_polylines(std::vector<Feature_polyline<GeomTraits>>& curves, const Function& function,
                                 double s, const mesh_polylines::Repair_settings& repair,
                                 Surface_reconstruction_report<GeomTraits>& report)
{
  typedef Reconstruction_constants C;
  Polyline_projection_settings projection;
  projection.gradient_step = C::surface_projection_step * s;
  projection.maximal_move = C::maximal_move_onto_surface * s;
  projection.clearance = C::clearance_per_edge_size * report.edge_size;
  projection.clearance_step = C::clearance_step * s;
  // a protecting ball, up to the edge size, around a vertex kept this far from an unprotectable
  // one does not reach what made that vertex unprotectable (another sheet within the clearance
  // of it, or no surface near it)
  projection.cut_margin = projection.clearance + report.edge_size;
  projection.minimum_length = C::minimum_polyline_length * s;
  Polyline_projection_counts counts;
  project_polylines_onto_surface(curves, function, projection, counts);
  report.repair_after_projection.input_polylines = curves.size();
  const mesh_polylines::Contract_tolerances tolerances{repair.tolerance, repair.maximum_angle};
  std::vector<Mesh_3_polyline_problem> problems = mesh_polylines::find_contract_violations(curves, tolerances);
  for(int pass = 0; pass < C::contract_passes && !problems.empty(); ++pass) {
    add_repair_pass(report.repair_after_projection, mesh_polylines::repair_feature_polylines(curves, repair));
    project_polylines_onto_surface(curves, function, projection, counts);
    problems = mesh_polylines::find_contract_violations(curves, tolerances);
  }
  // Each problem of the last check names a curve dropped here, and dropping curves adds no
  // problem (the check looks at the curves one by one and two by two): the protected curves
  // pass the check.
  mesh_polylines::drop_shorter_of_conflicting_curves(curves, problems, report.repair_after_projection);
  report.moved_onto_surface = counts.moved_onto_surface;
  report.cut_off_surface = counts.cut_off_surface;
  report.cut_near_other_sheet = counts.cut_near_other_sheet;
}

/// Mesh_3 on `function`, the polylines protected; the soup of its surface facets.
template <typename GeomTraits, typename Function>
Triangle_soup_3<typename GeomTraits::Point_3>
mesh_with_mesh_3(const Function& function, const typename GeomTraits::Sphere_3& bound,
                 const std::vector<Feature_polyline<GeomTraits>>& curves, std::size_t number_of_points,
                 const Reconstruction_settings& settings, Progress_reporter& progress,
                 Surface_reconstruction_report<GeomTraits>& report)
{
  std::vector<std::vector<typename GeomTraits::Point_3>> features;
  if(settings.protect_polylines) {
    for(const auto& c : curves)
      features.push_back(c.points);
    report.protected_polylines = curves;
  }
  Mesh_sizes sizes;
  sizes.facet_size = report.facet_size;
  sizes.facet_distance = report.facet_distance;
  sizes.edge_size = report.edge_size;
  sizes.facet_angle = report.facet_angle;
  Surface_meshing_limits limits;
  limits.time_limit = settings.time_limit;
  limits.seed = settings.seed;
  limits.maximal_number_of_vertices = static_cast<std::size_t>(
    Reconstruction_constants::maximal_vertices_per_point * static_cast<double>(number_of_points));
  limits.heartbeat = [&progress](double) { return progress(Progress_shares::poisson); };
  limits.unresponsive_handler = settings.unresponsive_handler;
  Surface_meshing_result<typename GeomTraits::Point_3> mesh =
    mesh_implicit_surface<GeomTraits>(function, bound, features, sizes, limits);
  if(!mesh.error.empty() && !mesh.stopped)
    throw Surface_reconstruction_error(mesh.error);
  report.protected_vertices = mesh.protected_vertices;
  report.far_field = mesh.far_field;
  report.stopped = mesh.stopped;
  report.stop_reason = progress.cancelled ? "cancelled by the callback" : mesh.error;
  return std::move(mesh.surface);
}

/// The whole pipeline; see the file comment.
template <typename GeomTraits, typename ConcurrencyTag>
Triangle_soup_3<typename GeomTraits::Point_3>
reconstruct(const std::vector<typename GeomTraits::Point_3>& points, const Feature_curve_network<GeomTraits>& network,
            const Reconstruction_settings& settings, Surface_reconstruction_report<GeomTraits>& report)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef Reconstruction_constants C;
  if(points.size() < C::minimum_points)
    throw Surface_reconstruction_error("too few points to mesh (" + std::to_string(points.size()) + ")");
  report.spacing = CGAL::to_double(network.scales.spacing);
  report.noise = CGAL::to_double(network.scales.noise);
  if(!(report.spacing > 0) || !std::isfinite(report.spacing))
    throw Surface_reconstruction_error("the feature network has no sampling spacing (pass the network of "
                                       "extract_sharp_features())");
  const double s = report.spacing / C::spacing_per_s;
  choose_mesh_sizes(settings, s, report.noise, report);
  Progress_reporter progress{&settings.callback};
  auto cancelled = [&]() {
    report.stopped = true;
    report.stop_reason = "cancelled by the callback";
    return Triangle_soup_3<Point_3>();
  };
  auto start = std::chrono::steady_clock::now();
  progress(0);

  std::vector<Feature_polyline<GeomTraits>> curves;
  std::vector<Point_3> corners;
  if(settings.uses_polylines()) {
    curves = network.polylines;
    for(const auto& c : network.corners)
      corners.push_back(c.point);
  }
  mesh_polylines::Repair_settings repair;
  repair.tolerance = C::repair_tolerance * s;
  repair.minimum_length = C::minimum_polyline_length * s;
  report.repair = mesh_polylines::repair_feature_polylines(curves, repair, corners);

  auto pwn = oriented_normals<GeomTraits, ConcurrencyTag>(points, progress, report);
  Crease_model<GeomTraits> creases(settings.correct_normals || settings.sharpen_creases
                                     ? curves : std::vector<Feature_polyline<GeomTraits>>(),
                                   points, Crease_model_options::for_spacing(s));
  use_crease_model(creases, curves, pwn, s, settings, report);
  report.seconds_normals = seconds_since(start);
  if(!progress(Progress_shares::normals))
    return cancelled();

  start = std::chrono::steady_clock::now();
  typedef CGAL::Poisson_reconstruction_function<GeomTraits> Poisson;
  Poisson poisson(pwn.begin(), pwn.end(), CGAL::First_of_pair_property_map<Point_with_normal<Point_3>>(),
                  CGAL::Second_of_pair_property_map<Point_with_normal<Point_3>>());
  if(!poisson.compute_implicit_function())
    throw Surface_reconstruction_error("Poisson reconstruction failed (the linear solver did not converge)");
  Crease_sharpened_function<GeomTraits, Poisson> function;
  function.base = &poisson;
  function.creases = settings.sharpen_creases ? &creases : nullptr;
  function.base_scale = 1. / gradient_norm(poisson, pwn, s);
  if(settings.protect_polylines)
    prepare_protected_polylines(curves, function, s, repair, report);
  const typename GeomTraits::Sphere_3 bound = bounding_sphere<GeomTraits>(points, function, pwn, s);
  report.seconds_poisson = seconds_since(start);
  if(!progress(Progress_shares::poisson))
    return cancelled();

  start = std::chrono::steady_clock::now();
  auto surface = mesh_with_mesh_3(function, bound, curves, points.size(), settings, progress, report);
  report.seconds_meshing = seconds_since(start);
  progress(1);
  return surface;
}

} // namespace reconstruction
} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif // CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_RECONSTRUCTION_RECONSTRUCTION_IMPL_H
