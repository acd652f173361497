# Target (bench/README.md): full encoding of the 128 x 128 x 1024 matrix under 2 s, a
# single-effect cone-of-influence slice under 50 ms.
if(TARGET cemv_encoder)
  add_executable(bench_encoder ${CMAKE_CURRENT_LIST_DIR}/bench_encoder.cpp)
  target_link_libraries(bench_encoder PRIVATE cemv_encoder cemv_testsupport benchmark::benchmark)
endif()
