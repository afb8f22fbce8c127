// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// sfe_tiled_vs_untiled: are the tiled curves the untiled ones, vertex for vertex?
//
//   sfe_tiled_vs_untiled --mesh M.off --points 500000 [--noise 0] [--seed 1] --tiles 27
//
// Samples the cloud as sfe_bench_run does, estimates the tiled scales once, and runs the untiled
// context with those scales and their threshold, and CGAL::extract_sharp_features_in_tiles; then
// prints, as one JSON line, how many smoothed edge points, corners and curve vertices of the two
// runs are bit-identical (edge points matched by their source point).

#include "bench_support.h"

#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features_in_tiles.h>

#include <array>
#include <iostream>
#include <map>
#include <set>

using namespace sfe_bench;

namespace {

typedef CGAL::Sharp_features<K> Result;
typedef std::array<double, 3> Coordinates;

Coordinates coordinates(const Point& p) { return {{p.x(), p.y(), p.z()}}; }

std::set<Coordinates> curve_vertices(const Result& r)
{
  std::set<Coordinates> out;
  for(const auto& polyline : r.network.polylines)
    for(const Point& p : polyline.points)
      out.insert(coordinates(p));
  return out;
}

std::size_t common(const std::set<Coordinates>& a, const std::set<Coordinates>& b)
{
  std::size_t n = 0;
  for(const Coordinates& c : a)
    n += b.count(c);
  return n;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    std::map<std::string, std::string> defaults = cloud_option_defaults();
    defaults["tiles"] = "8";
    const Command_line options(argc, argv, defaults);
    if(options.text("mesh").empty())
      throw std::invalid_argument("--mesh is required\n" + options.usage());
    const std::vector<Point> cloud = make_cloud(options);
    typedef CGAL::Parallel_if_available_tag Tag;
    const auto scales = CGAL::estimate_sharp_feature_scales_for_tiles<Tag>(cloud);

    Result untiled, tiled;
    const CGAL::Sharp_feature_extraction_context<K, Tag> context(
      cloud, scales, CGAL::parameters::threshold_distance(scales.residual_threshold));
    context.extract_sharp_features(untiled);
    CGAL::extract_sharp_features_in_tiles<Tag>(
      cloud, tiled, CGAL::Sharp_feature_extraction::parameters::number_of_tiles(std::size_t(options.number("tiles"))));

    std::map<std::size_t, Coordinates> untiled_edges;
    for(const auto& e : untiled.smoothed.edge_points)
      untiled_edges[e.source] = coordinates(e.point);
    std::size_t same_edges = 0;
    for(const auto& e : tiled.smoothed.edge_points)
    {
      const auto found = untiled_edges.find(e.source);
      same_edges += found != untiled_edges.end() && found->second == coordinates(e.point) ? 1 : 0;
    }
    std::set<Coordinates> untiled_corners, tiled_corners;
    for(const auto& c : untiled.network.corners)
      untiled_corners.insert(coordinates(c.point));
    for(const auto& c : tiled.network.corners)
      tiled_corners.insert(coordinates(c.point));

    Json_line line;
    add_cloud_fields(line, options, cloud.size());
    line.add("tiles", options.number("tiles"))
        .add("halo", CGAL::tile_halo_width(scales))
        .add("edge_points_untiled", untiled.smoothed.edge_points.size())
        .add("edge_points_tiled", tiled.smoothed.edge_points.size())
        .add("edge_points_identical", same_edges)
        .add("corners_untiled", untiled_corners.size())
        .add("corners_tiled", tiled_corners.size())
        .add("corners_identical", common(untiled_corners, tiled_corners))
        .add("curves_untiled", untiled.network.polylines.size())
        .add("curves_tiled", tiled.network.polylines.size())
        .add("vertices_untiled", curve_vertices(untiled).size())
        .add("vertices_tiled", curve_vertices(tiled).size())
        .add("vertices_identical", common(curve_vertices(untiled), curve_vertices(tiled)));
    line.write(options.text("output"));
    return EXIT_SUCCESS;
  }
  catch(const std::exception& e)
  {
    std::cerr << "sfe_tiled_vs_untiled: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
