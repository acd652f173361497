# Plausibility checks (model/validate.cpp): one trigger and one near miss per rule.
add_executable(test_model_validate ${CMAKE_CURRENT_LIST_DIR}/test_validate.cpp)
target_include_directories(test_model_validate PRIVATE ${CMAKE_CURRENT_LIST_DIR})
target_compile_definitions(test_model_validate PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(test_model_validate PRIVATE cemv_model GTest::gtest_main)
gtest_discover_tests(test_model_validate DISCOVERY_MODE PRE_TEST)
