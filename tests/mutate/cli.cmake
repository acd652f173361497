# `cemv mutate`: every exit code and its outputs (the mutants, mutants.json,
# the distinguishing scenarios) on a one-cause one-effect matrix.
if(TARGET cemv_mutate AND TARGET cemv_diff)
  set(MUTATE_CASES ${PROJECT_SOURCE_DIR}/tests/diff/cases)
  set(MUTATE_TMP ${CMAKE_CURRENT_BINARY_DIR}/mutate)
  cemv_cli_test(NAME cli_mutate_exit0 EXIT 0
    MATCH "TINY: 11 mutants written to .* \\(6 single-point edits refused by validation\\)"
    COMMAND $<TARGET_FILE:cemv> mutate ${MUTATE_CASES}/mutate_tiny.json --out ${MUTATE_TMP}/plain)
  cemv_cli_test(NAME cli_mutate_list_operators_exit0 EXIT 0 MATCH "intersection-removed  each processed"
    COMMAND $<TARGET_FILE:cemv> mutate --list-operators)
  # --equivalence: every mutant decided, mutants.json and a killing scenario
  # per non-equivalent mutant that passes on the original and fails on it.
  add_test(NAME cli_mutate_equivalence
    COMMAND bash ${PROJECT_SOURCE_DIR}/tests/mutate/mutate_outputs.sh $<TARGET_FILE:cemv>
            ${MUTATE_CASES}/mutate_tiny.json ${MUTATE_TMP}/equivalence)
  cemv_cli_test(NAME cli_mutate_no_out_exit2 EXIT 2 MATCH "--out DIR is required"
    COMMAND $<TARGET_FILE:cemv> mutate ${MUTATE_CASES}/mutate_tiny.json)
  cemv_cli_test(NAME cli_mutate_invalid_exit2 EXIT 2 MATCH "small_invalid.json:.*error"
    COMMAND $<TARGET_FILE:cemv> mutate ${MUTATE_CASES}/small_invalid.json --out ${MUTATE_TMP}/invalid)
  cemv_cli_test(NAME cli_mutate_unwritable_exit2 EXIT 2 MATCH "error"
    COMMAND $<TARGET_FILE:cemv> mutate ${MUTATE_CASES}/mutate_tiny.json --out ${MUTATE_CASES}/mutate_tiny.json/sub)
  if(TARGET cemv_mutate)  # the double: tests/cli/change_double.cmake (included after this folder)
    cemv_cli_test(NAME cli_mutate_undecided_exit3 EXIT 3 MATCH "equivalent 0, non-equivalent 0, undecided 27"
      COMMAND $<TARGET_FILE:cemv_change_double> mutate ${MUTATE_CASES}/mutate_undecided.json --equivalence
              --out ${MUTATE_TMP}/undecided)
    cemv_cli_test(NAME cli_mutate_internal_exit4 EXIT 4 MATCH "internal error: equivalence of matrix"
      COMMAND $<TARGET_FILE:cemv_change_double> mutate ${MUTATE_CASES}/mutate_internal.json --equivalence
              --out ${MUTATE_TMP}/internal)
  endif()
endif()
