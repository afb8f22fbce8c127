// libFuzzer target: CGAL::IO::read_point_cloud, the reader of the extract_sharp_features
// program, on arbitrary bytes in the format SFE_FUZZ_FORMAT ("xyz", "ply", "off" or "las"; one
// executable per format, so that each has its own corpus). The program calls the file
// overload, which picks the format from the extension and calls this stream overload.
// Besides the sanitizers, it checks what the reader documents: on success every point is
// finite and the points were appended; on failure the points are unchanged and the reason is
// one non-empty line. A successful read must also survive a round trip through XYZ. For LAS,
// the streaming reader, a few points at a time, must give the same points.
#include "fuzz_check.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/IO/read_point_cloud.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#ifndef SFE_FUZZ_FORMAT
#error "define SFE_FUZZ_FORMAT as \"xyz\", \"ply\", \"off\" or \"las\""
#endif

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size),
                        std::ios::in | std::ios::binary);
  const Point_3 sentinel(0.5, 0.25, 0.125);
  std::vector<Point_3> points{sentinel};
  std::string why;
  if(!CGAL::IO::read_point_cloud(is, SFE_FUZZ_FORMAT, points, &why))
  {
    SFE_FUZZ_CHECK(points.size() == 1 && points[0] == sentinel);
    SFE_FUZZ_CHECK(!why.empty() && why.find('\n') == std::string::npos);
    return 0;
  }
  SFE_FUZZ_CHECK(!points.empty() && points[0] == sentinel);
  std::ostringstream xyz;
  xyz << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(std::size_t i = 1; i < points.size(); ++i)
  {
    const Point_3& p = points[i];
    SFE_FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
    xyz << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  std::istringstream again_stream(xyz.str());
  std::vector<Point_3> again{sentinel};
  SFE_FUZZ_CHECK(CGAL::IO::read_point_cloud(again_stream, "xyz", again, &why));
  SFE_FUZZ_CHECK(again == points);
  if(std::string(SFE_FUZZ_FORMAT) == "las")
  {
    // Small chunks, so that the inputs the fuzzer makes span several.
    constexpr std::size_t chunk_points = 2;
    std::istringstream las(std::string(reinterpret_cast<const char*>(data), size), std::ios::in | std::ios::binary);
    CGAL::IO::LAS_point_reader reader(las);
    std::vector<double> xyz;
    while(reader.read(chunk_points, xyz) == chunk_points)
      ;
    SFE_FUZZ_CHECK(xyz.size() == 3 * (points.size() - 1));
    for(std::size_t i = 1; i < points.size(); ++i)
      SFE_FUZZ_CHECK(points[i] == Point_3(xyz[3 * i - 3], xyz[3 * i - 2], xyz[3 * i - 1]));
  }
  return 0;
}
