# Every example requirement reaches the verdict written in its file.
add_executable(test_check_examples ${CMAKE_CURRENT_LIST_DIR}/test_check_examples.cpp)
target_link_libraries(test_check_examples PRIVATE cemv_checker GTest::gtest_main)
target_compile_definitions(test_check_examples PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_check_examples DISCOVERY_TIMEOUT 60)

# A wrong rule planted in the encoding is caught by the runtime replay.
add_executable(test_check_replay ${CMAKE_CURRENT_LIST_DIR}/test_check_replay.cpp)
target_link_libraries(test_check_replay PRIVATE cemv_checker GTest::gtest_main)
target_compile_definitions(test_check_replay PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_check_replay DISCOVERY_TIMEOUT 60)
