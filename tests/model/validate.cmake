# Plausibility checks (model/validate.cpp): one trigger and one near miss per rule.
add_executable(test_model_validate ${CMAKE_CURRENT_LIST_DIR}/test_validate.cpp)
target_include_directories(test_model_validate PRIVATE ${CMAKE_CURRENT_LIST_DIR})
target_compile_definitions(test_model_validate PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(test_model_validate PRIVATE cemv_model GTest::gtest_main)
gtest_discover_tests(test_model_validate DISCOVERY_MODE PRE_TEST)

# `cemv validate`: exit 0 without errors, 1 with errors, 2 for an unreadable or
# malformed file (docs/validation.md).
set(VC ${CMAKE_CURRENT_LIST_DIR}/validate_cases)
cemv_cli_test(NAME cli_validate_errors_exit_1 EXIT 1
  MATCH "error   E-INTERSECTION-X  intersection cause\\[1\\]/effect\\[1\\]  \\[6\\.5\\.2\\]  intersection type X"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/errors.json)
cemv_cli_test(NAME cli_validate_errors_summary EXIT 1
  MATCH "^2 errors, 2 warnings$"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/errors.json)
cemv_cli_test(NAME cli_validate_override_missing EXIT 1
  MATCH "error   E-OVERRIDE-TIME-MISSING  effect\\[2\\] CLOSE_2  \\[6\\.5\\.2\\]"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/errors.json)
cemv_cli_test(NAME cli_validate_warnings_exit_0 EXIT 0
  MATCH "warning W-TIMER-ROUNDING  cause\\[1\\] PSH_1  \\[13\\]  time\\.ms = 250 ms is not a multiple of cycle_ms 100: it acts as 300 ms"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/warnings.json)
cemv_cli_test(NAME cli_validate_signature EXIT 0
  MATCH "^signature: [0-9a-f]{64}$"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/warnings.json)
cemv_cli_test(NAME cli_validate_cycle_warning EXIT 0
  MATCH "W-REF-CYCLE  cause\\[1\\] PSH_1  \\[8\\.3\\]  cycle cause\\[1\\] -> effect\\[1\\] -> cause\\[1\\]: cause\\[1\\] reads effect\\[1\\] from the previous scan cycle"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/cycle.json)
cemv_cli_test(NAME cli_validate_json EXIT 1
  MATCH "\"rule\": \"E-INTERSECTION-X\""
  COMMAND $<TARGET_FILE:cemv> validate --format json ${VC}/errors.json)
cemv_cli_test(NAME cli_validate_json_header EXIT 0
  MATCH "\"format\": \"cemv-validation/1\""
  COMMAND $<TARGET_FILE:cemv> validate --format json ${VC}/cycle.json)
cemv_cli_test(NAME cli_validate_malformed_exit_2 EXIT 2
  MATCH "malformed.json:2:1: error: "
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/malformed.json)
cemv_cli_test(NAME cli_validate_unknown_key_exit_2 EXIT 2
  MATCH "causes\\[0\\]\\.bypas_tag"
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/unknown_key.json)
cemv_cli_test(NAME cli_validate_missing_file_exit_2 EXIT 2
  COMMAND $<TARGET_FILE:cemv> validate ${VC}/does-not-exist.json)
cemv_cli_test(NAME cli_validate_bad_format_option_exit_2 EXIT 2
  COMMAND $<TARGET_FILE:cemv> validate --format xml ${VC}/cycle.json)
# Every bundled example validates without errors (docs/validation.md).
foreach(example tank-overfill burner-management pipeline-hipps compressor)
  if(EXISTS ${PROJECT_SOURCE_DIR}/examples/${example}/matrix.json)
    cemv_cli_test(NAME cli_validate_example_${example} EXIT 0
      MATCH "^0 errors, [0-9]+ warnings$"
      COMMAND $<TARGET_FILE:cemv> validate ${PROJECT_SOURCE_DIR}/examples/${example}/matrix.json)
  endif()
endforeach()

# The imported LSST grid (docs/csv.md) loads, and validation lists the
# missing maximum override times of its effects with R intersections.
set(LSST_GRID ${CEMV_LSST_DIR}/lsst-tma-interlock-table.csv)
cemv_cli_test(NAME cli_validate_lsst_override_missing EXTERNAL EXIT 1
    MATCH "error   E-OVERRIDE-TIME-MISSING  effect\\[1\\] TMA_A_1  \\[6\\.5\\.2\\]"
    COMMAND bash -c "\"$1\" import-csv \"$2\" -o \"$3\" 2>/dev/null && \"$1\" validate \"$3\""
            lsst $<TARGET_FILE:cemv> ${LSST_GRID} ${CMAKE_CURRENT_BINARY_DIR}/lsst-import.json)
