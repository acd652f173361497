# Dependency graph (model/graph.cpp): evaluation order, cycles, cone of influence, DOT.
add_executable(test_model_graph ${CMAKE_CURRENT_LIST_DIR}/test_graph.cpp)
target_include_directories(test_model_graph PRIVATE ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(test_model_graph PRIVATE cemv_model cemv_reports GTest::gtest_main)
gtest_discover_tests(test_model_graph DISCOVERY_MODE PRE_TEST)

# `cemv graph`: DOT (red edge for the reference that closes a cycle) or the
# evaluation order; exit 2 for bad input or an unwritable output file.
set(GC ${CMAKE_CURRENT_LIST_DIR}/validate_cases)
cemv_cli_test(NAME cli_graph_dot EXIT 0
  MATCH "\"effect\\[1\\]\" -> \"cause\\[1\\]\" .label=\"Effect\\[1\\] as bypass_tag.n\\(previous cycle\\)\", style=dashed, color=red"
  COMMAND $<TARGET_FILE:cemv> graph ${GC}/cycle.json)
cemv_cli_test(NAME cli_graph_order EXIT 0
  MATCH "^2 cause\\[1\\] PSH_1  \\(reads effect\\[1\\] from the previous cycle\\)$"
  COMMAND $<TARGET_FILE:cemv> graph --order ${GC}/cycle.json)
cemv_cli_test(NAME cli_graph_output_file EXIT 0
  COMMAND $<TARGET_FILE:cemv> graph ${GC}/cycle.json -o ${CMAKE_CURRENT_BINARY_DIR}/cycle.dot)
cemv_cli_test(NAME cli_graph_unwritable_exit_2 EXIT 2
  MATCH "cannot write"
  COMMAND $<TARGET_FILE:cemv> graph ${GC}/cycle.json -o /nonexistent-dir/cycle.dot)
cemv_cli_test(NAME cli_graph_malformed_exit_2 EXIT 2
  COMMAND $<TARGET_FILE:cemv> graph ${GC}/malformed.json)

# Properties on seeded random matrices from tests/support.
if(TARGET cemv_testsupport)
  add_executable(test_model_graph_random ${CMAKE_CURRENT_LIST_DIR}/test_graph_random.cpp)
  target_link_libraries(test_model_graph_random PRIVATE cemv_testsupport cemv_model cemv_reports GTest::gtest_main)
  gtest_discover_tests(test_model_graph_random DISCOVERY_MODE PRE_TEST)
endif()
