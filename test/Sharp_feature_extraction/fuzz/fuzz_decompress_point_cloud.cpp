// libFuzzer target: CGAL::decompress_point_cloud (the decoder of compress_point_cloud, with
// OpenJPEG underneath) on arbitrary bytes. Besides the sanitizers, it checks what the decoder
// documents: a bitstream is either refused with std::invalid_argument or decoded into finite
// points; nothing else escapes.
#include "fuzz_check.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/decompress_point_cloud.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::vector<unsigned char> bytes(data, data + size);
  std::vector<Point_3> points;
  try
  {
    CGAL::decompress_point_cloud(bytes, points);
  }
  catch(const std::invalid_argument&)
  {
    return 0;
  }
  for(const Point_3& p : points)
    SFE_FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
  return 0;
}
