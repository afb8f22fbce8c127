// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_POLYLINES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_POLYLINES_H

#include <CGAL/number_utils.h>

#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <string>

namespace CGAL {
namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// Writes polylines in Mesh_3's text format: one polyline per line, `n x1 y1 z1 ... xn yn zn`,
/// with enough digits that reading them back gives the same doubles (so shared corners and
/// closed loops stay exact).
/// \tparam PolylineRange a range of ranges of points (e.g. `std::vector<std::vector<Point_3>>`).
///   The points need `x()`, `y()` and `z()` to which `CGAL::to_double()` applies.
/// \param os the output stream.
/// \param polylines the polylines, written in their order.
/// \returns `true` on success, `false` if the stream failed.
template <typename PolylineRange>
bool write_polylines(std::ostream& os, const PolylineRange& polylines)
{
  os << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(const auto& polyline : polylines)
  {
    os << polyline.size();
    for(const auto& p : polyline)
      os << ' ' << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z());
    os << '\n';
  }
  return bool(os);
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, to the file `filename` (`false` also if it cannot be opened).
template <typename PolylineRange>
bool write_polylines(const std::string& filename, const PolylineRange& polylines)
{
  std::ofstream os(filename);
  return os && write_polylines(os, polylines);
}

} // namespace IO
} // namespace CGAL

#endif
