# Target (bench/README.md): `cemv diff` of two generated 128 x 128 matrices that
# differ in one intersection, structural and semantic comparison, under 10 s.
if(TARGET cemv_diff)
  add_executable(bench_diff ${CMAKE_CURRENT_LIST_DIR}/bench_diff.cpp)
  target_link_libraries(bench_diff PRIVATE cemv_diff cemv_testsupport benchmark::benchmark)
endif()
