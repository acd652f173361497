# Mutation operators: every example's mutants are valid single-point edits.
if(TARGET cemv_mutate)
  add_executable(test_mutants ${CMAKE_CURRENT_LIST_DIR}/test_mutants.cpp)
  target_link_libraries(test_mutants PRIVATE cemv_mutate cemv_formats GTest::gtest_main)
  target_compile_definitions(test_mutants PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_mutants)
endif()
