# What a CI pipeline gates on (issue 31, docs/checker.md "Gating", docs/ci.md):
# --expect and --baseline, --cache, -q that still names each failure, SARIF
# at the matrix lines, flag typos, -q on every command, untrusted paths inside
# input files, a spreadsheet given where a matrix is expected. The command's
# own paths run on the checker double (check_double/README.md); what needs
# the engines runs on the real checker with the burner example (1-2 s).
set(_d $<TARGET_FILE:cemv_check_double>)
set(_c $<TARGET_FILE:cemv>)
set(_tank examples/tank-overfill/matrix.json)
set(_burner examples/burner-management)
set(_g ${CMAKE_CURRENT_LIST_DIR}/gate_cases)
set(_v ${PROJECT_SOURCE_DIR}/tests/reports/validate_outputs.py)
set(_tmp ${CMAKE_CURRENT_BINARY_DIR}/gate)
file(MAKE_DIRECTORY ${_tmp})

# --expect: each verdict against its `# expect:` comment (none: a passing one).
cemv_cli_test(NAME gate_expect_all_as_expected_exit_0 EXIT 0
  MATCH "cemv check --expect: 4 of 4 properties as expected \\(2 known findings expected\\)"
  COMMAND ${_d} check ${_tank} ${_g}/expected.props --expect)
cemv_cli_test(NAME gate_without_expect_findings_exit_1 EXIT 1 MATCH "2 unreachable|1 falsified"
  COMMAND ${_d} check ${_tank} ${_g}/expected.props)
cemv_cli_test(NAME gate_expect_names_each_unexpected_exit_1 EXIT 1
  MATCH "not as expected: g.fixed_defect \\(proved, expected falsified\\), g.falsified_new \\(falsified, expected proved or reachable\\)"
  COMMAND ${_d} check ${_tank} ${_g}/unexpected.props --expect)
cemv_cli_test(NAME gate_expect_line_per_unexpected EXIT 1
  MATCH "unexpected.props:3:11: error: property 'g.fixed_defect' proved by k-induction \\(k = 1\\), expected falsified \\(# expect:\\)"
  COMMAND ${_d} check ${_tank} ${_g}/unexpected.props --expect)
cemv_cli_test(NAME gate_expect_only_undecided_exit_3 EXIT 3 MATCH "1 of 2 properties not as expected: g.unknown_timer"
  COMMAND ${_d} check ${_tank} ${_g}/undecided.props --expect)
# The test view agrees with the gate: an expected finding is no failing test,
# and SARIF keeps it as a suppressed result.
add_test(NAME gate_expect_junit_and_sarif WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash -c "${_d} check ${_tank} ${_g}/expected.props --expect -q --format junit -o ${_tmp}/expect.xml --report sarif:${_tmp}/expect.sarif && python3 ${_v} junit ${_tmp}/expect.xml 4 0 0 && python3 ${_v} sarif ${_tmp}/expect.sarif 2 && python3 -c \"import json,sys; r=json.load(open(sys.argv[1]))['runs'][0]['results']; assert all(x['suppressions'][0]['kind']=='inSource' for x in r), r\" ${_tmp}/expect.sarif")
# The examples' seeded defects are recorded as expected: the gate passes.
cemv_cli_test(NAME gate_expect_real_example_exit_0 EXIT 0
  MATCH "cemv check --expect: 8 of 8 properties as expected \\(1 known finding expected\\)"
  COMMAND ${_c} check ${_burner}/matrix.json ${_burner}/requirements.props --expect)

# --baseline FILE: fail on what changed since an earlier result.
cemv_cli_test(NAME gate_baseline_fails_on_changes EXIT 0 MATCH "baseline gates on changes"
  COMMAND bash ${_g}/baseline.sh ${_d} ${_tank} ${_g}/baseline.props ${_tmp}/baseline)

# --cache DIR: verdicts reused, and the outputs are the same bytes.
cemv_cli_test(NAME gate_cache_double EXIT 0 MATCH "cache: 3 verdicts reused, outputs identical"
  COMMAND bash ${_g}/cache.sh ${_d} ${_tank} ${_g}/cache_double.props ${_tmp}/cache_double)
cemv_cli_test(NAME gate_cache_real_with_counterexamples EXIT 0 MATCH "cache: 8 verdicts reused, outputs identical"
  COMMAND bash ${_g}/cache.sh ${_c} ${_burner}/matrix.json ${_burner}/requirements.props ${_tmp}/cache_real out)
cemv_cli_test(NAME gate_cache_unwritable_exit_2 EXIT 2 MATCH "^error: /proc/no/such: cannot create the folder"
  COMMAND ${_d} check ${_tank} tests/cli/check_cases/proved.props --cache /proc/no/such)

# -q still prints one line per negative or unknown verdict: place and name.
add_test(NAME gate_quiet_names_each_failure WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash -c "out=$(${_d} check ${_tank} tests/cli/check_cases/all_verdicts.props -q 2>&1); [ $? = 1 ] && [ \"$(echo \"$out\" | grep -Ec '^tests/cli/check_cases/all_verdicts.props:[0-9]+:[0-9]+: (error|warning): property ')\" = 4 ] && echo \"$out\" | grep -q \"all_verdicts.props:4:10: error: property 'd.falsified_close' falsified at cycle 3\" || { echo \"$out\"; exit 1; }")
cemv_cli_test(NAME gate_quiet_real_names_the_finding EXIT 1
  MATCH "^examples/burner-management/requirements.props:46:10: error: property 'defect.flame_failure_always_trips' falsified"
  COMMAND ${_c} check ${_burner}/matrix.json ${_burner}/requirements.props -q)

# SARIF: a counterexample's cells at their lines in the matrix; relative
# documentation URIs; cemv diff --format sarif at the line of each change.
add_test(NAME gate_sarif_counterexample_cells WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash -c "${_c} check ${_tank} tests/cli/check_cases/tank_small.props --format sarif -o ${_tmp}/cells.sarif -q; python3 ${_v} sarif ${_tmp}/cells.sarif 1 && python3 ${_g}/related_locations.py ${_tmp}/cells.sarif ${_tank} cli.bypass_keeps_xv101_open 3,1")
add_test(NAME gate_diff_sarif_at_the_changed_lines WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND python3 ${_g}/diff_sarif.py ${_c} tests/diff/cases/small_old.json tests/diff/cases/small_new.json ${_tmp}/diff.sarif)

# Flag typos get the nearest flag of that command; every command takes -q.
cemv_cli_test(NAME gate_flag_typo_check EXIT 2
  MATCH "^error: check: unknown option '--timout'; did you mean '--timeout'\\? \\(cemv check --help lists the options\\)"
  COMMAND ${_c} check ${_tank} --standard --timout 5)
cemv_cli_test(NAME gate_flag_typo_validate EXIT 2 MATCH "^error: validate: unknown option '--formt'; did you mean '--format'\\?"
  COMMAND ${_c} validate ${_tank} --formt=json)
cemv_cli_test(NAME gate_flag_typo_top_level EXIT 2 MATCH "^error: unknown option '--verison'; did you mean '--version'\\?"
  COMMAND ${_c} --verison)
cemv_cli_test(NAME gate_flag_unknown_no_hint EXIT 2 MATCH "^error: replay: unknown option '--zzzzzz' \\(cemv replay --help lists the options\\)"
  COMMAND ${_c} replay ${_tank} examples/tank-overfill/acceptance --zzzzzz)
add_test(NAME gate_every_command_takes_quiet WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash -c "cmds=$(${_c} --help | awk '/^Subcommands:/{s=1;next} s&&NF{print $1}'); [ -n \"$cmds\" ] || exit 1; for c in $cmds; do ${_c} $c --help | grep -q -- '-q,--quiet' || { echo \"$c takes no -q\"; exit 1; }; done; echo \"$(echo $cmds | wc -w) commands take -q\"")
cemv_cli_test(NAME gate_replay_quiet_names_failures EXIT 1 MATCH "^FAIL "
  COMMAND ${_c} replay examples/tank-overfill/matrix.json ${_g}/failing.scenario.json -q)
cemv_cli_test(NAME gate_replay_quiet_silent_on_pass EXIT 0 MATCH "^$"
  COMMAND ${_c} replay examples/tank-overfill/matrix.json examples/tank-overfill/acceptance -q)

# Untrusted paths inside input files; files that are no matrix.
cemv_cli_test(NAME gate_inner_paths_stay_inside EXIT 0 MATCH "inner paths stay inside the working folder"
  COMMAND bash ${_g}/inner_paths.sh ${_c} ${_tmp}/inner_paths)
add_test(NAME gate_spreadsheet_given_as_matrix WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash ${_g}/spreadsheets.sh ${_c} ${_tmp}/spreadsheets)
