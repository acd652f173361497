# Target (bench/README.md): loading + validating a generated 128 x 128 matrix with
# 1024 intersections takes under 50 ms.
add_executable(bench_model ${CMAKE_CURRENT_LIST_DIR}/bench_model.cpp)
target_link_libraries(bench_model PRIVATE cemv_formats cemv_testsupport benchmark::benchmark)
