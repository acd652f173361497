add_executable(test_model_io ${CMAKE_CURRENT_LIST_DIR}/test_io.cpp)
target_link_libraries(test_model_io PRIVATE cemv_model GTest::gtest_main)
gtest_discover_tests(test_model_io DISCOVERY_MODE PRE_TEST)
