// Feature curves in a text file, one curve per line: n x1 y1 z1 ... xn yn zn, or with both
// normals of every vertex, n x1 y1 z1 a1 b1 c1 d1 e1 f1 ... (9 numbers per vertex). The format
// of mesh_with_sharp_features --curves and --curves-out, and of the meshing benchmark's true
// creases.

#ifndef SFE_UTILITIES_FEATURE_CURVE_FILES_H
#define SFE_UTILITIES_FEATURE_CURVE_FILES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sfe_utilities {

/// reads the curves of `path`; throws `std::runtime_error` saying where the file is wrong.
template <typename GeomTraits>
std::vector<CGAL::Feature_polyline<GeomTraits>> read_feature_curves(const std::string& path)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot open curve file " + path);
  std::vector<CGAL::Feature_polyline<GeomTraits>> curves;
  std::string line;
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number) {
    std::istringstream fields(line);
    std::vector<double> v;
    for(double x; fields >> x;)
      v.push_back(x);
    if(v.empty())
      continue;
    const std::size_t n = static_cast<std::size_t>(v[0]), stride = (v.size() == 1 + 9 * n) ? 9 : 3;
    if(n == 0 || v.size() != 1 + stride * n)
      throw std::runtime_error(path + ":" + std::to_string(line_number) + ": expected a count n then 3n or 9n numbers");
    CGAL::Feature_polyline<GeomTraits> c;
    for(const double* p = &v[1]; p < v.data() + v.size(); p += stride) {
      c.points.push_back(Point_3(p[0], p[1], p[2]));
      if(stride == 9)
        c.normals.push_back({{Vector_3(p[3], p[4], p[5]), Vector_3(p[6], p[7], p[8])}});
    }
    curves.push_back(c);
  }
  return curves;
}

/// writes `curves` to `path`, with their normals where every vertex has them; throws
/// `std::runtime_error` if the file cannot be written.
template <typename GeomTraits>
void write_feature_curves(const std::string& path, const std::vector<CGAL::Feature_polyline<GeomTraits>>& curves)
{
  std::ofstream out(path);
  out.precision(17);
  for(const auto& c : curves) {
    out << c.points.size();
    for(std::size_t i = 0; i < c.points.size(); ++i) {
      out << ' ' << c.points[i];
      if(c.normals.size() == c.points.size())
        out << ' ' << c.normals[i][0] << ' ' << c.normals[i][1];
    }
    out << '\n';
  }
  if(!out)
    throw std::runtime_error("cannot write " + path);
}

} // namespace sfe_utilities

#endif // SFE_UTILITIES_FEATURE_CURVE_FILES_H
