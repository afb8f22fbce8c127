// Runs CGAL::extract_sharp_features() with its defaults and writes what each stage produced, for
// the manual's pipeline figure: PREFIX_candidates.xyz, PREFIX_projected.xyz, PREFIX_smoothed.xyz
// (points, one per line) and PREFIX_final.polylines.txt (the curves, Mesh_3's polyline format).
//
//   dump_stage_points CLOUD.xyz PREFIX

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Sharp_feature_extraction.h>

#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

bool write_points(const std::string& filename, const std::vector<K::Point_3>& points)
{
  std::ofstream os(filename);
  os.precision(std::numeric_limits<double>::max_digits10);
  for(const K::Point_3& p : points)
    os << p << '\n';
  return bool(os);
}

std::vector<K::Point_3> edge_positions(const CGAL::Feature_point_set<K>& features)
{
  std::vector<K::Point_3> out;
  for(const CGAL::Edge_point<K>& e : features.edge_points)
    out.push_back(e.point);
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<K::Point_3> points;
  if(argc != 3 || !CGAL::IO::read_points(argv[1], std::back_inserter(points)))
  {
    std::cerr << "usage: dump_stage_points CLOUD.xyz PREFIX" << std::endl;
    return 1;
  }
  const std::string prefix = argv[2];
  CGAL::Sharp_features<K> result;
  CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, result);

  std::vector<K::Point_3> candidates;
  for(std::size_t i : result.candidates.indices)
    candidates.push_back(points[i]);
  std::vector<std::vector<K::Point_3>> curves;
  for(const CGAL::Feature_polyline<K>& p : result.network.polylines)
    curves.push_back(p.points);

  const bool written = write_points(prefix + "_candidates.xyz", candidates)
                    && write_points(prefix + "_projected.xyz", edge_positions(result.projected))
                    && write_points(prefix + "_smoothed.xyz", edge_positions(result.smoothed))
                    && CGAL::IO::write_polylines(prefix + "_final.polylines.txt", curves);
  std::cout << points.size() << " points, " << candidates.size() << " candidates, "
            << result.projected.edge_points.size() << " edge points, " << curves.size() << " curves, "
            << result.network.corners.size() << " corners" << std::endl;
  return written ? 0 : 1;
}
