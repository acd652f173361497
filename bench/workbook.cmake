# Target (bench/README.md): a vendor C&E workbook of 400 rows x 100 columns
# with 3,000 merged ranges is read in under 2 s (XLSX and ODS).
add_executable(bench_workbook ${CMAKE_CURRENT_LIST_DIR}/bench_workbook.cpp)
target_link_libraries(bench_workbook PRIVATE cemv_sheets benchmark::benchmark)
