// I/O: write_polylines / read_polylines round trip (same doubles, so shared corners and closed
// loops stay exact), rejection of malformed lines, the counts in the PLY header, the points
// coloured by patch in the PLY, and read_point_cloud (the CLI's reader): XYZ, OFF and PLY
// (ASCII and binary) read exactly, and malformed files, among them a PLY vertex element without
// y and z, rejected with a reason.

#include "analytic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/IO/read_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/IO/read_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
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
  CHECK_FALSE(reads("4000000000000000000 0 0 0\n")); // a count the line cannot hold: no room reserved for it
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

TEST_CASE("write_PLY_feature_curves with patches writes every point after the curve vertices, with its patch and "
          "its patch's colour", "[io]")
{
  const CGAL::Feature_curve_network<K>& net = cube_network();
  std::stringstream curves_only;
  REQUIRE(CGAL::IO::write_PLY_feature_curves(curves_only, net));
  const std::string curve_header = curves_only.str().substr(0, curves_only.str().find("end_header"));
  std::size_t curve_vertices = 0;
  std::istringstream(curve_header.substr(curve_header.find("element vertex ") + 15)) >> curve_vertices;
  REQUIRE(curve_vertices > 0);

  const std::vector<Point_3> points = {Point_3(0.5, 0.1, 0.2), Point_3(3, 3, 3), Point_3(-0.5, 0.25, -0.125)};
  CGAL::Surface_patches<K> patches;
  patches.labels = {0, CGAL::Surface_patches<K>::unassigned, 5};
  std::stringstream ply;
  REQUIRE(CGAL::IO::write_PLY_feature_curves(ply, net, points, patches));
  std::string line;
  std::size_t vertices = 0;
  bool has_patch = false, has_colour = false;
  while(std::getline(ply, line) && line != "end_header")
  {
    if(line.rfind("element vertex ", 0) == 0)
      vertices = std::stoul(line.substr(15));
    has_patch |= line == "property int patch";
    has_colour |= line == "property uchar red" || line == "property uchar green" || line == "property uchar blue";
  }
  CHECK(has_patch);
  CHECK(has_colour);
  REQUIRE(vertices == curve_vertices + points.size());
  // Rows of 15 numbers: x y z, two normals, corner, curve, patch, red green blue.
  std::vector<std::vector<double>> rows;
  for(std::size_t v = 0; v < vertices; ++v)
  {
    REQUIRE(std::getline(ply, line));
    std::istringstream row(line);
    std::vector<double> values(15);
    for(double& x : values)
      REQUIRE(row >> x);
    rows.push_back(values);
  }
  for(std::size_t v = 0; v < curve_vertices; ++v)
  {
    CHECK(rows[v][10] >= 0);  // a curve
    CHECK(rows[v][11] == -1); // no patch
  }
  const std::vector<long long> expected_patch = {0, -1, 5};
  for(std::size_t k = 0; k < points.size(); ++k)
  {
    const std::vector<double>& row = rows[curve_vertices + k];
    CHECK(row[0] == points[k].x());
    CHECK(row[2] == points[k].z());
    CHECK(row[10] == -1); // no curve
    CHECK(row[11] == double(expected_patch[k]));
    const std::array<unsigned char, 3> colour = CGAL::IO::patch_colour(patches.labels[k]);
    for(int c = 0; c < 3; ++c)
      CHECK(row[12 + c] == double(colour[std::size_t(c)]));
  }

  patches.labels.pop_back();
  std::stringstream mismatched;
  CHECK_THROWS_AS(CGAL::IO::write_PLY_feature_curves(mismatched, net, points, patches), std::invalid_argument);
}

TEST_CASE("patch_colour is grey for no patch and tells apart the first 20 patches", "[io]")
{
  CHECK(CGAL::IO::patch_colour(CGAL::Surface_patches<K>::unassigned) == std::array<unsigned char, 3>{128, 128, 128});
  std::vector<std::array<unsigned char, 3>> colours;
  for(std::size_t patch = 0; patch < 20; ++patch)
    colours.push_back(CGAL::IO::patch_colour(patch));
  // Any two differ visibly: by at least 24 levels in some channel; consecutive ones by far more.
  for(std::size_t a = 0; a < colours.size(); ++a)
    for(std::size_t b = a + 1; b < colours.size(); ++b)
    {
      int largest = 0;
      for(std::size_t c = 0; c < 3; ++c)
        largest = (std::max)(largest, std::abs(int(colours[a][c]) - int(colours[b][c])));
      CHECK(largest >= (b == a + 1 ? 64 : 24));
    }
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

namespace {

/// Reads `text` as a point cloud in `format`; `why` receives the reason of a failure.
bool reads_cloud(const std::string& text, const std::string& format, std::vector<Point_3>& points,
                 std::string& why)
{
  std::istringstream is(text, std::ios::in | std::ios::binary);
  return CGAL::IO::read_point_cloud(is, format, points, &why);
}

/// The reason why `text` is rejected, or "accepted".
std::string rejection(const std::string& text, const std::string& format)
{
  std::vector<Point_3> points;
  std::string why;
  return reads_cloud(text, format, points, why) ? std::string("accepted") : why;
}

bool mentions(const std::string& reason, const std::string& part)
{
  return reason != "accepted" && reason.find(part) != std::string::npos;
}

/// Appends `value` in the byte order of a `binary_little_endian` (or big) PLY body.
template <typename T>
void put_binary(std::string& body, T value, bool little_endian)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const std::uint16_t one = 1;
  const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
  if(host_little != little_endian)
    std::reverse(bytes, bytes + sizeof(T));
  body.append(bytes, sizeof(T));
}

std::string ply_header(const std::string& format, const std::string& elements)
{
  return "ply\nformat " + format + " 1.0\ncomment written by test_io\n" + elements + "end_header\n";
}

} // namespace

TEST_CASE("read_point_cloud rejects a PLY vertex element with only an x property (ASCII and binary)", "[io]")
{
  // CGAL::IO::read_points, which the CLI used before, reads these as points with y = z = 0.
  const std::string x_only = "element vertex 3\nproperty float x\n";
  CHECK(mentions(rejection(ply_header("ascii", x_only) + "1\n2\n3\n", "ply"), "no 'y' property"));
  for(const bool little : {true, false})
  {
    std::string binary = ply_header(little ? "binary_little_endian" : "binary_big_endian", x_only);
    for(float x : {1.f, 2.f, 3.f})
      put_binary(binary, x, little);
    CHECK(mentions(rejection(binary, "ply"), "no 'y' property"));
  }
  CHECK(mentions(rejection(ply_header("ascii", "element vertex 1\nproperty float x\nproperty float y\n") + "1 2\n", "ply"),
                 "no 'z' property"));
  CHECK(mentions(rejection(ply_header("ascii", "element face 0\nproperty float x\n"), "ply"), "no vertex element"));
}

TEST_CASE("read_point_cloud reads ASCII and binary PLY exactly, whatever the types and the other elements", "[io]")
{
  std::vector<Point_3> points;
  std::string why;
  // Integer-typed coordinates (CGAL's reader asserts on them), properties around x, y and z, an
  // element before the vertices with a list, and faces after them.
  const std::string elements = "element material 1\nproperty list uchar int ids\nproperty uchar kind\n"
                               "element vertex 2\nproperty double nx\nproperty int x\nproperty float z\n"
                               "property short y\nelement face 1\nproperty list uchar int vertex_indices\n";
  REQUIRE(reads_cloud(ply_header("ascii", elements) + "3 7 8 9 1\n0.5 1 3.25 -2\n0 -4 0.125 5\n2 0 1\n", "ply",
                      points, why));
  REQUIRE(points.size() == 2);
  CHECK(points[0] == Point_3(1, -2, 3.25));
  CHECK(points[1] == Point_3(-4, 5, 0.125));
  for(const bool little : {true, false})
  {
    std::string binary = ply_header(little ? "binary_little_endian" : "binary_big_endian", elements);
    put_binary<std::uint8_t>(binary, 3, little);
    for(std::int32_t id : {7, 8, 9})
      put_binary(binary, id, little);
    put_binary<std::uint8_t>(binary, 1, little);
    for(const Point_3& p : {Point_3(1, -2, 3.25), Point_3(-4, 5, 0.125)})
    {
      put_binary(binary, 0.5, little);
      put_binary(binary, std::int32_t(p.x()), little);
      put_binary(binary, float(p.z()), little);
      put_binary(binary, std::int16_t(p.y()), little);
    }
    std::vector<Point_3> binary_points;
    REQUIRE(reads_cloud(binary, "PLY", binary_points, why)); // the format in any letter case
    CHECK(binary_points == points);                           // faces after the vertices are not needed
  }
}

TEST_CASE("read_point_cloud rejects malformed PLY files with a reason", "[io]")
{
  const std::string xyz = "element vertex 1\nproperty double x\nproperty double y\nproperty double z\n";
  CHECK(mentions(rejection("PLY\n", "ply"), "not a PLY file"));
  CHECK(mentions(rejection("ply\nformat ascii 1.0\n" + xyz, "ply"), "no end_header"));
  CHECK(mentions(rejection("ply\n" + xyz + "end_header\n0 0 0\n", "ply"), "no format line"));
  CHECK(mentions(rejection(ply_header("utf8", xyz), "ply"), "unknown format 'utf8'"));
  CHECK(mentions(rejection(ply_header("ascii", "element vertex 1\nproperty int64 x\n"), "ply"), "PLY type"));
  CHECK(mentions(rejection(ply_header("ascii", "property float x\n" + xyz), "ply"), "before any element"));
  CHECK(mentions(rejection(ply_header("ascii", xyz + "property list float int i\n"), "ply"), "integer type"));
  CHECK(mentions(rejection(ply_header("ascii", xyz + "bogus line\n"), "ply"), "unknown keyword 'bogus'"));
  CHECK(mentions(rejection(ply_header("ascii", "element vertex -1\n"), "ply"), "element NAME COUNT"));
  CHECK(mentions(rejection(ply_header("ascii", xyz + "property float x\n") + "0 0 0 0\n", "ply"), "single number"));
  CHECK(mentions(rejection(ply_header("ascii", "element vertex 1\nproperty list uchar float x\nproperty float y\n"
                                               "property float z\n"), "ply"), "single number"));
  CHECK(mentions(rejection(ply_header("ascii", xyz) + "0 0\n", "ply"), "item 0 of 1 is truncated"));
  CHECK(mentions(rejection(ply_header("ascii", xyz) + "0 zero 0\n", "ply"), "truncated or malformed"));
  CHECK(mentions(rejection(ply_header("ascii", xyz) + "0 nan 0\n", "ply"), "vertex 0: non-finite"));
  std::string binary = ply_header("binary_little_endian", xyz);
  put_binary(binary, 1.0, true);
  put_binary(binary, std::numeric_limits<double>::infinity(), true);
  put_binary(binary, 1.0, true);
  CHECK(mentions(rejection(binary, "ply"), "vertex 0: non-finite"));
  CHECK(mentions(rejection(binary.substr(0, binary.size() - 1), "ply"), "truncated"));
  // Counts far beyond the data fail at the end of the data, without reserving room for them.
  CHECK(mentions(rejection(ply_header("ascii", "element vertex 4000000000000000\nproperty float x\n"
                                               "property float y\nproperty float z\n") + "0 0 0\n", "ply"),
                 "item 1 of 4000000000000000"));
  std::string huge_list = ply_header("binary_little_endian", "element a 1\nproperty list uint double l\n" + xyz);
  put_binary<std::uint32_t>(huge_list, 4000000000u, true);
  CHECK(mentions(rejection(huge_list, "ply"), "element 'a': item 0 of 1 is truncated"));
  // Elements without properties take no room, however many items they announce.
  std::vector<Point_3> points;
  std::string why;
  CHECK(reads_cloud(ply_header("ascii", "element nothing 4000000000000000\n" + xyz) + "1 2 3\n", "ply", points, why));
}

TEST_CASE("read_point_cloud reads XYZ files: comments, a count line, extra columns", "[io]")
{
  std::vector<Point_3> points;
  std::string why;
  REQUIRE(reads_cloud("# header comment\n3\n0 0 0\n\n1 2 3 0 0 1 # with a normal\n+1e-320 -1.5e300 .25\n", "xyz",
                      points, why));
  REQUIRE(points.size() == 3);
  CHECK(points[1] == Point_3(1, 2, 3));
  CHECK(points[2] == Point_3(1e-320, -1.5e300, 0.25));
  CHECK(reads_cloud("", "xyz", points, why)); // empty is a valid, empty cloud; points are appended
  CHECK(points.size() == 3);
}

TEST_CASE("read_point_cloud rejects malformed XYZ files with a reason", "[io]")
{
  CHECK(mentions(rejection("0 0 0\n1 1\n", "xyz"), "line 2: expected three coordinates, found 2"));
  CHECK(mentions(rejection("0 0 0\n1 1 one\n", "xyz"), "line 2: 'one' is not a number"));
  CHECK(mentions(rejection("0 0 0\n1 +-1 1\n", "xyz"), "'+-1' is not a number"));
  CHECK(mentions(rejection("0 0 nan\n", "xyz"), "line 1: non-finite coordinate"));
  CHECK(mentions(rejection("0 -inf 0\n", "xyz"), "line 1: non-finite coordinate"));
  CHECK(mentions(rejection("0 1e400 0\n", "xyz"), "line 1: non-finite coordinate"));
  CHECK(mentions(rejection("3\n0 0 0\n1 1 1\n", "xyz"), "announces 3 points, the file holds 2"));
  CHECK(mentions(rejection("0 0 0\n3\n", "xyz"), "line 2: expected three coordinates"));
}

TEST_CASE("read_point_cloud reads OFF vertices and rejects malformed OFF files", "[io]")
{
  std::vector<Point_3> points;
  std::string why;
  REQUIRE(reads_cloud("OFF\n# comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n", "off", points, why));
  REQUIRE(points.size() == 3);
  CHECK(points[2] == Point_3(0, 1, 0.5));
  std::vector<Point_3> normals_and_colours;
  REQUIRE(reads_cloud("CNOFF 2 0 0\n0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n", "off", normals_and_colours, why));
  CHECK(normals_and_colours.size() == 2);
  CHECK(mentions(rejection("", "off"), "empty file"));
  CHECK(mentions(rejection("PLY\n", "off"), "not an OFF file"));
  CHECK(mentions(rejection("4OFF\n1 0 0\n0 0 0 1\n", "off"), "not supported"));
  CHECK(mentions(rejection("nOFF\n4 1 0 0\n0 0 0 1\n", "off"), "not supported"));
  CHECK(mentions(rejection("OFF BINARY\n", "off"), "binary OFF"));
  CHECK(mentions(rejection("OFF\n", "off"), "no vertex and face counts"));
  CHECK(mentions(rejection("OFF\n2\n", "off"), "expected the counts"));
  CHECK(mentions(rejection("OFF\n2 0 x\n", "off"), "'x' is not a number"));
  CHECK(mentions(rejection("OFF\n2 0 0\n0 0 0\n", "off"), "ends after 1 of 2 vertices"));
  CHECK(mentions(rejection("OFF\n1 0 0\n0 0\n", "off"), "line 3: expected three vertex coordinates"));
  CHECK(mentions(rejection("OFF\n1 0 0\n0 inf 0\n", "off"), "line 3: non-finite coordinate"));
  CHECK(mentions(rejection("OFF\n4000000000000000 0 0\n0 0 0\n", "off"), "ends after 1 of 4000000000000000"));
}

TEST_CASE("read_point_cloud picks the format from the file extension and leaves the points on failure", "[io]")
{
  const std::string filename = "sfe_test_io_cloud.XYZ";
  {
    std::ofstream os(filename);
    os << "0 0 0\n1 2 3\n";
  }
  std::vector<Point_3> points{Point_3(9, 9, 9)};
  std::string why;
  REQUIRE(CGAL::IO::read_point_cloud(filename, points, &why));
  REQUIRE(points.size() == 3);
  CHECK(points[2] == Point_3(1, 2, 3));
  std::remove(filename.c_str());
  CHECK_FALSE(CGAL::IO::read_point_cloud(filename, points, &why));
  CHECK(why == "cannot open the file");
  CHECK_FALSE(CGAL::IO::read_point_cloud("cloud.e57", points, &why));
  CHECK(why == "unknown file extension 'e57' (expected .xyz, .ply, .off or .las)");
  CHECK_FALSE(CGAL::IO::read_point_cloud("a.dir/cloud", points));
  CHECK(points.size() == 3);
  CHECK(mentions(rejection("0 0 0\n", "e57"), "unknown point cloud format 'e57'"));
  CHECK(mentions(rejection("0 0 0\n1 1\n", "xyz"), "line 2"));
  std::vector<Point_3> kept{Point_3(1, 1, 1)};
  CHECK_FALSE(reads_cloud("0 0 0\n1 1\n", "xyz", kept, why));
  CHECK(kept.size() == 1);                                  // a failed read leaves the points as they were
}
