# Observable equivalence on the product of two matrices (checker/equivalence.hpp).
if(TARGET cemv_checker AND TARGET cemv_mutate)
  add_executable(test_equivalence ${CMAKE_CURRENT_LIST_DIR}/test_equivalence.cpp)
  target_link_libraries(test_equivalence PRIVATE cemv_checker cemv_mutate GTest::gtest_main)
  target_compile_definitions(test_equivalence PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_equivalence DISCOVERY_TIMEOUT 60)
endif()
