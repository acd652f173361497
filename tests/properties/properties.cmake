# The property language: parser (names, errors), concrete evaluator, standard
# property set, and the examples' requirement files (docs/properties.md).
add_executable(test_properties_parser ${CMAKE_CURRENT_LIST_DIR}/test_parser.cpp
                                      ${CMAKE_CURRENT_LIST_DIR}/test_parser_errors.cpp)
target_link_libraries(test_properties_parser PRIVATE cemv_properties GTest::gtest_main)
target_compile_definitions(test_properties_parser PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_properties_parser DISCOVERY_MODE PRE_TEST)

add_executable(test_properties_evaluator ${CMAKE_CURRENT_LIST_DIR}/test_evaluator.cpp)
target_link_libraries(test_properties_evaluator PRIVATE cemv_properties cemv_runtime GTest::gtest_main)
target_compile_definitions(test_properties_evaluator PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_properties_evaluator DISCOVERY_MODE PRE_TEST)

add_executable(test_properties_standard ${CMAKE_CURRENT_LIST_DIR}/test_standard.cpp
                                        ${CMAKE_CURRENT_LIST_DIR}/test_print.cpp)
target_link_libraries(test_properties_standard PRIVATE cemv_properties cemv_runtime cemv_testsupport GTest::gtest_main)
target_compile_definitions(test_properties_standard PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_properties_standard DISCOVERY_MODE PRE_TEST)

# The evaluator streamed cycle by cycle against the evaluator over whole traces.
add_executable(test_properties_stream_evaluator ${CMAKE_CURRENT_LIST_DIR}/test_stream_evaluator.cpp)
target_link_libraries(test_properties_stream_evaluator PRIVATE cemv_properties cemv_runtime cemv_testsupport GTest::gtest_main)
target_compile_definitions(test_properties_stream_evaluator PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_properties_stream_evaluator DISCOVERY_MODE PRE_TEST)

# The examples' requirement files: they parse, every property states its
# expected verdict, and the runtime agrees with those verdicts on every trace
# we can produce (scenarios, random inputs, the seeded defects' witnesses).
add_executable(test_properties_requirements ${CMAKE_CURRENT_LIST_DIR}/test_requirements.cpp)
target_link_libraries(test_properties_requirements PRIVATE cemv_properties cemv_runtime cemv_testsupport GTest::gtest_main)
target_compile_definitions(test_properties_requirements PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_properties_requirements DISCOVERY_MODE PRE_TEST)

# Independence (docs/properties.md, "The concrete evaluator"): the concrete
# evaluator and the symbolic monitor share no code; they meet only in ast.hpp.
cemv_cli_test(NAME properties_evaluator_includes_neither_encoder_nor_monitor EXIT 1
  COMMAND grep -nE "#include *[<\"](\\.\\./)*(encoder/|properties/monitor)"
          ${PROJECT_SOURCE_DIR}/properties/evaluator.hpp ${PROJECT_SOURCE_DIR}/properties/evaluator.cpp
          ${PROJECT_SOURCE_DIR}/properties/evaluator_stream.cpp ${PROJECT_SOURCE_DIR}/properties/evaluator_atoms.hpp)
cemv_cli_test(NAME properties_nothing_else_includes_the_evaluator EXIT 1
  COMMAND grep -rnE --exclude=evaluator.cpp --exclude=evaluator_stream.cpp "#include *[<\"](\\.\\./)*properties/evaluator" ${PROJECT_SOURCE_DIR}/properties)

# The concrete evaluator against the symbolic monitor (once both are in the tree).
if(EXISTS ${PROJECT_SOURCE_DIR}/properties/monitor.cpp)
  add_executable(test_properties_two_implementations ${CMAKE_CURRENT_LIST_DIR}/test_two_implementations.cpp)
  target_link_libraries(test_properties_two_implementations PRIVATE cemv_properties cemv_runtime cemv_encoder
                        cemv_testsupport GTest::gtest_main)
  target_compile_definitions(test_properties_two_implementations PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_properties_two_implementations DISCOVERY_MODE PRE_TEST)
endif()
