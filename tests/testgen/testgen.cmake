if(TARGET cemv_testgen)
  add_executable(test_testgen ${CMAKE_CURRENT_LIST_DIR}/test_testgen.cpp)
  target_link_libraries(test_testgen PRIVATE cemv_testgen cemv_testsupport GTest::gtest_main)
  target_compile_definitions(test_testgen PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_testgen DISCOVERY_TIMEOUT 60)
  add_executable(test_field ${CMAKE_CURRENT_LIST_DIR}/test_field.cpp)
  target_link_libraries(test_field PRIVATE cemv_testgen cemv_testsupport GTest::gtest_main)
  target_compile_definitions(test_field PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_field DISCOVERY_TIMEOUT 60)

  # Not in make test: prints the objectives of a matrix (a developer's tool).
  add_executable(cemv_testgen_objectives ${CMAKE_CURRENT_LIST_DIR}/tool_objectives.cpp)
  target_link_libraries(cemv_testgen_objectives PRIVATE cemv_testgen)
  # Not in make test: the benchmark's 128 x 128 matrix as JSON (bench/testgen.cmake).
  add_executable(cemv_big_matrix_json ${CMAKE_CURRENT_LIST_DIR}/tool_big_matrix.cpp)
  target_link_libraries(cemv_big_matrix_json PRIVATE cemv_formats cemv_testsupport)

  # The generated suite of every example replays 100 % green on its matrix
  # (examples/*/acceptance, written by cemv testgen), and its coverage.json
  # carries the signature of the matrix as it is now (a stale suite fails).
  foreach(ex burner-management compressor pipeline-hipps tank-overfill)
    if(NOT EXISTS ${PROJECT_SOURCE_DIR}/examples/${ex}/acceptance/coverage.json)
      continue()  # not generated yet (docs/testgen.md, "Figures on the examples")
    endif()
    cemv_cli_test(NAME testgen_replay_${ex} EXIT 0 MATCH "PASS"
      COMMAND ${PROJECT_BINARY_DIR}/cemv replay examples/${ex}/matrix.json examples/${ex}/acceptance)
    add_test(NAME testgen_signature_${ex} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
      COMMAND bash -c "grep -q \"\\\"signature\\\": \\\"$(${PROJECT_BINARY_DIR}/cemv signature examples/${ex}/matrix.json)\\\"\" examples/${ex}/acceptance/coverage.json")
  endforeach()
  # The committed field suites (examples/*/acceptance/field) replay green.
  foreach(ex burner-management compressor pipeline-hipps tank-overfill)
    cemv_cli_test(NAME testgen_field_replay_${ex} EXIT 0 MATCH "PASS"
      COMMAND ${PROJECT_BINARY_DIR}/cemv replay examples/${ex}/matrix.json examples/${ex}/acceptance/field)
  endforeach()
  cemv_cli_test(NAME testgen_field_resolution_refused EXIT 2 MATCH "resolution"
    COMMAND ${PROJECT_BINARY_DIR}/cemv testgen examples/tank-overfill/matrix.json --out ${CMAKE_CURRENT_BINARY_DIR}/field_res --field-only --resolution 0)
  cemv_cli_test(NAME testgen_replay_junit EXIT 0 MATCH "<testsuites"
    COMMAND ${PROJECT_BINARY_DIR}/cemv replay examples/tank-overfill/matrix.json examples/tank-overfill/acceptance --format junit)
  # The tank's suite on the pipeline matrix: its tags do not exist there (exit 2).
  cemv_cli_test(NAME testgen_replay_wrong_matrix EXIT 2 MATCH "does not load"
    COMMAND ${PROJECT_BINARY_DIR}/cemv replay examples/pipeline-hipps/matrix.json examples/tank-overfill/acceptance)
  cemv_cli_test(NAME testgen_replay_missing EXIT 2 MATCH "error"
    COMMAND ${PROJECT_BINARY_DIR}/cemv replay examples/tank-overfill/matrix.json no/such/file.scenario.json)
  cemv_cli_test(NAME testgen_requires_out EXIT 2 MATCH "out"
    COMMAND ${PROJECT_BINARY_DIR}/cemv testgen examples/tank-overfill/matrix.json)
endif()

# Field results recorded back (docs/acceptance.md): a filled field checklist,
# all OK, with a deviation, merged from two days, refused, after a change.
if(TARGET cemv_testgen)
  foreach(case all_ok deviation merge refusals changed)
    add_test(NAME record_${case} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
      COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/record.sh ${PROJECT_BINARY_DIR}/cemv ${case})
  endforeach()
endif()

# --mutation-report measures the field suite beside the automated one and puts
# the comparison into the field checklists (two causes of the tank, one effect).
if(TARGET cemv_testgen)
  cemv_cli_test(NAME testgen_field_mutation_report EXIT 0
    MATCH "field versus automated: field detects 17, automated 24, automated only 7"
    COMMAND ${PROJECT_BINARY_DIR}/cemv testgen tests/testgen/tank_two_causes.json
            --out ${CMAKE_CURRENT_BINARY_DIR}/field_mutation --mutation-report)
endif()
