// Test helper: two curve networks are the same to the last bit (test_kernels_and_determinism,
// test_tiled_extraction).

#ifndef SFE_TEST_IDENTICAL_NETWORKS_H
#define SFE_TEST_IDENTICAL_NETWORKS_H

#include "analytic_shapes.h"

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>

#include <catch2/catch.hpp>

namespace sfe_test {

/// Bit-identical curve networks, possibly of different kernels.
template <typename K1, typename K2>
void check_identical(const CGAL::Feature_curve_network<K1>& a, const CGAL::Feature_curve_network<K2>& b)
{
  REQUIRE(a.polylines.size() == b.polylines.size());
  REQUIRE(a.corners.size() == b.corners.size());
  for(std::size_t c = 0; c < a.polylines.size(); ++c)
  {
    const auto& p = a.polylines[c];
    const auto& q = b.polylines[c];
    REQUIRE(p.points.size() == q.points.size());
    CHECK(p.front_corner == q.front_corner);
    CHECK(p.back_corner == q.back_corner);
    bool same = true;
    for(std::size_t i = 0; i < p.points.size(); ++i)
    {
      for(int k = 0; k < 3; ++k)
        same = same && CGAL::to_double(p.points[i][k]) == CGAL::to_double(q.points[i][k])
                    && CGAL::to_double(p.normals[i][0][k]) == CGAL::to_double(q.normals[i][0][k])
                    && CGAL::to_double(p.normals[i][1][k]) == CGAL::to_double(q.normals[i][1][k]);
    }
    INFO("curve " << c);
    CHECK(same);
  }
  for(std::size_t k = 0; k < a.corners.size(); ++k)
  {
    CHECK(to_vec(a.corners[k].point).x == to_vec(b.corners[k].point).x);
    CHECK(to_vec(a.corners[k].point).y == to_vec(b.corners[k].point).y);
    CHECK(to_vec(a.corners[k].point).z == to_vec(b.corners[k].point).z);
    CHECK(a.corners[k].incident_polylines == b.corners[k].incident_polylines);
  }
}

} // namespace sfe_test

#endif
