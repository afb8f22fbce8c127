// libFuzzer target: CGAL::IO::read_polylines on arbitrary bytes. Besides the sanitizers, it
// checks what the reader documents: every point read is finite, and writing what was read and
// reading it back gives the same doubles.
#include "fuzz_check.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/IO/read_polylines.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::vector<Point_3>> polylines;
  CGAL::IO::read_polylines(is, polylines);
  for(const auto& polyline : polylines)
    for(const Point_3& p : polyline)
      SFE_FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));

  std::stringstream written;
  SFE_FUZZ_CHECK(CGAL::IO::write_polylines(written, polylines));
  std::vector<std::vector<Point_3>> again;
  SFE_FUZZ_CHECK(CGAL::IO::read_polylines(written, again));
  SFE_FUZZ_CHECK(again == polylines);
  return 0;
}
