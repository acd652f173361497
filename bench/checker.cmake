# The checker's targets (docs/performance.md): each example requirement < 1 s,
# requirement 4 (18,000-cycle timer) < 5 s beside plain BMC, the standard set of
# the 128 x 128 x 1024 matrix decided in < 60 s, scaling from 8 x 8.
if(TARGET cemv_checker)
  add_executable(bench_checker ${CMAKE_CURRENT_LIST_DIR}/bench_checker.cpp)
  target_link_libraries(bench_checker PRIVATE cemv_checker cemv_testsupport benchmark::benchmark)
  target_compile_definitions(bench_checker PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
