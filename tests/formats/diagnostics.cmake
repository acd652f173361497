# The helpers every format shares, with one behaviour (docs/scenario.md,
# docs/format.md): typo hints, quoting, the scenario's matrix key, refusing an
# invalid matrix, the expectation loop.
add_executable(test_formats_diagnostics ${CMAKE_CURRENT_LIST_DIR}/test_diagnostics.cpp)
target_link_libraries(test_formats_diagnostics PRIVATE cemv_formats GTest::gtest_main)
target_compile_definitions(test_formats_diagnostics PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_formats_diagnostics DISCOVERY_MODE PRE_TEST)
