// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// sfe_bench_run: our pipeline on one test cloud, scored against the ground truth.
//
//   sfe_bench_run --mesh M.off --truth PREFIX --points 100000 --noise 0.005 [--outliers 0.01]
//                 [--denser 5] [--seed 1] [--output rows.jsonl] [--picture curves.png]
//                 [--save-curves curves.polylines.txt] [--stage-memory 1] [--threads N] [--tiles T]
//                 [--patches 0] [--patch-picture patches.png]
//
// Samples the cloud (same sampler and seed as sfe_vcm_run, so both see the same points), runs
// CGAL::extract_sharp_features with default parameters only, and appends one JSON line: the
// per-stage times (result.timings), the heap peak of the run, the accuracy of the final curves,
// of the curves before completion, and of the points of each stage (candidates, projected,
// smoothed). Run one configuration per process: the process peak RSS is then the run's.
//
// --stage-memory 1 afterwards reruns the five stages one by one to measure the heap peak of
// each (extract_sharp_features gives one peak for the whole run).
//
// --threads N limits the run to N threads (default 0: all cores).
//
// The surface patches (CGAL::segment_into_patches on the final curves) are scored against the
// faces of the mesh unless --patches 0; --patch-picture draws them (points tinted by patch).
//
// --tiles T runs CGAL::extract_sharp_features_in_tiles with at least T tiles instead (default 0:
// untiled); the candidates and projected points, which the tiled run does not keep, are then not
// scored.

#include "bench_support.h"
#include "memory_tracking.h"
#include "patch_scoring.h"

#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features_in_tiles.h>

#include <utilities/feature_rendering.h>

#include <iostream>
#include <memory>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

using namespace sfe_bench;

namespace {

typedef CGAL::Sharp_features<K> Result;

std::vector<Polyline> polylines_of(const CGAL::Feature_curve_network<K>& network)
{
  std::vector<Polyline> curves;
  for(const auto& polyline : network.polylines)
    curves.push_back(polyline.points);
  return curves;
}

std::vector<Point> corners_of(const CGAL::Feature_curve_network<K>& network)
{
  std::vector<Point> corners;
  for(const auto& corner : network.corners)
    corners.push_back(corner.point);
  return corners;
}

std::vector<Point> points_of(const CGAL::Feature_point_set<K>& features)
{
  std::vector<Point> points;
  for(const auto& e : features.edge_points)
    points.push_back(e.point);
  for(const auto& c : features.corner_points)
    points.push_back(c.point);
  return points;
}

std::array<double, 3> to_array(const Point& p) { return {p.x(), p.y(), p.z()}; }

// The cloud (thinned to at most 150k points), our curves and corners, from two sides; with
// `patch_labels` (one per point of the cloud), the points tinted by patch.
void render(const std::string& path, const std::vector<Point>& cloud, const CGAL::Feature_curve_network<K>& network,
            const std::vector<std::size_t>& patch_labels = {})
{
  std::vector<std::array<double, 3>> points;
  std::vector<sfe_utilities::Colour> tints;
  const std::size_t stride = cloud.size() / 150000 + 1;
  for(std::size_t i = 0; i < cloud.size(); i += stride)
  {
    points.push_back(to_array(cloud[i]));
    if(!patch_labels.empty())
      tints.push_back(sfe_utilities::patch_tint(patch_labels[i], CGAL::Surface_patches<K>::unassigned));
  }
  std::vector<std::vector<std::array<double, 3>>> curves;
  for(const auto& polyline : network.polylines)
  {
    curves.emplace_back();
    for(const Point& p : polyline.points)
      curves.back().push_back(to_array(p));
  }
  std::vector<std::array<double, 3>> corners;
  for(const auto& corner : network.corners)
    corners.push_back(to_array(corner.point));
  sfe_utilities::Png_image image(800, 400);
  sfe_utilities::render_side_by_side(image, points, curves, corners, sfe_utilities::front_and_back_views(), tints);
  if(!image.write(path))
    throw std::runtime_error("cannot write " + path);
}

// Heap peak (MB above the usage at the start) of each stage run on its own.
void add_stage_memory(Json_line& line, const std::vector<Point>& cloud)
{
  typedef CGAL::Parallel_if_available_tag Tag;
  auto measure = [&](const char* stage, auto&& run) {
    reset_heap_peak();
    const std::size_t before = heap_bytes_in_use();
    run();
    line.add(std::string("heap_") + stage + "_mb", (heap_peak_bytes() - before) / 1048576.);
  };
  CGAL::Candidate_points<K> candidates;
  CGAL::Feature_point_set<K> projected, smoothed;
  CGAL::Feature_curve_network<K> network;
  measure("candidates", [&] { CGAL::compute_candidate_points<Tag>(cloud, candidates); });
  measure("projection", [&] { CGAL::rmls_project_candidates<Tag>(cloud, candidates, projected); });
  measure("smoothing", [&] {
    smoothed = projected;
    CGAL::smooth_feature_points<Tag>(smoothed);
  });
  measure("growing", [&] { CGAL::grow_feature_polylines(smoothed, network); });
  measure("completion", [&] { CGAL::complete_feature_polylines(network); });
}

/// The surface patches of `cloud` bounded by `network`, scored against the true patches of
/// the mesh (faces joined across edges no sharper than the ground truth's angle); drawn into
/// `--patch-picture` if given.
void add_patch_fields(Json_line& line, const Command_line& options, const std::vector<Point>& cloud,
                      const CGAL::Feature_curve_network<K>& network)
{
  const Stopwatch clock;
  CGAL::Surface_patches<K> patches;
  CGAL::segment_into_patches<CGAL::Parallel_if_available_tag>(cloud, network, patches);
  line.add("time_patches", clock.seconds());
  Indexed_mesh mesh = read_indexed_mesh(options.text("mesh"));
  const double offset = options.number("offset");
  for(Point& v : mesh.vertices)
    v = Point(v.x() + offset, v.y() + offset, v.z() + offset);
  const std::vector<std::size_t> truth =
    true_patch_of_points(mesh, true_patch_of_faces(mesh, options.number("truth-angle")), cloud);
  const Patch_scores scores = score_patches(truth, patches.labels, CGAL::Surface_patches<K>::unassigned);
  line.add("patches_true", scores.true_patches)
      .add("patches_ours", scores.our_patches)
      .add("patches_mean_iou", scores.mean_iou)
      .add("patches_ari", scores.adjusted_rand_index)
      .add("patches_unassigned", scores.unassigned);
  if(!options.text("patch-picture").empty())
    render(options.text("patch-picture"), cloud, network, patches.labels);
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    std::map<std::string, std::string> defaults = cloud_option_defaults();
    defaults["picture"] = "";
    defaults["patch-picture"] = "";
    defaults["save-curves"] = "";
    defaults["stage-memory"] = "0";
    defaults["threads"] = "0";
    defaults["tiles"] = "0";
    defaults["patches"] = "1";
    // The dihedral angle of the ground truth's creases (sfe_ground_truth --angle): the true
    // patches are the faces joined across the other edges.
    defaults["truth-angle"] = "30";
    const Command_line options(argc, argv, defaults);
    if(options.text("mesh").empty() || options.text("truth").empty())
      throw std::invalid_argument("--mesh and --truth are required\n" + options.usage());
    const int threads = int(options.number("threads"));
#ifdef CGAL_LINKED_WITH_TBB
    std::unique_ptr<tbb::global_control> thread_limit;
    if(threads > 0)
      thread_limit.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, threads));
#endif

    const Ground_truth truth = read_cloud_truth(options);
    const bool has_truth = !truth.curves.empty();
    const std::vector<Point> cloud = make_cloud(options);

    Json_line line;
    add_cloud_fields(line, options, cloud.size());
    line.add("method", "ours");
    line.add("threads", threads);
    const std::size_t tiles = std::size_t(options.number("tiles"));
    line.add("tiles", tiles);
    {
      Result result;
      reset_heap_peak();
      const std::size_t heap_before = heap_bytes_in_use();
      const Stopwatch clock;
      const bool completed = tiles == 0
        ? CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(cloud, result)
        : CGAL::extract_sharp_features_in_tiles<CGAL::Parallel_if_available_tag>(
            cloud, result, CGAL::Sharp_feature_extraction::parameters::number_of_tiles(tiles));
      const double wall = clock.seconds();
      const double heap_peak = (heap_peak_bytes() - heap_before) / 1048576.;

      const CGAL::Sharp_feature_timings& t = result.timings;
      line.add("completed", completed)
          .add("time_context", t.context)
          .add("time_candidates", t.candidates)
          .add("time_projection", t.projection)
          .add("time_smoothing", t.smoothing)
          .add("time_growing", t.growing)
          .add("time_completion", t.completion)
          .add("time_total", t.total())
          .add("time_wall", wall)
          .add("heap_peak_mb", heap_peak)
          .add("rss_peak_mb", process_peak_rss_bytes() / 1048576.);
      const auto& s = result.candidates.scales;
      line.add("scale_spacing", s.spacing / truth.diagonal)
          .add("scale_noise", s.noise / truth.diagonal)
          .add("scale_candidate_neighbors", s.candidate_neighbors)
          .add("scale_rmls_neighbors", s.rmls_neighbors)
          .add("scale_residual_threshold", s.residual_threshold / truth.diagonal)
          .add("scale_sampled_fraction", s.sampled_fraction)
          .add("scale_search_fraction", s.search_fraction)
          .add("scale_growth_radius", s.growth_radius / truth.diagonal);

      const std::vector<double> eps = report_eps();
      add_curve_fields(line, "ours",
                       evaluate_curves(truth, polylines_of(result.network), corners_of(result.network), eps),
                       has_truth);
      add_curve_fields(line, "grown",
                       evaluate_curves(truth, polylines_of(result.grown), corners_of(result.grown), eps), has_truth);
      if(tiles == 0)
      {
        std::vector<Point> candidates;
        for(std::size_t i : result.candidates.indices)
          candidates.push_back(cloud[i]);
        add_point_fields(line, "candidates", evaluate_points(truth, candidates, eps), has_truth);
        add_point_fields(line, "projected", evaluate_points(truth, points_of(result.projected), eps), has_truth);
      }
      add_point_fields(line, "smoothed", evaluate_points(truth, points_of(result.smoothed), eps), has_truth);

      if(options.number("patches") != 0)
        add_patch_fields(line, options, cloud, result.network);
      if(!options.text("save-curves").empty())
        write_polylines(options.text("save-curves"), polylines_of(result.network));
      if(!options.text("picture").empty())
        render(options.text("picture"), cloud, result.network);
    }
    if(options.number("stage-memory") != 0)
      add_stage_memory(line, cloud);
    line.write(options.text("output"));
    return EXIT_SUCCESS;
  }
  catch(const std::exception& e)
  {
    std::cerr << "sfe_bench_run: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
