# Timing diagrams (SVG) and value change dumps (VCD) of a run (reports/timing_svg.hpp,
# reports/vcd.hpp, docs/reports.md): golden files, and the VCD read back.
add_executable(test_reports_timing_pictures ${CMAKE_CURRENT_LIST_DIR}/test_timing_pictures.cpp)
target_link_libraries(test_reports_timing_pictures PRIVATE cemv_reports cemv_formats cemv_runtime GTest::gtest_main)
target_compile_definitions(test_reports_timing_pictures PRIVATE CEMV_GOLDEN_DIR="${CMAKE_CURRENT_LIST_DIR}/golden"
                           CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_reports_timing_pictures DISCOVERY_MODE PRE_TEST)

# The evidence report of an example loads in headless Chromium without errors,
# is byte-reproducible under SOURCE_DATE_EPOCH and prints to one page per
# chapter (docs/reports.md); with the example's acceptance suite its coverage
# tables. Its response-time table and the refusal of another matrix's results.
if(TARGET cemv_checker)
  set(EVIDENCE_TMP ${CMAKE_CURRENT_BINARY_DIR}/evidence)
  file(MAKE_DIRECTORY ${EVIDENCE_TMP})
  cemv_cli_test(NAME cli_evidence_loads_in_chromium EXIT 0 MATCH "evidence report loads in chromium"
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/evidence_headless.sh $<TARGET_FILE:cemv>
            examples/tank-overfill/matrix.json tests/cli/check_cases/tank_small.props
            ${CMAKE_CURRENT_BINARY_DIR}/evidence_headless
            --coverage examples/tank-overfill/acceptance/coverage.json
            -- "Objectives by kind" " objectives covered" "Every objective is covered."
            "No mutation figures given" "Not analysed")
  cemv_cli_test(NAME cli_evidence_response_table EXIT 0
    MATCH "<td>cause 1 -&gt; effect 1</td><td>0 cycles \\(0 ms\\)</td><td class=\"num\">200 ms</td><td class=\"num\">800 ms \\(80.0 %\\)</td><td class=\"ok\">ok</td>"
    COMMAND $<TARGET_FILE:cemv> evidence tests/response/no_watchdog.json --response --out - -q)
  cemv_cli_test(NAME cli_evidence_refuses_results_of_another_matrix EXIT 2
    MATCH "coverage.json: error: signature: these results are for the matrix with signature 77e3d26d"
    COMMAND $<TARGET_FILE:cemv> evidence tests/response/no_watchdog.json
            --coverage examples/tank-overfill/acceptance/coverage.json --out ${EVIDENCE_TMP}/refused.html)
  # check --out: every report format names each counterexample's .svg and .vcd.
  cemv_cli_test(NAME cli_check_reports_name_the_pictures EXIT 0 MATCH "every format names the pictures of [1-9]"
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_names_pictures.sh $<TARGET_FILE:cemv>
            examples/tank-overfill/matrix.json tests/cli/check_cases/tank_small.props
            ${CMAKE_CURRENT_BINARY_DIR}/check_names_pictures)
endif()
# testgen writes each test's timing diagram beside its scenario and names it.
if(TARGET cemv_testgen)
  set(TESTGEN_PICTURES ${CMAKE_CURRENT_BINARY_DIR}/testgen_pictures)
  cemv_cli_test(NAME cli_testgen_writes_test_diagrams EXIT 0 MATCH "diagram: .*/T001-[^ ]*\\.svg\n.*T001-[^ ]*\\.svg:1"
    COMMAND bash -c "rm -rf ${TESTGEN_PICTURES} && $<TARGET_FILE:cemv> testgen tests/response/no_watchdog.json --out ${TESTGEN_PICTURES} && grep -c '<svg xmlns' ${TESTGEN_PICTURES}/T001-*.svg /dev/null")
endif()
# The pictures on the command line: simulate names its files; check writes one per counterexample.
set(PICTURES_TMP ${CMAKE_CURRENT_BINARY_DIR}/pictures_cli)
file(MAKE_DIRECTORY ${PICTURES_TMP})
cemv_cli_test(NAME cli_simulate_svg_vcd EXIT 0 MATCH "diagram: .*scenario1.svg\nwaveforms: .*scenario1.vcd\nPASS"
  COMMAND $<TARGET_FILE:cemv> simulate examples/tank-overfill/scenario-1-overfill-trip.json
          --svg ${PICTURES_TMP}/scenario1.svg --vcd ${PICTURES_TMP}/scenario1.vcd)
