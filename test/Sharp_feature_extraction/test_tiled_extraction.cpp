// Tiled extraction: a cloud cut into tiles with the halo of tile_halo_width(), extracted tile by
// tile and stitched, gives the curves of the untiled run with the same scales and threshold to
// the last bit, in another order (so no gap and no duplicate at the tile faces, corners shared, loops closed), in
// any order of the tiles and with any number of threads; bad tiles are rejected.

#include "analytic_shapes.h"
#include "identical_networks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features_in_tiles.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
using namespace sfe_test;
namespace sfe = CGAL::Sharp_feature_extraction::parameters;

/// A bar with one chamfered long edge, 6 long: 15 creases, 10 corners; the tiles cut it across.
constexpr double bar_length = 6;
/// Points on the bar: a spacing of about 0.03, a halo of about a fifth of the bar.
constexpr std::size_t bar_points = 40000;
/// Tiles across the bar: 1.5 long each, less than the halo on each side.
constexpr std::size_t bar_tiles = 4;
/// The bar's creases: 5 along it, 5 around each end.
constexpr std::size_t bar_creases = 15;

Shape chamfered_bar()
{
  return make_prism("chamfered bar", {{{0, 0}, {1, 0}, {1, 0.75}, {0.75, 1}, {0, 1}}}, bar_length);
}

struct Bar
{
  std::vector<Point> points = to_points<Point>(sample(chamfered_bar(), bar_points, 0));
  CGAL::Sharp_feature_scales<double> scales =
    CGAL::estimate_sharp_feature_scales_for_tiles<CGAL::Parallel_if_available_tag>(points);
  double halo = CGAL::tile_halo_width(scales);
};

const Bar& bar()
{
  static const Bar b;
  return b;
}

CGAL::Sharp_features<K> untiled(const std::vector<Point>& points, const CGAL::Sharp_feature_scales<double>& scales)
{
  const CGAL::Sharp_feature_extraction_context<K> context(points, scales,
                                                          CGAL::parameters::threshold_distance(scales.residual_threshold));
  CGAL::Sharp_features<K> result;
  REQUIRE(context.extract_sharp_features(result));
  return result;
}

/// Tile `i` of `count` slabs across the bar (along y): the core [y0, y1), infinite ends.
CGAL::Bbox_3 slab(std::size_t i, std::size_t count)
{
  const double infinity = std::numeric_limits<double>::infinity();
  const double y0 = i == 0 ? -infinity : bar_length * double(i) / double(count);
  const double y1 = i + 1 == count ? infinity : bar_length * double(i + 1) / double(count);
  return CGAL::Bbox_3(-infinity, y0, -infinity, infinity, y1, infinity);
}

template <typename ConcurrencyTag>
CGAL::Tile_features<K> extract_slab(const Bar& b, std::size_t i, std::size_t count)
{
  const CGAL::Bbox_3 core = slab(i, count);
  std::vector<Point> points;
  for(const Point& p : b.points)
    if(p.y() >= core.ymin() - b.halo && p.y() < core.ymax() + b.halo)
      points.push_back(p);
  CGAL::Tile_features<K> tile;
  REQUIRE(CGAL::extract_tile_features<ConcurrencyTag>(points, core, b.scales, tile));
  return tile;
}

typedef std::array<double, 3> Coordinates;

/// A polyline's vertices in an order of their own: an open one from its smaller end, a closed
/// one from its smallest vertex, towards its smaller neighbour.
std::vector<Coordinates> canonical(const CGAL::Feature_polyline<K>& polyline)
{
  std::vector<Coordinates> v;
  for(const Point& p : polyline.points)
    v.push_back({{p.x(), p.y(), p.z()}});
  if(polyline.is_closed())
  {
    v.pop_back();
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    if(v.back() < v[1])
      std::reverse(v.begin() + 1, v.end());
    v.push_back(v.front());
  }
  else if(v.back() < v.front())
    std::reverse(v.begin(), v.end());
  return v;
}

/// The same curves and corners, vertex for vertex and bit for bit, whatever their order.
void check_same_curves(const CGAL::Feature_curve_network<K>& a, const CGAL::Feature_curve_network<K>& b)
{
  const auto curves = [](const CGAL::Feature_curve_network<K>& n) {
    std::vector<std::vector<Coordinates>> out;
    for(const auto& p : n.polylines)
      out.push_back(canonical(p));
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto corners = [](const CGAL::Feature_curve_network<K>& n) {
    std::vector<Coordinates> out;
    for(const auto& c : n.corners)
      out.push_back({{c.point.x(), c.point.y(), c.point.z()}});
    std::sort(out.begin(), out.end());
    return out;
  };
  CHECK(a.polylines.size() == b.polylines.size());
  CHECK(curves(a) == curves(b));
  CHECK(corners(a) == corners(b));
}

} // namespace

TEST_CASE("a bar cut into 4 tiles gives the untiled curves to the last bit", "[tiles]")
{
  const Bar& b = bar();
  // The test means something only if a tile does not see the whole bar.
  REQUIRE(2 * b.halo + bar_length / bar_tiles < bar_length);
  const CGAL::Sharp_features<K> whole = untiled(b.points, b.scales);
  CGAL::Sharp_features<K> tiled;
  REQUIRE(CGAL::extract_sharp_features_in_tiles<CGAL::Parallel_if_available_tag>(b.points, tiled,
                                                                                  sfe::number_of_tiles(bar_tiles)));
  check_same_curves(whole.network, tiled.network);
  CHECK(tiled.smoothed.edge_points.size() == whole.smoothed.edge_points.size());
  CHECK(mesh_3_contract_violation(tiled.network) == "");
  const Network_errors errors = measure(chamfered_bar(), tiled.network, 4 * b.scales.spacing, b.scales.spacing);
  INFO(errors.summary("tiled", 1.));
  CHECK(errors.polylines == bar_creases);
  CHECK(errors.corners == chamfered_bar().corners.size());
}

TEST_CASE("the stitched curves do not depend on the order of the tiles nor on the threads", "[tiles]")
{
  const Bar& b = bar();
  std::vector<CGAL::Tile_features<K>> sequential, parallel;
  for(std::size_t i = 0; i < bar_tiles; ++i)
  {
    sequential.push_back(extract_slab<CGAL::Sequential_tag>(b, i, bar_tiles));
    parallel.push_back(extract_slab<CGAL::Parallel_if_available_tag>(b, i, bar_tiles));
  }
  CGAL::Sharp_features<K> forward, reversed, threaded;
  REQUIRE(CGAL::stitch_tile_features(sequential, forward));
  std::reverse(sequential.begin(), sequential.end());
  std::swap(sequential[0], sequential[1]);
  REQUIRE(CGAL::stitch_tile_features(sequential, reversed));
  REQUIRE(CGAL::stitch_tile_features(parallel, threaded));
  check_identical(forward.network, reversed.network);
  check_identical(forward.network, threaded.network);
  check_same_curves(forward.network, untiled(b.points, b.scales).network);
}

TEST_CASE("a loop cut by the tiles is one closed curve", "[tiles]")
{
  // Two circular creases without a corner, cut in half by the tiles.
  const std::vector<Point> points = to_points<Point>(sample(capped_cylinder(), 20000, 0));
  const auto scales = CGAL::estimate_sharp_feature_scales_for_tiles<CGAL::Parallel_if_available_tag>(points);
  CGAL::Sharp_features<K> tiled;
  REQUIRE(CGAL::extract_sharp_features_in_tiles<CGAL::Parallel_if_available_tag>(points, tiled, sfe::number_of_tiles(2)));
  const Network_errors errors = measure(capped_cylinder(), tiled.network, 4 * scales.spacing, scales.spacing);
  INFO(errors.summary("tiled", 1.));
  CHECK(errors.polylines == 2);
  CHECK(errors.closed_polylines == 2);
  check_same_curves(untiled(points, scales).network, tiled.network);
}

TEST_CASE("bad tiles are rejected with a clear exception", "[tiles][bad input]")
{
  const Bar& b = bar();
  CGAL::Tile_features<K> tile;
  CHECK_THROWS_AS(CGAL::extract_tile_features<CGAL::Sequential_tag>(b.points, CGAL::Bbox_3(0, 1, 0, 1, 1, 1), b.scales, tile),
                  std::invalid_argument);
  std::vector<CGAL::Tile_features<K>> tiles = {extract_slab<CGAL::Sequential_tag>(b, 0, 2),
                                               extract_slab<CGAL::Sequential_tag>(b, 0, 2)};
  CGAL::Sharp_features<K> result;
  CHECK_THROWS_AS(CGAL::stitch_tile_features(tiles, result), std::invalid_argument);
  tiles[1] = extract_slab<CGAL::Sequential_tag>(b, 1, 2);
  tiles[1].scales.growth_radius *= 2;
  CHECK_THROWS_AS(CGAL::stitch_tile_features(tiles, result), std::invalid_argument);
}
