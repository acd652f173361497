# Change acceptance (docs/change-acceptance.md): change pairs on the examples
# with their expected classification, the LSST pair from its published CSVs,
# every exit code and output format of `cemv diff`, the HTML in a browser,
# and `cemv testgen --changed-from`.
if(TARGET cemv_diff AND TARGET cemv_mutate)
  add_executable(test_diff ${CMAKE_CURRENT_LIST_DIR}/test_diff.cpp)
  target_link_libraries(test_diff PRIVATE cemv_diff cemv_mutate GTest::gtest_main)
  target_compile_definitions(test_diff PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_diff DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
endif()

if(TARGET cemv_diff)
  set(DIFF_CASES ${CMAKE_CURRENT_LIST_DIR}/cases)
  set(DIFF_TMP ${CMAKE_CURRENT_BINARY_DIR}/diff)
  # Exit 0: a rename and a description edit change no behaviour.
  cemv_cli_test(NAME cli_diff_rename_exit0 EXIT 0
    MATCH "non-critical changed effect\\[2\\] P_2_RENAMED.*no behaviour changed: only non-critical"
    COMMAND bash -c "set -o pipefail && \"$1\" diff \"$2\" \"$3\" | tr '\\n' ' '" diff
            $<TARGET_FILE:cemv> ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_renamed.json)
  # Exit 1: intersection cause 1 / effect 1 N -> S; effect 1 latches in cycle 1.
  cemv_cli_test(NAME cli_diff_changed_exit1 EXIT 1
    MATCH "effect\\[1\\] XV_1: behaviour changed"
    COMMAND $<TARGET_FILE:cemv> diff ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_new.json)
  # Every format, -o, --out, -q and the distinguishing scenario on both versions.
  add_test(NAME cli_diff_formats
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/diff_formats.sh $<TARGET_FILE:cemv> ${DIFF_CASES} ${DIFF_TMP}/formats)
  # Exit 2: invalid input, unreadable file, an unknown format, an unwritable destination.
  cemv_cli_test(NAME cli_diff_invalid_matrix_exit2 EXIT 2 MATCH "small_invalid.json:.*error"
    COMMAND $<TARGET_FILE:cemv> diff ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_invalid.json)
  cemv_cli_test(NAME cli_diff_missing_file_exit2 EXIT 2 MATCH "no_such_file.json.*error|error.*no_such_file.json"
    COMMAND $<TARGET_FILE:cemv> diff ${DIFF_CASES}/no_such_file.json ${DIFF_CASES}/small_new.json)
  cemv_cli_test(NAME cli_diff_bad_format_exit2 EXIT 2 MATCH "--format 'xml': expected text, md, html, json or sarif"
    COMMAND $<TARGET_FILE:cemv> diff ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_new.json --format xml)
  cemv_cli_test(NAME cli_diff_unwritable_exit2 EXIT 2 MATCH "error"
    COMMAND $<TARGET_FILE:cemv> diff ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_new.json
            -o ${DIFF_CASES}/no_such_dir/report.txt)
  # Exit 3 and 4 on the CLI tests' double of observable equivalence
  # (tests/cli/change_double/README.md): an effect undecided, a run that
  # does not replay.
  if(TARGET cemv_mutate)  # the double: tests/cli/change_double.cmake (included after this folder)
    cemv_cli_test(NAME cli_diff_undecided_exit3 EXIT 3
      MATCH "effect\\[2\\] UNDECIDED_2: undecided \\(time limit\\).*retest the whole matrix.*undecided: some effect"
      COMMAND bash -c "set -o pipefail && \"$1\" diff \"$2\" \"$3\" | tr '\\n' ' '" diff
              $<TARGET_FILE:cemv_change_double> ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_undecided.json)
    cemv_cli_test(NAME cli_diff_internal_exit4 EXIT 4
      MATCH "internal error: equivalence of effect\\[2\\]: the runtimes do not reproduce"
      COMMAND $<TARGET_FILE:cemv_change_double> diff ${DIFF_CASES}/small_old.json ${DIFF_CASES}/small_internal.json)
  endif()
  # The HTML report loads in headless Chromium (as the evidence report's test).
  add_test(NAME diff_html_headless
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/diff_html_headless.sh $<TARGET_FILE:cemv> ${DIFF_CASES} ${DIFF_TMP}/html)
  # The LSST pair, imported from the two published CSVs.
  set(LSST_OLD ${CEMV_LSST_DIR}/lsst-tma-interlock-table-2023-10-05.csv)
  set(LSST_NEW ${CEMV_LSST_DIR}/lsst-tma-interlock-table.csv)
  add_test(NAME diff_lsst_pair
    COMMAND ${CEMV_WITH_LSST} bash ${CMAKE_CURRENT_LIST_DIR}/lsst_pair.sh $<TARGET_FILE:cemv> ${LSST_OLD} ${LSST_NEW} ${DIFF_TMP}/lsst)
  cemv_external_test(diff_lsst_pair)
endif()

# `cemv testgen NEW --changed-from OLD`: the tests the change needs.
if(TARGET cemv_diff AND TARGET cemv_testgen)
  add_test(NAME cli_testgen_changed_from
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/testgen_changed.sh $<TARGET_FILE:cemv> ${DIFF_CASES} ${DIFF_TMP}/testgen)
endif()
