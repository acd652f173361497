# `cemv check` through the CLI (docs/checker.md): every format and every exit
# status, destinations, the hard time limit, sharding, closed pipes and full
# disks. These run on cemv_check_double, the real CLI linked with a test double
# of the checker (check_double/README.md), so they test the command, not the
# engines; the tests on the real checker are in check_real.cmake.
set(_d $<TARGET_FILE:cemv_check_double>)
set(_tank examples/tank-overfill/matrix.json)
set(_c ${CMAKE_CURRENT_LIST_DIR}/check_cases)
set(_tmp ${CMAKE_CURRENT_BINARY_DIR}/check_cli)
file(MAKE_DIRECTORY ${_tmp})

# Exit statuses 0, 1, 3, 4 from verdicts; 2 from inputs.
cemv_cli_test(NAME cli_check_all_proved_exit_0 EXIT 0 MATCH "2 properties: 2 proved"
  COMMAND ${_d} check ${_tank} ${_c}/proved.props)
cemv_cli_test(NAME cli_check_falsified_exit_1
  EXIT 1 MATCH "all_verdicts.props:4:10: error: property 'd.falsified_close' falsified at cycle 3"
  COMMAND ${_d} check ${_tank} ${_c}/all_verdicts.props)
cemv_cli_test(NAME cli_check_unknown_exit_3 EXIT 3 MATCH "u.unknown_timer: undecided|unknown: bound reached"
  COMMAND ${_d} check ${_tank} ${_c}/unknown.props)
cemv_cli_test(NAME cli_check_internal_error_exit_4
  EXIT 4 MATCH "internal error: replayed trace does not violate 'i.internal_replay'"
  COMMAND ${_d} check ${_tank} ${_c}/internal.props)
cemv_cli_test(NAME cli_check_checker_failure_exit_4
  EXIT 4 MATCH "internal error: the checker failed: solver exception: out of memory"
  COMMAND ${_d} check ${_tank} ${_c}/crash.props)
cemv_cli_test(NAME cli_check_invalid_matrix_exit_2
  EXIT 2 MATCH "errors.json: error: the matrix has validation errors; it cannot be checked"
  COMMAND ${_d} check tests/model/validate_cases/errors.json --standard)
cemv_cli_test(NAME cli_check_property_error_exit_2 EXIT 2 MATCH "bad_kind.props:2:1: .*found 'alwayz'"
  COMMAND ${_d} check ${_tank} ${_c}/bad_kind.props)
cemv_cli_test(NAME cli_check_missing_props_exit_2 EXIT 2 MATCH "no_such.props"
  COMMAND ${_d} check ${_tank} ${_c}/no_such.props)
cemv_cli_test(NAME cli_check_nothing_to_check_exit_2 EXIT 2 MATCH "nothing to check"
  COMMAND ${_d} check ${_tank})
cemv_cli_test(NAME cli_check_bad_format_exit_2 EXIT 2 MATCH "--format: 'xml' is not a format"
  COMMAND ${_d} check ${_tank} --standard --format xml)
cemv_cli_test(NAME cli_check_bad_report_exit_2 EXIT 2 MATCH "--report 'sarif': expected FORMAT:FILE"
  COMMAND ${_d} check ${_tank} --standard --report sarif)
cemv_cli_test(NAME cli_check_report_twice_to_one_file_exit_2 EXIT 2 MATCH "'-' is already a destination"
  COMMAND ${_d} check ${_tank} --standard --report json:-)
cemv_cli_test(NAME cli_check_unwritable_report_fails_fast EXIT 2 MATCH "/no/such/dir/r.sarif: cannot write"
  COMMAND timeout 5 ${_d} check ${_tank} ${_c}/hang.props --report sarif:/no/such/dir/r.sarif)
cemv_cli_test(NAME cli_check_bad_jobs_exit_2 EXIT 2 MATCH "--jobs must be at least 1"
  COMMAND ${_d} check ${_tank} --standard --jobs 0)
foreach(bad 0/3 4/3 3 a/b 1/0 2/3x)
  string(REPLACE "/" "_of_" _n ${bad})
  cemv_cli_test(NAME cli_check_bad_shard_${_n}_exit_2 EXIT 2 MATCH "--shard '${bad}': expected i/n with 1 <= i <= n"
    COMMAND ${_d} check ${_tank} --standard --shard ${bad})
endforeach()
cemv_cli_test(NAME cli_check_stdin_read_once_exit_2 EXIT 2 MATCH "only once"
  COMMAND ${_d} check - -)

# Formats: each valid as its consumer reads it, and byte-identical between runs.
cemv_cli_test(NAME cli_check_formats_valid_and_deterministic EXIT 0 MATCH "formats valid and deterministic"
  COMMAND bash ${_c}/run_formats.sh ${_d} ${_tank} ${_c}/all_verdicts.props 1 ${_tmp}/formats 6 3 1 4)
cemv_cli_test(NAME cli_check_text_shows_support_and_table EXIT 1
  MATCH "support \\(minimal\\): intersection\\[1,1\\].*|scenario: .*d.falsified_close.json"
  COMMAND ${_d} check ${_tank} ${_c}/all_verdicts.props --out ${_tmp}/text_cex)
cemv_cli_test(NAME cli_check_standard_json EXIT 0 MATCH "\"standard\": true"
  COMMAND ${_d} check ${_tank} --standard --format json)
cemv_cli_test(NAME cli_check_props_from_stdin EXIT 0 MATCH "\"file\": \"<stdin>\""
  COMMAND bash -c "${_d} check ${_tank} - --format json < ${_c}/proved.props")
cemv_cli_test(NAME cli_check_matrix_from_stdin EXIT 0 MATCH "\"file\": \"<stdin>\""
  COMMAND bash -c "${_d} check - ${_c}/proved.props --format json < ${_tank}")
cemv_cli_test(NAME cli_check_invalid_matrix_from_stdin_exit_2
  EXIT 2 MATCH "<stdin>:14:5: error: E-INTERSECTION-X intersection cause\\[1\\]/effect\\[1\\]"
  COMMAND bash -c "${_d} check - --standard < tests/model/validate_cases/errors.json")
cemv_cli_test(NAME cli_check_quiet_prints_nothing EXIT 0 MATCH "^$"
  COMMAND bash -c "${_d} check ${_tank} ${_c}/proved.props -q -o ${_tmp}/quiet.xml --format junit 2>&1 | wc -c | grep -qx 0 && echo")
cemv_cli_test(NAME cli_check_summary_line_with_o EXIT 1
  MATCH "^cemv check: TANK_T100: 6 properties: 1 proved, 1 falsified, 1 reachable, 1 unreachable, 1 vacuous, 1 unknown; wrote sarif to .*summary.sarif, junit to .*summary.xml"
  COMMAND ${_d} check ${_tank} ${_c}/all_verdicts.props --format sarif -o ${_tmp}/summary.sarif --report junit:${_tmp}/summary.xml)
# --report takes one value: the matrix and property file after it stay positional.
cemv_cli_test(NAME cli_check_report_takes_one_value EXIT 0 MATCH "2 proved; wrote json to .*order.json, junit to .*order.xml"
  COMMAND ${_d} check --report junit:${_tmp}/order.xml -o ${_tmp}/order.json --format json ${_tank} ${_c}/proved.props)
# One run, several reports: each the same as a run in that format alone.
cemv_cli_test(NAME cli_check_several_reports_one_run EXIT 0 MATCH "^same$"
  COMMAND bash ${_c}/several_reports.sh ${_d} ${_tank} ${_c}/all_verdicts.props ${_tmp}/several)

# Destinations are checked before the work: the property that never returns is
# never reached (the outer timeout would turn the exit status into 124).
cemv_cli_test(NAME cli_check_unwritable_o_fails_fast EXIT 2 MATCH "/no/such/dir/r.json: cannot write"
  COMMAND timeout 5 ${_d} check ${_tank} ${_c}/hang.props -o /no/such/dir/r.json)
cemv_cli_test(NAME cli_check_out_is_a_file_fails_fast EXIT 2 MATCH "all_verdicts.props: cannot write into it: it is not a folder"
  COMMAND timeout 5 ${_d} check ${_tank} ${_c}/hang.props --out ${_c}/all_verdicts.props)
# A full disk is an error naming the destination, on stdout and on -o.
cemv_cli_test(NAME cli_check_stdout_full_exit_2 EXIT 2 MATCH "<stdout>: cannot write: No space left on device"
  COMMAND bash -c "${_d} check ${_tank} ${_c}/proved.props > /dev/full")
cemv_cli_test(NAME cli_check_o_full_exit_2 EXIT 2 MATCH "/dev/full: cannot write: No space left on device"
  COMMAND ${_d} check ${_tank} ${_c}/proved.props --format json -o /dev/full)
cemv_cli_test(NAME cli_check_closed_pipe_is_quiet EXIT 0 MATCH "closed pipe: quiet exit 141"
  COMMAND bash ${_c}/closed_pipe.sh ${_d} ${_tank} ${_tmp}/pipe)

# --total-timeout is a hard limit, and what it leaves behind is valid.
cemv_cli_test(NAME cli_check_total_timeout_watchdog EXIT 0 MATCH "interrupted report"
  COMMAND bash ${_c}/watchdog.sh ${_d} ${_tank} ${_c}/hang.props ${_tmp}/watchdog)
cemv_cli_test(NAME cli_check_killed_leaves_valid_or_no_json EXIT 0 MATCH "kills: "
  COMMAND bash ${_c}/killed.sh ${_d} ${_tank} ${_tmp}/killed)

# --shard i/n partitions the properties.
cemv_cli_test(NAME cli_check_shards_partition EXIT 0 MATCH "3 shards partition 9 properties"
  COMMAND bash ${_c}/shards.sh ${_d} ${_tank} ${_c}/all_verdicts.props --standard)

# The exit statuses are documented where users look.
cemv_cli_test(NAME cli_check_help_documents_exit_codes EXIT 0 MATCH "4 internal error"
  COMMAND ${_d} check --help)
