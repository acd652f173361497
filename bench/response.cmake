# cemv response's targets (docs/response-time.md): every path of the four
# examples < 10 s in total; the 600-cycle and 18,000-cycle delays beside plain
# BMC; every path of the 128 x 128 big_matrix decided in < 120 s.
if(TARGET cemv_response)
  add_executable(bench_response ${CMAKE_CURRENT_LIST_DIR}/bench_response.cpp)
  target_link_libraries(bench_response PRIVATE cemv_response cemv_testsupport benchmark::benchmark)
  target_compile_definitions(bench_response PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
# Not run by make bench: each engine alone on one path's probes (see the file).
if(TARGET cemv_response)
  add_executable(response_engines ${CMAKE_CURRENT_LIST_DIR}/response_engines.cpp)
  target_link_libraries(response_engines PRIVATE cemv_response)
endif()
