# cemv defeats: hand-made matrices whose minimal defeat sets are known.
if(TARGET cemv_defeats)
  add_executable(test_defeats ${CMAKE_CURRENT_LIST_DIR}/test_defeats.cpp)
  target_link_libraries(test_defeats PRIVATE cemv_defeats cemv_testsupport GTest::gtest_main)
  target_compile_definitions(test_defeats PRIVATE CEMV_BINARY="$<TARGET_FILE:cemv>" CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  add_dependencies(test_defeats cemv)
  gtest_discover_tests(test_defeats DISCOVERY_MODE PRE_TEST PROPERTIES TIMEOUT 600)
endif()
