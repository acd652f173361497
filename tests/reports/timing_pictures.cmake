# Timing diagrams (SVG) and value change dumps (VCD) of a run (reports/timing_svg.hpp,
# reports/vcd.hpp, docs/reports.md): golden files, and the VCD read back.
add_executable(test_reports_timing_pictures ${CMAKE_CURRENT_LIST_DIR}/test_timing_pictures.cpp)
target_link_libraries(test_reports_timing_pictures PRIVATE cemv_reports cemv_formats cemv_runtime GTest::gtest_main)
target_compile_definitions(test_reports_timing_pictures PRIVATE CEMV_GOLDEN_DIR="${CMAKE_CURRENT_LIST_DIR}/golden"
                           CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_reports_timing_pictures DISCOVERY_MODE PRE_TEST)
