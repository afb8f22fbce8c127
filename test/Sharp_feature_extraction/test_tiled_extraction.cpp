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
namespace sfe_parameters = CGAL::Sharp_feature_extraction::parameters;

/// A bar with one chamfered long edge, 6 long: 15 creases, 10 corners; the tiles cut it across.
constexpr double bar_length = 6;
/// Points on the bar: a spacing of about 0.03, a halo of about a fifth of the bar.
constexpr std::size_t bar_points = 40000;
/// Noise, relative to the bar's diagonal: on exact planes a tile without a halo would fit the
/// same planes as the whole cloud, and the test would not see a missing halo.
constexpr double bar_noise = 0.0005;
/// Tiles across the bar: 1.5 long each, less than the halo on each side.
constexpr std::size_t bar_tiles = 4;
/// Fraction of the creases' length the curves must cover (within 4 spacings).
constexpr double covered_fraction = 0.99;

Shape chamfered_bar()
{
  return make_prism("chamfered bar", {{{0, 0}, {1, 0}, {1, 0.75}, {0.75, 1}, {0, 1}}}, bar_length);
}

struct Bar
{
  std::vector<Point> points = to_points<Point>(sample(chamfered_bar(), bar_points, bar_noise));
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

/// Tile `i` of `count` slabs, with the points within `halo` of its core.
template <typename ConcurrencyTag>
CGAL::Tile_features<K> extract_slab(const Bar& b, std::size_t i, std::size_t count, double halo)
{
  const CGAL::Bbox_3 core = slab(i, count);
  std::vector<Point> points;
  for(const Point& p : b.points)
    if(p.y() >= core.ymin() - halo && p.y() < core.ymax() + halo)
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

/// The curves of `network`, each in its own order, sorted.
std::vector<std::vector<Coordinates>> curve_set(const CGAL::Feature_curve_network<K>& network)
{
  std::vector<std::vector<Coordinates>> out;
  for(const auto& p : network.polylines)
    out.push_back(canonical(p));
  std::sort(out.begin(), out.end());
  return out;
}

/// The corner points of `network`, sorted.
std::vector<Coordinates> corner_set(const CGAL::Feature_curve_network<K>& network)
{
  std::vector<Coordinates> out;
  for(const auto& c : network.corners)
    out.push_back({{c.point.x(), c.point.y(), c.point.z()}});
  std::sort(out.begin(), out.end());
  return out;
}

/// The same curves and corners, vertex for vertex and bit for bit, whatever their order.
void check_same_curves(const CGAL::Feature_curve_network<K>& a, const CGAL::Feature_curve_network<K>& b)
{
  CHECK(a.polylines.size() == b.polylines.size());
  CHECK(curve_set(a) == curve_set(b));
  CHECK(corner_set(a) == corner_set(b));
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
                                                                                  sfe_parameters::number_of_tiles(bar_tiles)));
  check_same_curves(whole.network, tiled.network);
  CHECK(tiled.smoothed.edge_points.size() == whole.smoothed.edge_points.size());
  CHECK(mesh_3_contract_violation(tiled.network) == "");
  const Network_errors errors = measure(chamfered_bar(), tiled.network, 4 * b.scales.spacing, b.scales.spacing);
  INFO(errors.summary("tiled", 1.));
  // Across the tile faces too (the noise, not the tiles, splits a few creases in two).
  CHECK(errors.coverage > covered_fraction);
}

TEST_CASE("the stitched curves do not depend on the order of the tiles nor on the threads", "[tiles]")
{
  const Bar& b = bar();
  std::vector<CGAL::Tile_features<K>> sequential, parallel;
  for(std::size_t i = 0; i < bar_tiles; ++i)
  {
    sequential.push_back(extract_slab<CGAL::Sequential_tag>(b, i, bar_tiles, b.halo));
    parallel.push_back(extract_slab<CGAL::Parallel_if_available_tag>(b, i, bar_tiles, b.halo));
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

TEST_CASE("without the halo the tiles' curves differ at their faces", "[tiles]")
{
  // What the tests above compare can differ: the halo is what makes the tiles exact.
  const Bar& b = bar();
  std::vector<CGAL::Tile_features<K>> tiles;
  for(std::size_t i = 0; i < bar_tiles; ++i)
    tiles.push_back(extract_slab<CGAL::Sequential_tag>(b, i, bar_tiles, 0.));
  CGAL::Sharp_features<K> stitched;
  REQUIRE(CGAL::stitch_tile_features(tiles, stitched));
  CHECK(curve_set(stitched.network) != curve_set(untiled(b.points, b.scales).network));
}

TEST_CASE("a loop cut by the tiles is one closed curve", "[tiles]")
{
  // Two circular creases without a corner, cut in half by the tiles.
  const std::vector<Point> points = to_points<Point>(sample(capped_cylinder(), 20000, 0));
  const auto scales = CGAL::estimate_sharp_feature_scales_for_tiles<CGAL::Parallel_if_available_tag>(points);
  CGAL::Sharp_features<K> tiled;
  REQUIRE(CGAL::extract_sharp_features_in_tiles<CGAL::Parallel_if_available_tag>(points, tiled, sfe_parameters::number_of_tiles(2)));
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
  std::vector<CGAL::Tile_features<K>> tiles = {extract_slab<CGAL::Sequential_tag>(b, 0, 2, b.halo),
                                               extract_slab<CGAL::Sequential_tag>(b, 0, 2, b.halo)};
  CGAL::Sharp_features<K> result;
  CHECK_THROWS_AS(CGAL::stitch_tile_features(tiles, result), std::invalid_argument);
  tiles[1] = extract_slab<CGAL::Sequential_tag>(b, 1, 2, b.halo);
  tiles[1].scales.growth_radius *= 2;
  CHECK_THROWS_AS(CGAL::stitch_tile_features(tiles, result), std::invalid_argument);
}
