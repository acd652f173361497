# Unit tests of the reference runtime (docs/semantics.md).
add_executable(test_runtime_unit
  ${CMAKE_CURRENT_LIST_DIR}/test_runtime_unit.cpp         # the fixed decisions, one by one
  ${CMAKE_CURRENT_LIST_DIR}/test_runtime_unit_random.cpp  # invariants on random matrices
  ${CMAKE_CURRENT_LIST_DIR}/test_runtime_unit_alloc.cpp   # counting operator new
  ${CMAKE_CURRENT_LIST_DIR}/test_runtime_explain.cpp      # why each status field changed; simulation permission
)
target_link_libraries(test_runtime_unit PRIVATE cemv_runtime cemv_testsupport GTest::gtest_main)
gtest_discover_tests(test_runtime_unit DISCOVERY_MODE PRE_TEST)
