# Every load issue placed at FILE:LINE:COL (formats/diagnostics.hpp): the
# compiler-style message, JSON path positions, the guarded parser for
# scenarios, element positions of validation findings, the wrong-matrix hint.
add_executable(test_formats_positions ${CMAKE_CURRENT_LIST_DIR}/test_positions.cpp)
target_link_libraries(test_formats_positions PRIVATE cemv_formats GTest::gtest_main)
target_compile_definitions(test_formats_positions PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_formats_positions DISCOVERY_MODE PRE_TEST)
