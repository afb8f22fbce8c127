// The shortest complete use of the package: points in, Mesh_3-ready polylines out.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main(int argc, char** argv)
{
  std::vector<K::Point_3> points;
  if(argc < 2 || !CGAL::IO::read_points(argv[1], std::back_inserter(points)))
  {
    std::cerr << "usage: minimal_example POINTS.xyz (a readable point file)" << std::endl;
    return 1;
  }
  std::vector<std::vector<K::Point_3>> polylines; // goes straight into Mesh_3's add_features()
  CGAL::extract_sharp_features<CGAL::Parallel_if_available_tag>(points, std::back_inserter(polylines));
  std::cout << polylines.size() << " feature curves" << std::endl;
  return CGAL::IO::write_polylines(std::cout, polylines) ? 0 : 1;
}
