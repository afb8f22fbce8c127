# Tests of the feature-protected meshing example (examples/Sharp_feature_extraction/meshing).
# Included from this directory's CMakeLists.txt; uses sfe_add_test() defined there.
# One heavy translation unit (it includes Mesh_3 and Poisson): about 75 s and 3.6 GB to compile.
if(SFE_BUILD_MESHING)
  sfe_add_test(test_meshing_with_features)
  target_include_directories(test_meshing_with_features PRIVATE
    ${PROJECT_SOURCE_DIR}/examples/Sharp_feature_extraction)
endif()
