# Mutation operators: every example's mutants are valid single-point edits.
if(TARGET cemv_mutate)
  add_executable(test_mutants ${CMAKE_CURRENT_LIST_DIR}/test_mutants.cpp)
  target_link_libraries(test_mutants PRIVATE cemv_mutate cemv_formats GTest::gtest_main)
  target_compile_definitions(test_mutants PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_mutants)
endif()

# The mutation report: reference objectives and interface-only mutants.
if(TARGET cemv_mutation_report)
  add_executable(test_mutation_report ${CMAKE_CURRENT_LIST_DIR}/test_mutation_report.cpp)
  target_link_libraries(test_mutation_report PRIVATE cemv_mutation_report cemv_formats GTest::gtest_main)
  gtest_discover_tests(test_mutation_report DISCOVERY_TIMEOUT 60)
endif()
