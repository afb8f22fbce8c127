// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_PLY_FEATURE_CURVES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_PLY_FEATURE_CURVES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/number_utils.h>

#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// Writes a curve network as an ASCII PLY that MeshLab and CloudCompare open: one vertex per
/// distinct curve point with properties `x y z`, `nx ny nz` (first surface normal),
/// `n2x n2y n2z` (second surface normal), `corner` (1 at corners) and `curve` (index of a curve
/// through it), and one `edge` element (`vertex1 vertex2`) per polyline segment.
/// Shared corner points and the closing point of loops are written once.
/// \tparam GeomTraits the traits of the network (see `SharpFeatureExtractionTraits`).
/// \param os the output stream.
/// \param network the curves and corners, for instance `Sharp_features::network`.
/// \returns `true` on success, `false` if the stream failed.
template <typename GeomTraits>
bool write_PLY_feature_curves(std::ostream& os, const Feature_curve_network<GeomTraits>& network)
{
  struct Vertex { double p[3], n1[3], n2[3]; int corner; std::size_t curve; };
  std::vector<Vertex> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::map<std::tuple<double, double, double>, std::size_t> id;
  auto xyz = [](const auto& v, double out[3]) {
    out[0] = CGAL::to_double(v[0]); out[1] = CGAL::to_double(v[1]); out[2] = CGAL::to_double(v[2]);
  };
  for(std::size_t c = 0; c < network.polylines.size(); ++c)
  {
    const Feature_polyline<GeomTraits>& polyline = network.polylines[c];
    std::size_t previous = 0;
    for(std::size_t i = 0; i < polyline.points.size(); ++i)
    {
      Vertex v;
      xyz(polyline.points[i], v.p);
      xyz(polyline.normals[i][0], v.n1);
      xyz(polyline.normals[i][1], v.n2);
      const bool at_corner = (i == 0 && polyline.front_corner != Feature_polyline<GeomTraits>::no_corner)
                          || (i + 1 == polyline.points.size() && polyline.back_corner != Feature_polyline<GeomTraits>::no_corner);
      v.corner = at_corner ? 1 : 0;
      v.curve = c;
      const auto key = std::make_tuple(v.p[0], v.p[1], v.p[2]);
      auto found = id.find(key);
      std::size_t index;
      if(found == id.end())
      {
        index = vertices.size();
        id.emplace(key, index);
        vertices.push_back(v);
      }
      else
      {
        index = found->second;
        vertices[index].corner |= v.corner;
      }
      if(i > 0 && index != previous)
        edges.emplace_back(previous, index);
      previous = index;
    }
  }
  os << "ply\nformat ascii 1.0\ncomment sharp feature curves\n"
     << "element vertex " << vertices.size() << "\n"
     << "property double x\nproperty double y\nproperty double z\n"
     << "property float nx\nproperty float ny\nproperty float nz\n"
     << "property float n2x\nproperty float n2y\nproperty float n2z\n"
     << "property uchar corner\nproperty int curve\n"
     << "element edge " << edges.size() << "\n"
     << "property int vertex1\nproperty int vertex2\nend_header\n";
  os << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(const Vertex& v : vertices)
    os << v.p[0] << ' ' << v.p[1] << ' ' << v.p[2] << ' ' << float(v.n1[0]) << ' ' << float(v.n1[1]) << ' '
       << float(v.n1[2]) << ' ' << float(v.n2[0]) << ' ' << float(v.n2[1]) << ' ' << float(v.n2[2]) << ' '
       << v.corner << ' ' << v.curve << '\n';
  for(const auto& e : edges)
    os << e.first << ' ' << e.second << '\n';
  return bool(os);
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, to the file `filename` (`false` also if it cannot be opened).
template <typename GeomTraits>
bool write_PLY_feature_curves(const std::string& filename, const Feature_curve_network<GeomTraits>& network)
{
  std::ofstream os(filename);
  return os && write_PLY_feature_curves(os, network);
}

} // namespace IO
} // namespace CGAL

#endif
