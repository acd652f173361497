# cemv response: exact response times on small matrices, the examples'
# signatures, and the seeded defect at the command line.
if(TARGET cemv_response)
  add_executable(test_response ${CMAKE_CURRENT_LIST_DIR}/test_response.cpp)
  target_link_libraries(test_response PRIVATE cemv_response cemv_testsupport GTest::gtest_main)
  target_compile_definitions(test_response PRIVATE CEMV_BINARY="$<TARGET_FILE:cemv>"
                             CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  add_dependencies(test_response cemv)
  gtest_discover_tests(test_response DISCOVERY_MODE PRE_TEST PROPERTIES TIMEOUT 600)

  add_executable(test_response_format ${CMAKE_CURRENT_LIST_DIR}/test_response_format.cpp)
  target_link_libraries(test_response_format PRIVATE cemv_response GTest::gtest_main)
  target_compile_definitions(test_response_format PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_response_format DISCOVERY_MODE PRE_TEST)
endif()
