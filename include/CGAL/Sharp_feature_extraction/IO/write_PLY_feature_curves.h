// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_PLY_FEATURE_CURVES_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_WRITE_PLY_FEATURE_CURVES_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <limits>
#include <iterator>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// A vertex of the PLY file: a curve vertex (`curve` >= 0) or a point of the cloud (`curve`
/// -1, no normals, the colour of its patch).
struct PLY_feature_vertex
{
  double p[3] = {0, 0, 0}, n1[3] = {0, 0, 0}, n2[3] = {0, 0, 0};
  int corner = 0;
  long long curve = -1, patch = -1;
  std::array<unsigned char, 3> colour = {0, 0, 0};
};

template <typename Vector>
void write_PLY_xyz(const Vector& v, double out[3])
{
  out[0] = CGAL::to_double(v[0]);
  out[1] = CGAL::to_double(v[1]);
  out[2] = CGAL::to_double(v[2]);
}

/// One vertex per distinct curve point (black), and the segments of the curves between them.
template <typename GeomTraits>
void collect_PLY_curves(const Feature_curve_network<GeomTraits>& network, std::vector<PLY_feature_vertex>& vertices,
                        std::vector<std::pair<std::size_t, std::size_t>>& edges)
{
  std::map<std::tuple<double, double, double>, std::size_t> id;
  for(std::size_t c = 0; c < network.polylines.size(); ++c)
  {
    const Feature_polyline<GeomTraits>& polyline = network.polylines[c];
    std::size_t previous = 0;
    for(std::size_t i = 0; i < polyline.points.size(); ++i)
    {
      PLY_feature_vertex v;
      write_PLY_xyz(polyline.points[i], v.p);
      write_PLY_xyz(polyline.normals[i][0], v.n1);
      write_PLY_xyz(polyline.normals[i][1], v.n2);
      const bool at_corner = (i == 0 && polyline.front_corner != Feature_polyline<GeomTraits>::no_corner)
                          || (i + 1 == polyline.points.size() && polyline.back_corner != Feature_polyline<GeomTraits>::no_corner);
      v.corner = at_corner ? 1 : 0;
      v.curve = static_cast<long long>(c);
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
}

/// The file: the vertices, with the patch properties (`patch`, `red`, `green`, `blue`) if
/// `with_patches`, then the edges.
inline bool write_PLY_vertices_and_edges(std::ostream& os, const std::vector<PLY_feature_vertex>& vertices,
                                         const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                                         bool with_patches)
{
  os << "ply\nformat ascii 1.0\ncomment sharp feature curves" << (with_patches ? " and surface patches" : "") << "\n"
     << "element vertex " << vertices.size() << "\n"
     << "property double x\nproperty double y\nproperty double z\n"
     << "property float nx\nproperty float ny\nproperty float nz\n"
     << "property float n2x\nproperty float n2y\nproperty float n2z\n"
     << "property uchar corner\nproperty int curve\n"
     << (with_patches ? "property int patch\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n" : "")
     << "element edge " << edges.size() << "\n"
     << "property int vertex1\nproperty int vertex2\nend_header\n";
  os << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(const PLY_feature_vertex& v : vertices)
  {
    os << v.p[0] << ' ' << v.p[1] << ' ' << v.p[2] << ' ' << float(v.n1[0]) << ' ' << float(v.n1[1]) << ' '
       << float(v.n1[2]) << ' ' << float(v.n2[0]) << ' ' << float(v.n2[1]) << ' ' << float(v.n2[2]) << ' '
       << v.corner << ' ' << v.curve;
    if(with_patches)
      os << ' ' << v.patch << ' ' << int(v.colour[0]) << ' ' << int(v.colour[1]) << ' ' << int(v.colour[2]);
    os << '\n';
  }
  for(const auto& e : edges)
    os << e.first << ' ' << e.second << '\n';
  return bool(os);
}

} // namespace internal
} // namespace Sharp_feature_extraction

namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// The colour of surface patch `patch` in the files and pictures of this package: hues a golden
/// angle apart (so that patches of neighbouring indices differ most), saturated and bright;
/// mid grey for `Surface_patches::unassigned`. It depends on the index only.
/// \returns red, green and blue in [0, 255].
inline std::array<unsigned char, 3> patch_colour(std::size_t patch)
{
  if(patch == (std::numeric_limits<std::size_t>::max)())
    return {128, 128, 128};
  // The fractional part of patch / golden ratio: consecutive hues stay far apart however many.
  const double golden_fraction = 0.6180339887498949;
  const double hue = 6 * std::fmod(double(patch) * golden_fraction, 1.);
  const double saturation = 0.75, value = 0.95;
  const double sector = std::floor(hue), f = hue - sector;
  const double p = value * (1 - saturation), q = value * (1 - saturation * f), t = value * (1 - saturation * (1 - f));
  double rgb[3];
  switch(int(sector) % 6)
  {
  case 0: rgb[0] = value; rgb[1] = t; rgb[2] = p; break;
  case 1: rgb[0] = q; rgb[1] = value; rgb[2] = p; break;
  case 2: rgb[0] = p; rgb[1] = value; rgb[2] = t; break;
  case 3: rgb[0] = p; rgb[1] = q; rgb[2] = value; break;
  case 4: rgb[0] = t; rgb[1] = p; rgb[2] = value; break;
  default: rgb[0] = value; rgb[1] = p; rgb[2] = q; break;
  }
  return {static_cast<unsigned char>(std::lround(255 * rgb[0])), static_cast<unsigned char>(std::lround(255 * rgb[1])),
          static_cast<unsigned char>(std::lround(255 * rgb[2]))};
}


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
  std::vector<Sharp_feature_extraction::internal::PLY_feature_vertex> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  Sharp_feature_extraction::internal::collect_PLY_curves(network, vertices, edges);
  return Sharp_feature_extraction::internal::write_PLY_vertices_and_edges(os, vertices, edges, false);
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, to the file `filename` (`false` also if it cannot be opened).
template <typename GeomTraits>
bool write_PLY_feature_curves(const std::string& filename, const Feature_curve_network<GeomTraits>& network)
{
  std::ofstream os(filename);
  return os && write_PLY_feature_curves(os, network);
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Writes the curves and the points coloured by surface patch in one ASCII PLY: the vertices
/// of the curves as above, then every point of `points` in input order; every vertex has, in
/// addition, the properties `patch` (the point's patch, -1 for none and for curve vertices) and
/// `red green blue` (`patch_colour()` of the patch for a point, black for a curve vertex),
/// which MeshLab and CloudCompare show as colours. Points have `curve` -1 and zero normals
/// (the points carry none).
/// \tparam PointRange a model of `ConstRange` whose value type is the key of `point_map`.
/// \param os the output stream.
/// \param network the curves and corners.
/// \param points the points that were segmented.
/// \param patches their patches: `segment_into_patches()` on `points` (one label per point).
/// \param np optional named parameters among the ones listed below.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `GeomTraits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns `true` on success, `false` if the stream failed.
/// \throws std::invalid_argument if `patches` does not hold one label per point.
template <typename GeomTraits, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
bool write_PLY_feature_curves(std::ostream& os, const Feature_curve_network<GeomTraits>& network,
                              const PointRange& points, const Surface_patches<GeomTraits>& patches,
                              const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  if(std::size_t(std::distance(points.begin(), points.end())) != patches.labels.size())
    throw std::invalid_argument("write_PLY_feature_curves: " + std::to_string(patches.labels.size())
                                + " patch labels for " + std::to_string(std::distance(points.begin(), points.end()))
                                + " points");
  std::vector<Sharp_feature_extraction::internal::PLY_feature_vertex> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  Sharp_feature_extraction::internal::collect_PLY_curves(network, vertices, edges);
  std::size_t i = 0;
  for(const auto& item : points)
  {
    Sharp_feature_extraction::internal::PLY_feature_vertex v;
    Sharp_feature_extraction::internal::write_PLY_xyz(get(point_map, item), v.p);
    const std::size_t label = patches.labels[i++];
    v.patch = label == Surface_patches<GeomTraits>::unassigned ? -1 : static_cast<long long>(label);
    v.colour = patch_colour(label);
    vertices.push_back(v);
  }
  return Sharp_feature_extraction::internal::write_PLY_vertices_and_edges(os, vertices, edges, true);
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, to the file `filename` (`false` also if it cannot be opened).
template <typename GeomTraits, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
bool write_PLY_feature_curves(const std::string& filename, const Feature_curve_network<GeomTraits>& network,
                              const PointRange& points, const Surface_patches<GeomTraits>& patches,
                              const NamedParameters& np = parameters::default_values())
{
  std::ofstream os(filename);
  return os && write_PLY_feature_curves(os, network, points, patches, np);
}

} // namespace IO
} // namespace CGAL

#endif
