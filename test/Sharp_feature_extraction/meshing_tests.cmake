# Tests of the Mesh_3 readiness of polylines and of the surface reconstruction.
# Included from this directory's CMakeLists.txt; uses sfe_add_test() defined there.

# repair_polylines_for_mesh_3() and find_mesh_3_polyline_problems() (no Mesh_3 inside: quick to compile).
sfe_add_test(test_repair_polylines_for_mesh_3)

# reconstruct_surface_with_sharp_features(): one heavy translation unit (it includes Mesh_3 and
# Poisson), about 75 s and 3.6 GB to compile.
if(SFE_BUILD_MESHING)
  sfe_add_test(test_meshing_with_features)
endif()
