// I/O: write_polylines / read_polylines round trip (same doubles, so shared corners and closed
// loops stay exact), rejection of malformed lines, and the counts in the PLY header.

#include "analytic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/IO/read_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
using namespace sfe_test;

/// The cube's curve network (noise 0), computed once.
const CGAL::Feature_curve_network<K>& cube_network()
{
  static const CGAL::Feature_curve_network<K> network = [] {
    CGAL::Sharp_features<K> result;
    const std::vector<Point_3> points = to_points<Point_3>(sample(unit_cube(), 20000, 0));
    CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, result);
    return result.network;
  }();
  return network;
}

std::vector<std::vector<Point_3>> polylines_of(const CGAL::Feature_curve_network<K>& net)
{
  std::vector<std::vector<Point_3>> out;
  for(const auto& p : net.polylines)
    out.push_back(p.points);
  return out;
}

bool same_doubles(const std::vector<std::vector<Point_3>>& a, const std::vector<std::vector<Point_3>>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    if(a[i].size() != b[i].size())
      return false;
    for(std::size_t j = 0; j < a[i].size(); ++j)
      if(!(a[i][j].x() == b[i][j].x() && a[i][j].y() == b[i][j].y() && a[i][j].z() == b[i][j].z()))
        return false;
  }
  return true;
}

bool reads(const std::string& text, std::vector<std::vector<Point_3>>& polylines)
{
  std::istringstream is(text);
  return CGAL::IO::read_polylines(is, polylines);
}

bool reads(const std::string& text)
{
  std::vector<std::vector<Point_3>> polylines;
  return reads(text, polylines);
}

} // namespace

TEST_CASE("write_polylines then read_polylines gives back the same doubles", "[io]")
{
  std::vector<std::vector<Point_3>> original = polylines_of(cube_network());
  REQUIRE(!original.empty());
  // Doubles that a short decimal form would round: thirds, tiny, huge, negative zero, closed loop.
  original.push_back({Point_3(1. / 3, -2. / 3, 0.1), Point_3(1e-300, -1e300, -0.), Point_3(0.1 + 0.2, 5e-324, 1),
                      Point_3(1. / 3, -2. / 3, 0.1)});
  std::stringstream stream;
  REQUIRE(CGAL::IO::write_polylines(stream, original));
  std::vector<std::vector<Point_3>> read;
  REQUIRE(CGAL::IO::read_polylines(stream, read));
  CHECK(same_doubles(original, read));
  CHECK(read.back().front() == read.back().back());
}

TEST_CASE("write_polylines and read_polylines round-trip through a file", "[io]")
{
  const std::vector<std::vector<Point_3>> original = polylines_of(cube_network());
  const std::string filename = "sfe_test_io_round_trip.polylines.txt";
  REQUIRE(CGAL::IO::write_polylines(filename, original));
  std::vector<std::vector<Point_3>> read;
  REQUIRE(CGAL::IO::read_polylines(filename, read));
  CHECK(same_doubles(original, read));
  std::remove(filename.c_str());
  std::vector<std::vector<Point_3>> none;
  CHECK_FALSE(CGAL::IO::read_polylines("this/file/does/not/exist.txt", none));
}

TEST_CASE("read_polylines skips blank and comment lines", "[io]")
{
  std::vector<std::vector<Point_3>> polylines;
  CHECK(reads("# a comment\n\n2 0 0 0 1 1 1\n   \n  # indented comment\n3 0 0 0 1 0 0 1 1 0\n", polylines));
  REQUIRE(polylines.size() == 2);
  CHECK(polylines[0].size() == 2);
  CHECK(polylines[1].size() == 3);
  CHECK(polylines[1][2] == Point_3(1, 1, 0));
  CHECK(reads(""));
}

TEST_CASE("read_polylines rejects malformed lines", "[io]")
{
  CHECK_FALSE(reads("3 0 0 0 1 1 1\n"));             // fewer points than announced
  CHECK_FALSE(reads("2 0 0 0 1 1\n"));               // a point with two coordinates
  CHECK_FALSE(reads("2 0 0 0 1 1 1 7\n"));           // extra number
  CHECK_FALSE(reads("2 0 0 0 1 1 1 x\n"));           // trailing garbage
  CHECK_FALSE(reads("2 0 0 nan 1 1 1\n"));           // non-finite coordinate
  CHECK_FALSE(reads("2 0 0 0 inf 1 1\n"));
  CHECK_FALSE(reads("two 0 0 0 1 1 1\n"));           // no count
  CHECK_FALSE(reads("2 0 0 0 1 a 1\n"));             // not a number
  CHECK_FALSE(reads("1 0 0 0\n2 0 0 0 1 1\n"));      // a good line, then a bad one
  std::vector<std::vector<Point_3>> partial;
  CHECK_FALSE(reads("1 0 0 0\n2 0 0 0 1 1\n", partial));
  CHECK(partial.size() == 1);                        // documented: keeps what was read before
}

TEST_CASE("read_polylines reads into a point type of another kernel", "[io]")
{
  std::vector<std::vector<CGAL::Simple_cartesian<double>::Point_3>> polylines;
  std::istringstream is("2 0.5 0.25 0.125 1 2 3\n");
  REQUIRE(CGAL::IO::read_polylines(is, polylines));
  REQUIRE(polylines.size() == 1);
  CHECK(polylines[0][0].z() == 0.125);
}

TEST_CASE("write_PLY_feature_curves writes one vertex per distinct curve point and one edge per segment", "[io]")
{
  const CGAL::Feature_curve_network<K>& net = cube_network();
  REQUIRE(!net.polylines.empty());
  std::set<std::tuple<double, double, double>> distinct, corner_points;
  std::set<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>> segments;
  std::size_t segment_count = 0;
  for(const auto& p : net.polylines)
  {
    for(std::size_t i = 0; i < p.points.size(); ++i)
    {
      distinct.insert(std::make_tuple(p.points[i].x(), p.points[i].y(), p.points[i].z()));
      if(i > 0 && !(p.points[i] == p.points[i - 1]))
        ++segment_count;
    }
  }
  for(const auto& k : net.corners)
    corner_points.insert(std::make_tuple(k.point.x(), k.point.y(), k.point.z()));

  std::stringstream ply;
  REQUIRE(CGAL::IO::write_PLY_feature_curves(ply, net));
  std::string line;
  std::size_t vertices = 0, edges = 0;
  bool ended = false;
  std::vector<std::string> header;
  while(std::getline(ply, line))
  {
    header.push_back(line);
    std::istringstream row(line);
    std::string word, element;
    row >> word;
    if(word == "element")
    {
      std::size_t n;
      row >> element >> n;
      (element == "vertex" ? vertices : edges) = n;
    }
    if(line == "end_header")
    {
      ended = true;
      break;
    }
  }
  REQUIRE(ended);
  CHECK(header[0] == "ply");
  CHECK(header[1] == "format ascii 1.0");
  CHECK(vertices == distinct.size());
  CHECK(edges == segment_count);

  // Body: `vertices` rows of 11 numbers, then `edges` rows of 2 valid indices.
  std::size_t flagged_corners = 0;
  for(std::size_t v = 0; v < vertices; ++v)
  {
    REQUIRE(std::getline(ply, line));
    std::istringstream row(line);
    double values[11];
    for(double& x : values)
      REQUIRE(row >> x);
    std::string rest;
    CHECK_FALSE(row >> rest);
    CHECK(distinct.count(std::make_tuple(values[0], values[1], values[2])) == 1);
    if(values[9] == 1)
    {
      ++flagged_corners;
      CHECK(corner_points.count(std::make_tuple(values[0], values[1], values[2])) == 1);
    }
  }
  CHECK(flagged_corners == corner_points.size());
  for(std::size_t e = 0; e < edges; ++e)
  {
    REQUIRE(std::getline(ply, line));
    std::istringstream row(line);
    std::size_t a, b;
    REQUIRE(row >> a >> b);
    CHECK(a < vertices);
    CHECK(b < vertices);
    CHECK(a != b);
  }
  CHECK_FALSE(std::getline(ply, line));
}

TEST_CASE("write_PLY_feature_curves writes a valid empty file for an empty network", "[io]")
{
  std::stringstream ply;
  REQUIRE(CGAL::IO::write_PLY_feature_curves(ply, CGAL::Feature_curve_network<K>()));
  const std::string text = ply.str();
  CHECK(text.find("element vertex 0\n") != std::string::npos);
  CHECK(text.find("element edge 0\n") != std::string::npos);
  CHECK(text.size() >= std::string("end_header\n").size());
  CHECK(text.compare(text.size() - 11, 11, "end_header\n") == 0);
}
