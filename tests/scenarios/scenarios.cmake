# Scenario files run through `cemv simulate` (issue 3 section 5): every bullet of
# manual chapter 13 as a scenario named after its section and bullet, on the small
# matrices in matrices/, plus the rejections of bad scenarios (exit 2, message
# naming the bad item), a failing expectation (exit 1) and the trace option.
# A scenario of the cemv-scenario/1 format is a list of steps; docs/scenario.md.
set(CEMV_SCEN ${CMAKE_CURRENT_LIST_DIR})

# scenario file (without .json) -> matrix in matrices/ (without .json)
set(cemv_chapter13_scenarios  # and the other rules of issue 3 section 3, issue3_*
  13_1_1_on_delay_bullets1_2_4_delayed_activation:ch13_causes
  13_1_1_on_delay_bullets3_5_canceled:ch13_causes
  13_1_1_off_delay_bullets1_2_4_active_for_the_delay:ch13_causes
  13_1_1_off_delay_bullets3_5_canceled:ch13_causes
  13_1_1_off_delay_bullet4_acknowledgement_has_no_effect:ch13_causes
  13_1_1_timed_bullets1_2_time_for_timed_cause:ch13_causes
  13_1_1_timed_bullet3_regardless_of_input:ch13_causes
  13_1_2_inhibit_intro_inactive_while_TRUE:ch13_causes
  13_1_2_inhibit_bullet2_independent_of_time_functions:ch13_causes
  13_1_2_inhibit_bullet3_does_not_acknowledge:ch13_causes
  13_1_3_bypass_intro_bullet1_inactive_while_TRUE:ch13_causes
  13_1_3_bypass_bullet2_independent_of_time_functions:ch13_causes
  13_1_3_bypass_bullet3_does_not_acknowledge:ch13_causes
  13_1_3_bypass_bullet4_timed_soft_bypass:ch13_causes
  13_1_4_auto_ack_para1_inactive_when_condition_gone:ch13_causes
  13_1_4_auto_ack_para2_manual_acknowledgement:ch13_causes
  13_1_4_auto_ack_para3_no_effect_with_off_delay_or_timed:ch13_causes
  13_2_1_N_intro_reset_override_has_no_effect:ch13_effects
  13_2_1_S_bullet1_reset_required:ch13_effects
  13_2_1_S_bullet2_rising_edge_required:ch13_effects
  13_2_1_V_items1_2_3_override_time_and_timeout_alarm:ch13_effects
  13_2_1_V_bullet1_rising_edge_starts_and_stops:ch13_effects
  13_2_1_V_bullet3_cause_inactive_stops_override:ch13_effects
  13_2_1_V_override_failed_cause:ch13_effects
  13_2_1_V_operator_override:ch13_effects
  13_2_1_S_operator_reset:ch13_effects
  13_2_1_R_items1_2_3_override_and_reset:ch13_effects
  13_2_1_R_item4_no_reset_while_override_running:ch13_effects
  13_2_2_N_items1_2_output_delay:ch13_effects
  13_2_2_S_bullets_reset_after_output_delay:ch13_effects
  13_2_2_V_items4_5_6_output_delay_and_override:ch13_effects
  13_2_2_V_bullets_override_tag_no_effect:ch13_effects
  13_2_2_R_item7_and_stored_during_delay:ch13_effects
  13_2_3_N_bullets_bypass:ch13_effects
  13_2_3_S_bullets_bypass:ch13_effects
  13_2_3_V_bullets_bypass_and_override:ch13_effects
  13_2_3_R_bullets_bypass_override_reset:ch13_effects
  13_2_4_N_item2_bypass_interrupts_output_delay:ch13_effects
  13_2_4_S_bullets_bypass_with_output_delay:ch13_effects
  13_2_4_V_bullets_bypass_with_output_delay:ch13_effects
  13_2_4_R_bullets_bypass_with_output_delay:ch13_effects
  13_2_5_table_row1_no_effect:ch13_process_data
  13_2_5_table_row2_mask_items1_2:ch13_process_data
  13_2_5_table_row3_pass_through_item1:ch13_process_data
  13_2_5_table_row4_pass_through_and_mask_items1_2:ch13_process_data
  13_2_5_pass_through_with_output_delay:ch13_process_data
  # issue 3 section 3 rules beyond chapter 13
  issue3_first_out:issue3_rules
  issue3_prewarning_and_delta_alarm:issue3_rules
  issue3_xoon_assignment:issue3_rules
  issue3_internal_references:issue3_rules
  issue3_simulation:issue3_rules
  issue3_mutually_locked_maintenance:issue3_rules
  issue3_group_deactivation:issue3_rules
  issue3_secure_write:issue3_secure_write
)
foreach(entry ${cemv_chapter13_scenarios})
  string(REPLACE ":" ";" parts ${entry})
  list(GET parts 0 scenario)
  list(GET parts 1 matrix)
  cemv_cli_test(NAME scenario_${scenario} EXIT 0 MATCH "PASS"
                COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/matrices/${matrix}.json
                        ${CEMV_SCEN}/${scenario}.json)
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
  MATCH "syntax_error.json: line 2, column [0-9]+: JSON syntax error"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/syntax_error.json)
cemv_cli_test(NAME scenario_reject_missing_file EXIT 2 MATCH "no_such_scenario.json"
  COMMAND $<TARGET_FILE:cemv> simulate ${cemv_rej_matrix} ${CEMV_SCEN}/rejects/no_such_scenario.json)
cemv_cli_test(NAME scenario_reject_matrix_with_validation_errors EXIT 2
  MATCH "E-INTERSECTION-X intersection cause\\[1\\]/effect\\[1\\]"
  COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/rejects/matrix_with_x.json ${CEMV_SCEN}/rejects/trivial.json)
cemv_cli_test(NAME scenario_reject_matrix_unknown_key EXIT 2 MATCH "bypas_tag"
  COMMAND $<TARGET_FILE:cemv> simulate ${CEMV_SCEN}/rejects/matrix_unknown_key.json ${CEMV_SCEN}/rejects/trivial.json)
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
