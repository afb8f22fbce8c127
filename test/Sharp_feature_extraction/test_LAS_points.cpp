// LAS: write_LAS_points then LAS_point_reader give back the positions (within half a scale
// step) for every version 1.2 to 1.4 and point format 0 to 10, with extra bytes and variable
// length records; chunked reads, seek, the read_point_cloud entry (.las); and every kind of bad
// file rejected with a one-line LAS_error: not LAS, unsupported version, LAZ, a format missing
// from the version, a short record, an inconsistent header, zero scale, truncation.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/IO/read_LAS_points.h>
#include <CGAL/Sharp_feature_extraction/IO/read_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/IO/write_LAS_points.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace las_test {

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;
namespace L = CGAL::Sharp_feature_extraction::internal::LAS_layout;

// A few points with coordinates of georeferenced size (hundreds of kilometres) and sub-metre detail.
std::vector<Point_3> sample_points()
{
  std::vector<Point_3> points;
  for(int i = 0; i < 25; ++i)
    points.emplace_back(512000.25 + 3.5 * i, 5400000.5 - 1.25 * i * i, 120.0 + std::sin(double(i)));
  return points;
}

std::string las_bytes(const std::vector<Point_3>& points, const CGAL::IO::LAS_write_options& options = {})
{
  std::ostringstream os(std::ios::out | std::ios::binary);
  REQUIRE(CGAL::IO::write_LAS_points(os, points, options));
  return os.str();
}

std::vector<double> read_all(const std::string& bytes, std::size_t chunk)
{
  std::istringstream is(bytes, std::ios::in | std::ios::binary);
  CGAL::IO::LAS_point_reader reader(is);
  std::vector<double> xyz;
  while(reader.read(chunk, xyz) == chunk)
    ;
  return xyz;
}

// The writer's quantisation: half a step of 2^-30 of the half extent, here about 1e-6 m.
double quantisation(const std::vector<Point_3>& points)
{
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const Point_3& p : points)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  const double half_extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / 2;
  const double integer_half_range = 1073741824.0; // the writer's (2^30)
  return half_extent / integer_half_range;
}

std::string message_of(const std::string& bytes)
{
  std::istringstream is(bytes, std::ios::in | std::ios::binary);
  try
  {
    CGAL::IO::LAS_point_reader reader(is);
    std::vector<double> xyz;
    while(reader.read(7, xyz) > 0)
      ;
  }
  catch(const CGAL::IO::LAS_error& e)
  {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The test cases are in the namespace too: the sanitizer build compiles every test file as one
// translation unit (test_covering), where other files name their own Point_3.

TEST_CASE("LAS 1.2 to 1.4, point formats 0 to 10: the positions come back within half a scale step", "[io][las]")
{
  const std::vector<Point_3> points = sample_points();
  const double tolerance = quantisation(points) / 2 * (1 + 1e-9);
  for(unsigned format = 0; format <= 10; ++format)
    for(unsigned minor = L::first_minor_version[format]; minor <= 4; ++minor)
    {
      CAPTURE(format, minor);
      CGAL::IO::LAS_write_options options;
      options.version_minor = minor;
      options.point_format = format;
      options.extra_bytes = format % 3 == 0 ? 5 : 0; // some formats with extra bytes
      options.vlr_bytes = format % 2 == 0 ? 54 + 17 : 0; // some with a variable length record
      const std::string bytes = las_bytes(points, options);
      std::istringstream is(bytes, std::ios::in | std::ios::binary);
      CGAL::IO::LAS_point_reader reader(is);
      CHECK(reader.header().version_minor == minor);
      CHECK(reader.header().point_format == format);
      CHECK(reader.header().record_length == L::record_size[format] + options.extra_bytes);
      CHECK(reader.header().point_count == points.size());
      std::vector<double> xyz;
      CHECK(reader.read(1000, xyz) == points.size());
      CHECK(reader.read(1000, xyz) == 0);
      REQUIRE(xyz.size() == 3 * points.size());
      for(std::size_t i = 0; i < points.size(); ++i)
        for(int a = 0; a < 3; ++a)
          CHECK(std::abs(xyz[3 * i + a] - points[i][a]) <= tolerance);
    }
}

TEST_CASE("LAS points read in chunks of any size are the same, and seek moves to any point", "[io][las]")
{
  const std::string bytes = las_bytes(sample_points());
  const std::vector<double> whole = read_all(bytes, 1000);
  CHECK(read_all(bytes, 1) == whole);
  CHECK(read_all(bytes, 7) == whole);
  std::istringstream is(bytes, std::ios::in | std::ios::binary);
  CGAL::IO::LAS_point_reader reader(is);
  reader.seek(20);
  std::vector<double> tail;
  CHECK(reader.read(100, tail) == 5);
  CHECK(tail == std::vector<double>(whole.begin() + 3 * 20, whole.end()));
  CHECK_THROWS_AS(reader.seek(26), CGAL::IO::LAS_error);
}

TEST_CASE("read_point_cloud reads .las files", "[io][las]")
{
  const std::vector<Point_3> points = sample_points();
  const std::string filename = "test_LAS_points_cloud.las";
  REQUIRE(CGAL::IO::write_LAS_points(filename, points));
  std::vector<Point_3> read{Point_3(1, 2, 3)};
  std::string why;
  REQUIRE(CGAL::IO::read_point_cloud(filename, read, &why));
  std::remove(filename.c_str());
  REQUIRE(read.size() == points.size() + 1);
  CHECK(std::abs(read.back().x() - points.back().x()) <= quantisation(points));
}

TEST_CASE("Bad LAS files are rejected with a one-line LAS_error saying why", "[io][las]")
{
  const std::vector<Point_3> points = sample_points();
  CGAL::IO::LAS_write_options v14;
  v14.version_minor = 4;
  v14.point_format = 6;
  const std::string good = las_bytes(points), good14 = las_bytes(points, v14);
  REQUIRE(message_of(good).empty());
  REQUIRE(message_of(good14).empty());
  auto patched = [](std::string bytes, std::size_t at, unsigned char value) {
    bytes[at] = char(value);
    return bytes;
  };
  CHECK(mentions(message_of(""), "ends within the LAS header"));
  CHECK(mentions(message_of("ply\nformat ascii 1.0\n" + std::string(300, ' ')), "not a LAS file"));
  CHECK(mentions(message_of(patched(good, L::version_minor_at, 1)), "LAS version 1.1 is not supported"));
  CHECK(mentions(message_of(patched(good, L::version_minor_at, 5)), "LAS version 1.5 is not supported"));
  CHECK(mentions(message_of(patched(good, L::version_major_at, 2)), "LAS version 2.2"));
  CHECK(mentions(message_of(patched(good, L::point_format_at, 0x80 | 3)), "compressed LAS (LAZ)"));
  CHECK(mentions(message_of(patched(good, L::point_format_at, 11)), "unknown LAS point format 11"));
  CHECK(mentions(message_of(patched(good, L::point_format_at, 6)), "point format 6 does not exist in version 1.2"));
  CHECK(mentions(message_of(patched(good, L::record_length_at, 19)), "record length 19 is shorter"));
  CHECK(mentions(message_of(patched(good, L::header_size_at, 200)), "header size 200 is smaller"));
  CHECK(mentions(message_of(patched(good, L::offset_to_points_at, 100)), "within the header"));
  CHECK(mentions(message_of(patched(good14, L::header_size_at + 1, 0)), "smaller than the 375 bytes"));
  std::string zero_scale = good;
  std::fill(zero_scale.begin() + L::scale_at + 8, zero_scale.begin() + L::scale_at + 16, '\0');
  CHECK(mentions(message_of(zero_scale), "y scale factor is zero"));
  CHECK(mentions(message_of(good.substr(0, good.size() - 1)), "ends after 24 of the 25 points"));
  CHECK(mentions(message_of(good14.substr(0, 300)), "ends within the LAS header"));
  CHECK(mentions(message_of(patched(good, L::offset_to_points_at + 1, 0xFF)), "ends before its point records"));
  std::vector<Point_3> kept{Point_3(1, 1, 1)};
  std::istringstream truncated(good.substr(0, good.size() - 1), std::ios::in | std::ios::binary);
  std::string why;
  CHECK_FALSE(CGAL::IO::read_point_cloud(truncated, "las", kept, &why));
  CHECK(kept.size() == 1); // a failed read leaves the points as they were
  CHECK(why.find('\n') == std::string::npos);
}

} // namespace las_test
