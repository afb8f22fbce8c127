// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_READ_POLYLINES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_READ_POLYLINES_H

#include <algorithm>
#include <cmath>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// Reads polylines written in Mesh_3's text format (one polyline per line, `n x1 y1 z1 ... xn yn zn`;
/// blank lines and lines starting with `#` are skipped).
/// \tparam Point_3 a point type constructible from three doubles.
/// \param is the input stream.
/// \param polylines receives the polylines, appended in the order of the lines.
/// \returns `false` (and leaves `polylines` with what was read before) on a malformed line:
///   a count that does not match the coordinates, or a non-finite coordinate.
template <typename Point_3>
bool read_polylines(std::istream& is, std::vector<std::vector<Point_3>>& polylines)
{
  std::string line;
  while(std::getline(is, line))
  {
    std::istringstream row(line);
    std::size_t n;
    if(!(row >> n))
    {
      if(line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t\r")] == '#')
        continue;
      return false;
    }
    // A point takes at least 6 characters ("0 0 0 "): a larger count is malformed, and must
    // not make us reserve room for it.
    const std::size_t shortest_point_text = 6;
    std::vector<Point_3> polyline;
    polyline.reserve(std::min(n, line.size() / shortest_point_text + 1));
    for(std::size_t i = 0; i < n; ++i)
    {
      double x, y, z;
      if(!(row >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        return false;
      polyline.emplace_back(x, y, z);
    }
    std::string rest;
    if(row >> rest)
      return false;
    polylines.push_back(std::move(polyline));
  }
  return !is.bad();
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, from the file `filename`; `false` if it cannot be opened.
template <typename Point_3>
bool read_polylines(const std::string& filename, std::vector<std::vector<Point_3>>& polylines)
{
  std::ifstream is(filename);
  return is && read_polylines(is, polylines);
}

} // namespace IO
} // namespace CGAL

#endif
