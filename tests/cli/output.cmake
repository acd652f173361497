# The CLI's one output path (cli/output.hpp): checked writes, closed pipes,
# atomic replacement, destinations checked before the work.
add_executable(test_cli_output ${CMAKE_CURRENT_LIST_DIR}/test_output.cpp)
target_link_libraries(test_cli_output PRIVATE cemv_output GTest::gtest_main)
gtest_discover_tests(test_cli_output DISCOVERY_MODE PRE_TEST)
