# The RFC 4180 tokenizer and the record layout cemv-csv/1 (6.6, docs/csv.md),
# read through import_csv as users read them (sheets/csv.hpp); the grid is
# tests/sheets/csv.cmake.
add_executable(test_formats_csv ${CMAKE_CURRENT_LIST_DIR}/test_csv.cpp)
target_link_libraries(test_formats_csv PRIVATE cemv_formats cemv_sheets GTest::gtest_main)
target_compile_definitions(test_formats_csv PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_formats_csv DISCOVERY_MODE PRE_TEST)
