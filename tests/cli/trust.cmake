# A command line that CI jobs and editors can trust (README, "Commands"):
# no silent write failure, every error names its file, nothing invalid
# processed silently, validation over many files in CI formats, a streaming
# trace. The cases and helper scripts are in trust_cases/.
set(_c $<TARGET_FILE:cemv>)
set(_t ${CMAKE_CURRENT_LIST_DIR}/trust_cases)
set(_tank examples/tank-overfill/matrix.json)
set(_hipps examples/pipeline-hipps/matrix.json)
set(_ch13 tests/scenarios/matrices/ch13_causes.json)
set(_on_delay tests/scenarios/13_1_1_on_delay_bullets1_2_4_delayed_activation.json)
set(_errors tests/model/validate_cases/errors.json)
set(_tmp ${CMAKE_CURRENT_BINARY_DIR}/trust_cli)
file(MAKE_DIRECTORY ${_tmp})

# 1. A full disk is an error (exit 2, naming the destination), for every
# command that writes, on standard output and with -o.
set(_writers
  "report ${_tank}"
  "report ${_tank} --format json"
  "validate ${_tank}"
  "validate ${_tank} --format sarif"
  "validate ${_tank} ${_hipps} --format gcc"
  "fmt ${_tank}"
  "signature ${_tank}"
  "graph ${_tank}"
  "graph ${_tank} --order"
  "export-csv ${_tank}"
  "export-csv ${_tank} --layout grid"
  "import-csv tests/sheets/csv_cases/tab_grid.tsv --orientation causes-as-rows"
  "export-smt ${_hipps} --roots effect:1 --depth 2"
  "simulate ${_ch13} ${_on_delay}"
  "simulate ${_ch13} ${_on_delay} --format json")
set(_i 0)
foreach(_args IN LISTS _writers)
  math(EXPR _i "${_i} + 1")
  string(REGEX MATCH "^[a-z-]+" _cmd "${_args}")
  cemv_cli_test(NAME cli_devfull_stdout_${_i}_${_cmd} EXIT 2 MATCH "^error: <stdout>: cannot write: No space left on device$"
    COMMAND bash -c "$0 ${_args} > /dev/full" ${_c})
  if(_cmd STREQUAL "signature")
    continue()  # signature writes to standard output only
  endif()
  cemv_cli_test(NAME cli_devfull_output_${_i}_${_cmd} EXIT 2 MATCH "^error: /dev/full: cannot write: No space left on device$"
    COMMAND bash -c "$0 ${_args} -o /dev/full" ${_c})
endforeach()
cemv_cli_test(NAME cli_devfull_trace EXIT 2 MATCH "^error: /dev/full: cannot write: No space left on device$"
  COMMAND ${_c} simulate ${_ch13} ${_on_delay} --trace /dev/full)
cemv_cli_test(NAME cli_devfull_fmt_check EXIT 2 MATCH "^error: <stdout>: cannot write"
  COMMAND bash -c "$0 fmt --check tests/scenarios/matrices/ch13_effects.json ${_tank} > /dev/full" ${_c})

# A closed pipe ends quietly: no message, whatever the command.
cemv_cli_test(NAME cli_closed_pipe_is_quiet EXIT 0 MATCH "^quiet$"
  COMMAND bash ${_t}/closed_pipe.sh ${_c})

# Destinations are checked before the work: an unwritable --trace or -o fails
# before the scenario runs (no PASS printed), for every command.
cemv_cli_test(NAME cli_simulate_unwritable_trace_fails_first EXIT 0 MATCH "^fails first$"
  COMMAND bash ${_t}/quiet.sh ${_c} unwritable ${_ch13} ${_on_delay} --trace /no/such/dir/t.json)
foreach(_args "report ${_tank}" "fmt ${_tank}" "graph ${_tank}" "export-csv ${_tank}" "validate ${_tank}"
              "export-smt ${_hipps}" "simulate ${_ch13} ${_on_delay}" "import-csv tests/sheets/csv_cases/tab_grid.tsv --orientation causes-as-rows")
  string(REGEX MATCH "^[a-z-]+" _cmd "${_args}")
  cemv_cli_test(NAME cli_unwritable_output_${_cmd} EXIT 2 MATCH "^error: /no/such/dir/out: cannot write"
    COMMAND bash -c "$0 ${_args} -o /no/such/dir/out" ${_c})
endforeach()

# A run killed while writing its -o or --trace file leaves the old file intact.
cemv_cli_test(NAME cli_killed_run_keeps_old_file EXIT 0 MATCH "old files intact"
  COMMAND bash ${_t}/killed.sh ${_c} ${_ch13} ${_tmp}/killed)

# "-" is standard input, named <stdin> in messages.
cemv_cli_test(NAME cli_stdin_signature EXIT 0 MATCH "^same signature$"
  COMMAND bash -c "[ \"$($0 signature - < ${_tank})\" = \"$($0 signature ${_tank})\" ] && echo 'same signature'" ${_c})
cemv_cli_test(NAME cli_stdin_error_named EXIT 2 MATCH "^<stdin>:1:2: error: "
  COMMAND bash -c "echo '{x' | $0 validate -" ${_c})
cemv_cli_test(NAME cli_stdin_scenario EXIT 0 MATCH "^PASS$"
  COMMAND bash -c "$0 simulate ${_ch13} - < ${_on_delay}" ${_c})

# 2. Every message names its place: the file first, then line and column.
foreach(_case
    "matrix_syntax|fmt tests/formats/malformed/syntax-missing-colon.json|^tests/formats/malformed/syntax-missing-colon.json:3:[0-9]+: error: syntax error"
    "matrix_path|fmt tests/formats/malformed/unknown-key-cause.json|^tests/formats/malformed/unknown-key-cause.json:[0-9]+:[0-9]+: error: causes\\[0\\]\\.bypas_tag: unknown key"
    "matrix_overflow|validate tests/formats/malformed/number-overflow.json|^tests/formats/malformed/number-overflow.json:1:54: error: number '1e999' is out of range"
    "matrix_missing|report no/such/matrix.json|^no/such/matrix.json: error: cannot open"
    "matrix_refused|graph ${_t}/duplicate_id.json|^.*duplicate_id.json:7:5: error: E-DUPLICATE-CAUSE-ID cause\\[1\\]"
    "scenario_overflow|simulate ${_ch13} ${_t}/scenario_overflow.json|^.*scenario_overflow.json:4:16: error: number '1e999' is out of range \\(overflows a double\\)$"
    "scenario_nan|simulate ${_ch13} ${_t}/scenario_nan.json|^.*scenario_nan.json:4:23: error: 'NaN' is not a JSON number"
    "scenario_duplicate|simulate ${_ch13} ${_t}/scenario_duplicate_key.json|^.*scenario_duplicate_key.json:5:6: error: steps\\[0\\]\\.cycles: duplicate key"
    "scenario_syntax|simulate ${_ch13} ${_t}/scenario_syntax.json|^.*scenario_syntax.json:4:18: error: JSON syntax error"
    "scenario_deep|simulate ${_ch13} ${_t}/scenario_deep.json|^.*scenario_deep.json:1:[0-9]+: error: JSON nesting deeper than 64 levels"
    "scenario_utf8|simulate ${_ch13} ${_t}/scenario_bad_utf8.json|^.*scenario_bad_utf8.json:1:[0-9]+: error: invalid UTF-8: byte 0xFF does not belong here"
    "scenario_tag|simulate ${_ch13} tests/scenarios/rejects/typo_tag.json|^tests/scenarios/rejects/typo_tag.json:[0-9]+:[0-9]+: error: steps\\[0\\]\\.inputs: unknown tag 'INHI13'"
    "scenario_missing|simulate ${_ch13} no/such/scenario.json|^no/such/scenario.json: error: cannot open"
    "csv_syntax|import-csv tests/sheets/csv_cases/bad_unterminated_quote.csv|^tests/sheets/csv_cases/bad_unterminated_quote.csv:[0-9]+(:[0-9]+)?: error: "
    "csv_not_grid|import-csv tests/sheets/csv_cases/not_a_grid.csv|^tests/sheets/csv_cases/not_a_grid.csv(:[0-9]+)*: error: ")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _name)
  list(GET _parts 1 _args)
  list(GET _parts 2 _regex)
  separate_arguments(_argv UNIX_COMMAND "${_args}")
  cemv_cli_test(NAME cli_message_names_file_${_name} EXIT 2 MATCH "${_regex}" COMMAND ${_c} ${_argv})
endforeach()
# ... and every stderr line of those begins with a file name.
cemv_cli_test(NAME cli_messages_begin_with_file EXIT 0 MATCH "^every line names its file$"
  COMMAND bash ${_t}/every_line_names_file.sh ${_c} ${_ch13} ${_t})

# A scenario of another matrix: one line says so; long lists are capped.
cemv_cli_test(NAME cli_scenario_of_another_matrix EXIT 2
  MATCH "error: none of the scenario's [0-9]+ tags is in matrix TANK_T100. is it the scenario of another matrix\\?"
  COMMAND ${_c} simulate ${_tank} examples/burner-management/scenario-1-air-trip-ack-reset.json)
cemv_cli_test(NAME cli_long_error_list_capped EXIT 0 MATCH "^capped at 20 and 1 line$"
  COMMAND bash ${_t}/capped.sh ${_c} ${_tmp})

# 3. Nothing invalid is processed silently.
cemv_cli_test(NAME cli_graph_refuses_duplicate_id EXIT 2
  MATCH "duplicate_id.json: error: the matrix has validation errors. it cannot be drawn as a graph"
  COMMAND ${_c} graph ${_t}/duplicate_id.json)
cemv_cli_test(NAME cli_export_smt_refuses_invalid EXIT 2 MATCH "it cannot be encoded"
  COMMAND ${_c} export-smt ${_errors})
cemv_cli_test(NAME cli_report_invalid_banner_exit_1 EXIT 1 MATCH "^## INVALID MATRIX: 2 validation error\\(s\\)$"
  COMMAND ${_c} report ${_errors})
cemv_cli_test(NAME cli_report_invalid_validation_first EXIT 0 MATCH "^validation first$"
  COMMAND bash -c "$0 report ${_errors} | grep -n '^## ' | head -3 | grep -q '3 Validation summary' && echo 'validation first'" ${_c})
cemv_cli_test(NAME cli_report_invalid_json_banner EXIT 1 MATCH "\"banner\": \"INVALID MATRIX"
  COMMAND ${_c} report ${_errors} --format json)
cemv_cli_test(NAME cli_export_smt_depth_with_vmt_refused EXIT 2 MATCH "--depth applies to --format smt2"
  COMMAND ${_c} export-smt ${_hipps} --format vmt --depth 5)
cemv_cli_test(NAME cli_export_csv_orientation_needs_grid EXIT 2 MATCH "--orientation applies to --layout grid only"
  COMMAND ${_c} export-csv ${_tank} --orientation effects-as-rows)
cemv_cli_test(NAME cli_import_csv_grid_options_with_records_refused EXIT 2
  MATCH "--separator, --name and --orientation apply to grids"
  COMMAND ${_c} import-csv tests/sheets/csv_cases/tab_grid.tsv --layout records --name X)
cemv_cli_test(NAME cli_fmt_several_files_without_check EXIT 2 MATCH "give one FILE to format"
  COMMAND ${_c} fmt ${_tank} ${_hipps})
cemv_cli_test(NAME cli_import_csv_name_too_long EXIT 2
  MATCH "--name 'ABCDEFGHIJKLMNOPQ': 17 characters. a matrix name has at most 16 \\(6\\.1\\.2\\)"
  COMMAND ${_c} import-csv tests/sheets/csv_cases/tab_grid.tsv --orientation causes-as-rows --name ABCDEFGHIJKLMNOPQ)
cemv_cli_test(NAME cli_import_csv_name_16_accepted EXIT 0 MATCH "\"name\": \"ABCDEFGHIJKLMNOP\""
  COMMAND ${_c} import-csv tests/sheets/csv_cases/tab_grid.tsv --orientation causes-as-rows --name ABCDEFGHIJKLMNOP -q)
cemv_cli_test(NAME cli_unknown_command_did_you_mean EXIT 2
  MATCH "^error: unknown command 'grpah'. did you mean 'graph'\\?"
  COMMAND ${_c} grpah ${_tank})
cemv_cli_test(NAME cli_unknown_command_no_hint EXIT 2 MATCH "^error: unknown command 'frobnicate' \\(cemv --help"
  COMMAND ${_c} frobnicate)

# 4. Validation as a CI gate.
cemv_cli_test(NAME cli_validate_many_summary EXIT 1
  MATCH "^3 files: 2 clean, 1 with errors. 2 errors, 6 warnings$"
  COMMAND ${_c} validate ${_tank} ${_hipps} ${_errors})
cemv_cli_test(NAME cli_validate_many_unreadable_exit_2 EXIT 2
  MATCH "^3 files: 1 clean, 1 with errors, 1 unreadable. 2 errors, 3 warnings$"
  COMMAND ${_c} validate ${_tank} ${_errors} no/such.json)
cemv_cli_test(NAME cli_validate_warnings_as_errors EXIT 1 MATCH "^1 files: 0 clean, 1 with errors. 0 errors, 3 warnings$"
  COMMAND ${_c} validate tests/model/validate_cases/warnings.json --format gcc --warnings-as-errors)
cemv_cli_test(NAME cli_validate_warnings_as_errors_are_errors EXIT 1
  MATCH "^tests/model/validate_cases/warnings.json:6:5: error: \\[W-TIMER-ROUNDING\\] cause\\[1\\] PSH_1: "
  COMMAND ${_c} validate tests/model/validate_cases/warnings.json --format gcc --warnings-as-errors)
cemv_cli_test(NAME cli_validate_warnings_only_exit_0 EXIT 0
  COMMAND ${_c} validate tests/model/validate_cases/warnings.json --format gcc)
cemv_cli_test(NAME cli_validate_gcc_positions EXIT 1
  MATCH "^tests/model/validate_cases/errors.json:[0-9]+:[0-9]+: error: \\[E-INTERSECTION-X\\] intersection cause\\[1\\]/effect\\[1\\]: "
  COMMAND ${_c} validate ${_errors} --format gcc)
cemv_cli_test(NAME cli_validate_gcc_position_exact EXIT 1
  MATCH "duplicate_id.json:7:5: error: \\[E-DUPLICATE-CAUSE-ID\\] cause\\[1\\]"
  COMMAND ${_c} validate ${_t}/duplicate_id.json --format gcc)
cemv_cli_test(NAME cli_validate_sarif_and_junit_valid EXIT 0 MATCH "^sarif and junit valid$"
  COMMAND python3 ${_t}/check_ci_formats.py ${_c} ${_tank} ${_errors} ${_t}/duplicate_id.json no/such.json)
cemv_cli_test(NAME cli_validate_quiet EXIT 1 MATCH "^quiet: errors only$"
  COMMAND bash ${_t}/quiet.sh ${_c} validate ${_errors})
cemv_cli_test(NAME cli_fmt_check EXIT 0 MATCH "^fmt --check ok$"
  COMMAND bash ${_t}/fmt_check.sh ${_c} ${_tmp}/fmt_check)

# 5. Machine-readable simulation and a streaming trace.
cemv_cli_test(NAME cli_simulate_json EXIT 0 MATCH "^simulate json ok$"
  COMMAND python3 ${_t}/check_simulate_json.py ${_c} ${_ch13} ${_on_delay}
          tests/scenarios/rejects/failing_expectation.json)
cemv_cli_test(NAME cli_simulate_trace_changes EXIT 0 MATCH "^trace-changes ok"
  COMMAND python3 ${_t}/check_trace_changes.py ${_c} ${_ch13} ${_on_delay} ${_tmp})
cemv_cli_test(NAME cli_simulate_quiet EXIT 0 MATCH "^nothing printed$"
  COMMAND bash -c "out=$($0 simulate ${_ch13} ${_on_delay} --quiet 2>&1) && [ -z \"$out\" ] && echo 'nothing printed'" ${_c})
cemv_cli_test(NAME cli_simulate_quiet_failure_still_printed EXIT 1 MATCH "^FAIL steps\\[1\\]"
  COMMAND ${_c} simulate ${_ch13} tests/scenarios/rejects/failing_expectation.json --quiet)
cemv_cli_test(NAME cli_simulate_trace_changes_needs_trace EXIT 2 MATCH "--trace-changes needs --trace"
  COMMAND ${_c} simulate ${_ch13} ${_on_delay} --trace-changes)
