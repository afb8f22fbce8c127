# The meshing benchmark's measuring program (no Mesh_3: compiles in well under a minute).
# Included from benchmark/Sharp_feature_extraction/CMakeLists.txt; scripts/bench_meshing.sh runs it
# together with mesh_with_sharp_features (examples/).
add_executable(measure_mesh_against_truth
  ${CMAKE_CURRENT_LIST_DIR}/measure_mesh_against_truth.cpp)
target_link_libraries(measure_mesh_against_truth PRIVATE CGAL::Sharp_feature_extraction ZLIB::ZLIB)
target_include_directories(measure_mesh_against_truth PRIVATE ${CMAKE_CURRENT_LIST_DIR} ${SFE_UTILITIES_DIR})
