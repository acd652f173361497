# Symbolic monitor: each operator on concrete cycles through
# the encoder's Evaluator, and BMC depths through Z3.
if(TARGET cemv_properties)
  add_executable(test_monitor ${CMAKE_CURRENT_LIST_DIR}/test_monitor.cpp)
  target_compile_definitions(test_monitor PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_link_libraries(test_monitor PRIVATE cemv_properties cemv_formats GTest::gtest_main)
  gtest_discover_tests(test_monitor DISCOVERY_MODE PRE_TEST)
endif()

# Independence (docs/properties.md, "The symbolic monitor"): the monitor shares
# no code with the runtime or with the concrete evaluator.
cemv_cli_test(NAME properties_monitor_includes_neither_runtime_nor_evaluator EXIT 1
  COMMAND grep -nE "#include *[<\"](\\.\\./)*(runtime/|properties/evaluator)"
          ${PROJECT_SOURCE_DIR}/properties/monitor.hpp ${PROJECT_SOURCE_DIR}/properties/monitor.cpp)
