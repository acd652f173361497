# The random matrix / scenario generators of tests/support (tests/support/README.md).
add_executable(test_model_generators ${CMAKE_CURRENT_LIST_DIR}/test_generators.cpp)
# The runtime replays the random scenarios to show they reach every status.
target_link_libraries(test_model_generators PRIVATE cemv_testsupport cemv_formats cemv_runtime GTest::gtest_main)
gtest_discover_tests(test_model_generators DISCOVERY_MODE PRE_TEST)
