add_executable(test_runtime_unit ${CMAKE_CURRENT_LIST_DIR}/test_runtime_unit.cpp
                                 ${CMAKE_CURRENT_LIST_DIR}/test_runtime_unit_alloc.cpp)
target_link_libraries(test_runtime_unit PRIVATE cemv_runtime GTest::gtest_main)
gtest_discover_tests(test_runtime_unit DISCOVERY_MODE PRE_TEST)
