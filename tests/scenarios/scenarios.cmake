# Scenario files run through `cemv simulate`: every bullet of manual chapter 13
# as a scenario named after its section and bullet, and the rules of
# docs/semantics.md beyond chapter 13 (semantics_<paragraph>_*), on the small
# matrices in matrices/; plus the rejections of bad scenarios (exit 2, message
# naming the bad item), a failing expectation (exit 1) and the trace option.
# A scenario of the cemv-scenario/1 format is a list of steps; docs/scenario.md.
set(CEMV_SCEN ${CMAKE_CURRENT_LIST_DIR})

# Every scenario here names its matrix (its "matrix" key, a path relative to
# the file, docs/scenario.md), so `cemv simulate SCENARIO` finds it; the
# encoder's scenario test (tests/encoder/test_differential.cpp) reads the same key.
file(GLOB cemv_semantics_scenarios CONFIGURE_DEPENDS ${CEMV_SCEN}/*.json)
list(SORT cemv_semantics_scenarios)
foreach(_scenario ${cemv_semantics_scenarios})
  get_filename_component(scenario ${_scenario} NAME_WE)
  cemv_cli_test(NAME scenario_${scenario} EXIT 0 MATCH "PASS"
                COMMAND $<TARGET_FILE:cemv> simulate ${_scenario})
endforeach()

set(cemv_rej_matrix ${CEMV_SCEN}/matrices/ch13_causes.json)
cemv_cli_test(NAME scenario_reject_tag_typo EXIT 2
  MATCH "steps\\[0\\]\\.inputs: unknown tag 'INHI13' \\(did you mean 'INH13'\\?\\)"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/typo_tag.json)
cemv_cli_test(NAME scenario_reject_unknown_command EXIT 2
  MATCH "steps\\[0\\]\\.commands\\[0\\]\\.op: unknown command 'reset_cause'"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/unknown_command.json)
cemv_cli_test(NAME scenario_reject_unknown_expect_field EXIT 2
  MATCH "steps\\[0\\]\\.expect\\.cause\\[1\\]\\.actived: unknown cause field 'actived' \\(did you mean 'active'\\?\\)"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/unknown_expect_field.json)
cemv_cli_test(NAME scenario_reject_unknown_expect_key EXIT 2
  MATCH "steps\\[0\\]\\.expect\\.O99: unknown expectation key 'O99'"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/unknown_expect_key.json)
cemv_cli_test(NAME scenario_reject_unknown_expect_cause EXIT 2
  MATCH "no cause named 'ON_DELAI' \\(did you mean 'ON_DELAY'\\?\\)"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/unknown_expect_cause.json)
cemv_cli_test(NAME scenario_reject_ms_not_multiple EXIT 2
  MATCH "steps\\[0\\]\\.ms: 250 is not a multiple of cycle_ms \\(100\\)"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/ms_not_multiple.json)
cemv_cli_test(NAME scenario_reject_unknown_step_key EXIT 2
  MATCH "steps\\[0\\]\\.expekt: unknown key \\(did you mean 'expect'\\?\\)"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/unknown_step_key.json)
cemv_cli_test(NAME scenario_reject_syntax_error EXIT 2
  MATCH "syntax_error.json:2:[0-9]+: error: JSON syntax error"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/syntax_error.json)
cemv_cli_test(NAME scenario_reject_missing_file EXIT 2 MATCH "no_such_scenario.json"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/no_such_scenario.json)
cemv_cli_test(NAME scenario_reject_matrix_with_validation_errors EXIT 2
  MATCH "E-INTERSECTION-X intersection cause\\[1\\]/effect\\[1\\]"
  COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/matrices/matrix_with_x.json ${CEMV_SCEN}/rejects/trivial.json)
cemv_cli_test(NAME scenario_reject_matrix_unknown_key EXIT 2 MATCH "bypas_tag"
  COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/matrices/matrix_unknown_key.json ${CEMV_SCEN}/rejects/trivial.json)
cemv_cli_test(NAME scenario_failing_expectation_exit_1 EXIT 1
  MATCH "FAIL steps\\[1\\] \\(cycle 21, t = 2000 ms\\): cause\\[1\\]\\.active expected true, actual false"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/failing_expectation.json)
cemv_cli_test(NAME scenario_timing_table EXIT 0
  MATCH "cause\\[1\\]\\.active +1:0  22:1"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix}
          ${CEMV_SCEN}/13_1_1_on_delay_bullets1_2_4_delayed_activation.json)
cemv_cli_test(NAME scenario_trace EXIT 0 MATCH "^ \"format\": \"cemv-trace/1\",$"
  COMMAND bash -c "$<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/13_1_1_on_delay_bullets1_2_4_delayed_activation.json --trace ${PROJECT_BINARY_DIR}/scenario_trace_on_delay.json >/dev/null && cat ${PROJECT_BINARY_DIR}/scenario_trace_on_delay.json")
# Deterministic output: two runs, trace included, are byte-identical.
cemv_cli_test(NAME scenario_output_deterministic EXIT 0 MATCH "^identical$"
  COMMAND bash -c "c=$<TARGET_FILE:cemv> && m=${CEMV_SCEN}/matrices/ch13_effects.json && s=${CEMV_SCEN}/13_2_2_V_items4_5_6_output_delay_and_override.json && t=${PROJECT_BINARY_DIR}/scenario_det && $c simulate $m $s --trace $t.1.json > $t.1.txt && $c simulate $m $s --trace $t.2.json > $t.2.txt && cmp $t.1.txt $t.2.txt && cmp $t.1.json $t.2.json && echo identical")

# The scenario's "matrix" key (docs/scenario.md): with one argument `cemv
# simulate` loads the matrix the key names, relative to the scenario file...
cemv_cli_test(NAME scenario_matrix_key_one_argument EXIT 0
  MATCH "^matrix CH13_CAUSES signature [0-9a-f]{64}$"
  COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/13_1_1_on_delay_bullets1_2_4_delayed_activation.json)
# ... and refuses it like a matrix given on the command line,
cemv_cli_test(NAME scenario_matrix_key_refused_matrix EXIT 2
  MATCH "matrix_with_x.json:4:20: error: E-INTERSECTION-X intersection cause\\[1\\]/effect\\[1\\]"
  COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/rejects/trivial.json)
# without the key it says what to do, and a key that is not a path is bad input.
cemv_cli_test(NAME scenario_matrix_key_missing EXIT 2
  MATCH "no_key.json: error: the scenario names no matrix: give MATRIX SCENARIO"
  COMMAND bash -c "f=${PROJECT_BINARY_DIR}/no_key.json && echo '{\"format\": \"cemv-scenario/1\", \"steps\": [{}]}' > $f && $0 simulate $f"
          $<TARGET_FILE:cemv>)
cemv_cli_test(NAME scenario_matrix_key_not_a_string EXIT 2
  MATCH "bad_key.json:1:31: error: matrix: must be a non-empty string"
  COMMAND bash -c "f=${PROJECT_BINARY_DIR}/bad_key.json && echo '{\"format\": \"cemv-scenario/1\", \"matrix\": 3, \"steps\": [{}]}' > $f && $0 simulate $f"
          $<TARGET_FILE:cemv>)
