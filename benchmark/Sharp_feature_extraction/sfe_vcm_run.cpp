// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// sfe_vcm_run: the peer. CGAL's Voronoi covariance measure labels the points of a test cloud
// that lie on sharp edges (compute_vcm, then vcm_is_on_feature_edge); the labelled points are
// scored against the ground truth.
//
//   sfe_vcm_run --mesh M.off --truth PREFIX --points 100000 --noise 0.005 \
//               --R 0.02,0.04 --r 0.01 --threshold 0.1,0.16 [--output rows.jsonl]
//
// R (offset radius) and r (convolution radius) are fractions of the mesh's bounding-box
// diagonal dB. The VCM is computed once per (R, r); every threshold reuses it. One JSON line
// per (R, r, threshold).

#include "bench_support.h"
#include "memory_tracking.h"

#include <CGAL/vcm_estimate_edges.h>

#include <iostream>

using namespace sfe_bench;

int main(int argc, char** argv)
{
  try
  {
    std::map<std::string, std::string> defaults = cloud_option_defaults();
    defaults["R"] = "0.03";
    defaults["r"] = "0.01";
    defaults["threshold"] = "0.16";
    defaults["save-points"] = "";
    const Command_line options(argc, argv, defaults);
    if(options.text("mesh").empty() || options.text("truth").empty())
      throw std::invalid_argument("--mesh and --truth are required\n" + options.usage());

    const Ground_truth truth = read_cloud_truth(options);
    const bool has_truth = !truth.curves.empty();
    const double dB = truth.diagonal;
    const std::vector<Point> cloud = make_cloud(options);

    for(double R : options.numbers("R"))
      for(double r : options.numbers("r"))
      {
        std::vector<std::array<double, 6>> covariances;
        reset_heap_peak();
        const std::size_t heap_before = heap_bytes_in_use();
        const Stopwatch vcm_clock;
        CGAL::compute_vcm(cloud, covariances, R * dB, r * dB, CGAL::parameters::geom_traits(K()));
        const double vcm_seconds = vcm_clock.seconds();
        const std::size_t vcm_heap = heap_peak_bytes() - heap_before;

        for(double threshold : options.numbers("threshold"))
        {
          const Stopwatch label_clock;
          std::vector<Point> labelled;
          for(std::size_t i = 0; i < cloud.size(); ++i)
            if(CGAL::vcm_is_on_feature_edge(covariances[i], threshold))
              labelled.push_back(cloud[i]);
          const double label_seconds = label_clock.seconds();
          if(!options.text("save-points").empty())
            write_points(options.text("save-points"), labelled);

          Json_line line;
          add_cloud_fields(line, options, cloud.size());
          line.add("method", "vcm")
              .add("vcm_R", R)
              .add("vcm_r", r)
              .add("vcm_threshold", threshold)
              .add("time_vcm", vcm_seconds)
              .add("time_label", label_seconds)
              .add("time_total", vcm_seconds + label_seconds)
              .add("heap_peak_mb", vcm_heap / 1048576.)
              .add("rss_peak_mb", process_peak_rss_bytes() / 1048576.);
          add_point_fields(line, "vcm", evaluate_points(truth, labelled, report_eps()), has_truth);
          line.write(options.text("output"));
        }
      }
    return EXIT_SUCCESS;
  }
  catch(const std::exception& e)
  {
    std::cerr << "sfe_vcm_run: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
