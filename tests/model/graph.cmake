# Dependency graph (model/graph.cpp): evaluation order, cycles, cone of influence, DOT.
add_executable(test_model_graph ${CMAKE_CURRENT_LIST_DIR}/test_graph.cpp)
target_include_directories(test_model_graph PRIVATE ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(test_model_graph PRIVATE cemv_model GTest::gtest_main)
gtest_discover_tests(test_model_graph DISCOVERY_MODE PRE_TEST)
