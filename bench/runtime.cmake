# Target (bench/README.md): one scan cycle of the 128 x 128 x 1024 matrix under 20 us,
# no heap allocation inside step().
if(TARGET cemv_runtime)
  add_executable(bench_runtime ${CMAKE_CURRENT_LIST_DIR}/bench_runtime.cpp)
  target_link_libraries(bench_runtime PRIVATE cemv_runtime cemv_testsupport benchmark::benchmark)
endif()
