// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// sfe_ground_truth: the true creases of a CAD mesh, written for the benchmark runners.
//
//   sfe_ground_truth --mesh fandisk.off --prefix out/bench/truth/fandisk [--angle 30]
//                    [--output rows.jsonl] [--picture truth.png]
//
// writes PREFIX.polylines.txt, PREFIX.corners.xyz and PREFIX.diagonal, and appends one JSON
// line with the counts (curves, corners, sharp edges, ...) to --output (default: stdout).
// --picture renders the curves and corners over a sampling of the mesh (two views), to check
// by eye that every curve is a crease and no curve is a tessellation line.

#include "bench_support.h"
#include "ground_truth.h"

#include <utilities/feature_rendering.h>

#include <iostream>

int main(int argc, char** argv)
{
  try
  {
    const sfe_bench::Command_line options(
        argc, argv, {{"mesh", ""}, {"prefix", ""}, {"angle", "30"}, {"label", ""}, {"output", "-"}, {"picture", ""}});
    if(options.text("mesh").empty() || options.text("prefix").empty())
      throw std::invalid_argument("--mesh and --prefix are required\n" + options.usage());

    const sfe_bench::Indexed_mesh mesh = sfe_bench::read_indexed_mesh(options.text("mesh"));
    const sfe_bench::Ground_truth truth = sfe_bench::compute_ground_truth(mesh, options.number("angle"));
    sfe_bench::write_ground_truth(options.text("prefix"), truth);

    const sfe_bench::Curve_samples samples = sfe_bench::sample_polylines(truth.curves, truth.diagonal);
    std::size_t closed = 0;
    for(const sfe_bench::Polyline& curve : truth.curves)
      if(curve.size() > 2 && curve.front() == curve.back())
        ++closed;

    sfe_bench::Json_line line;
    line.add("label", options.text("label"))
        .add("mesh", options.text("mesh").substr(options.text("mesh").find_last_of('/') + 1))
        .add("angle", options.number("angle"))
        .add("vertices", mesh.vertices.size())
        .add("faces", mesh.faces.size())
        .add("diagonal", truth.diagonal)
        .add("curves", truth.curves.size())
        .add("closed_curves", closed)
        .add("corners", truth.corners.size())
        .add("sharp_edges", truth.sharp_edges)
        .add("dangling_ends", truth.dangling_ends)
        .add("irregular_edges", truth.irregular_edges)
        .add("misoriented_edges", truth.misoriented_edges)
        .add("length", samples.length / truth.diagonal);
    line.write(options.text("output"));

    if(!options.text("picture").empty())
    {
      sfe_utilities::Sampling_options sampling;
      sampling.number_of_points = 60000;
      const auto cloud = sfe_utilities::sample_triangle_soup(
          sfe_utilities::read_triangle_soup(options.text("mesh")), sampling);
      std::vector<std::vector<std::array<double, 3>>> curves;
      for(const sfe_bench::Polyline& curve : truth.curves)
      {
        curves.emplace_back();
        for(const sfe_bench::Point& p : curve)
          curves.back().push_back({p.x(), p.y(), p.z()});
      }
      std::vector<std::array<double, 3>> corners;
      for(const sfe_bench::Point& p : truth.corners)
        corners.push_back({p.x(), p.y(), p.z()});
      sfe_utilities::Png_image image(800, 400);
      sfe_utilities::render_side_by_side(image, cloud, curves, corners, sfe_utilities::front_and_back_views());
      if(!image.write(options.text("picture")))
        throw std::runtime_error("cannot write " + options.text("picture"));
    }
    return EXIT_SUCCESS;
  }
  catch(const std::exception& e)
  {
    std::cerr << "sfe_ground_truth: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
