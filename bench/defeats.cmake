# cemv defeats's targets (docs/defeats.md): the four examples, every path,
# K = 2, < 30 s in total; big_matrix's SIF groups with K = 1 < 120 s.
if(TARGET cemv_defeats)
  add_executable(bench_defeats ${CMAKE_CURRENT_LIST_DIR}/bench_defeats.cpp)
  target_link_libraries(bench_defeats PRIVATE cemv_defeats cemv_testsupport benchmark::benchmark)
  target_compile_definitions(bench_defeats PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
