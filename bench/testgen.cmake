# The test generator's targets (docs/testgen.md): every objective of the
# 128 x 128 x 1024 big_matrix decided in < 120 s on 2 cores; tests and steps
# against objectives; the whole suite replayed in < 1 s.
if(TARGET cemv_testgen)
  add_executable(bench_testgen ${CMAKE_CURRENT_LIST_DIR}/bench_testgen.cpp)
  target_link_libraries(bench_testgen PRIVATE cemv_testgen cemv_testsupport benchmark::benchmark)
endif()
