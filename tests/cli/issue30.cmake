# Evidence an assessor accepts (docs/reports.md, docs/params.md, docs/checker.md
# "Why, per step"): export of invalid matrices, diff and evidence of invalid
# matrices, property names across files, explained counterexamples, timing
# diagram rows named after their elements. Cases in trust_cases/issue30.
set(_i30 tests/cli/trust_cases/issue30)
set(_i30_tmp ${CMAKE_CURRENT_BINARY_DIR}/issue30)
file(MAKE_DIRECTORY ${_i30_tmp})
set(_tank examples/tank-overfill/matrix.json)

# Export never writes what import refuses: a repeated intersection cannot be
# written as a sheet that gives it back, so the export is refused with the
# validation error at its element.
foreach(_layout records grid)
  cemv_cli_test(NAME cli_export_csv_${_layout}_refuses_invalid EXIT 2
    MATCH "repeated.json: error: the matrix has validation errors; it cannot be exported to .*repeated.json:[0-9]+:[0-9]+: error: E-INTERSECTION-REPEATED intersection cause\\[1\\]/effect\\[1\\]"
    COMMAND $<TARGET_FILE:cemv> export-csv ${_i30}/repeated.json --layout ${_layout} -o ${_i30_tmp}/repeated.csv)
endforeach()
if(TARGET cemv_checker)
  cemv_cli_test(NAME cli_export_workbook_refuses_invalid EXIT 2 MATCH "E-INTERSECTION-REPEATED"
    COMMAND $<TARGET_FILE:cemv> export-workbook ${_i30}/repeated.json -o ${_i30_tmp}/repeated.xlsx)
endif()
# An invalid matrix that the sheet does hold round-trips with its signature.
cemv_cli_test(NAME cli_export_invalid_round_trips EXIT 0 MATCH "^same signature$"
  COMMAND bash ${_i30}/export_round_trip.sh $<TARGET_FILE:cemv> ${_i30}/no_override.json ${_i30_tmp}/round_trip)

if(TARGET cemv_checker)
  # diff of an invalid matrix: the structural part, and why no behaviour (exit 2).
  cemv_cli_test(NAME cli_diff_invalid_gives_the_structure EXIT 2
    MATCH "^  critical     changed intersection cause\\[3\\]/effect\\[3\\]$"
    COMMAND $<TARGET_FILE:cemv> diff ${_tank} ${_i30}/no_override.json)
  cemv_cli_test(NAME cli_diff_invalid_says_why EXIT 2
    MATCH "^  NEW: E-OVERRIDE-TIME-MISSING effect\\[3\\] STOP_P102 \\(6.5.2\\): "
    COMMAND $<TARGET_FILE:cemv> diff ${_tank} ${_i30}/no_override.json)
  cemv_cli_test(NAME cli_diff_invalid_json EXIT 2 MATCH "^  \"NEW: E-OVERRIDE-TIME-MISSING effect\\[3\\]"
    COMMAND $<TARGET_FILE:cemv> diff ${_tank} ${_i30}/no_override.json --format json)
  # evidence of an invalid matrix: written, a banner and the validation first (exit 1).
  cemv_cli_test(NAME cli_evidence_invalid_renders EXIT 0
    MATCH "^exit 1; banner; validation first; nothing checked$"
    COMMAND bash ${_i30}/evidence_invalid.sh $<TARGET_FILE:cemv> ${_i30}/no_override.json ${_i30_tmp}/invalid)
  # Property names are unique across files: the second place, naming the first.
  cemv_cli_test(NAME cli_check_duplicate_names_across_files EXIT 2
    MATCH "second.props:3:10: error: property 'req1' is already defined at ${_i30}/first.props:2:10"
    COMMAND $<TARGET_FILE:cemv> check ${_tank} ${_i30}/first.props ${_i30}/second.props)
  cemv_cli_test(NAME cli_evidence_duplicate_names_across_files EXIT 2 MATCH "is already defined at"
    COMMAND $<TARGET_FILE:cemv> evidence ${_tank} ${_i30}/first.props ${_i30}/first.props --out ${_i30_tmp}/dup.html)
  # A counterexample explains itself, in the text, in cemv-result/1 and under
  # its timing diagram, whose rows are named after their elements.
  cemv_cli_test(NAME cli_check_explains_counterexamples EXIT 0 MATCH "^explained in text, JSON and diagram$"
    COMMAND bash ${_i30}/check_explains.sh $<TARGET_FILE:cemv> ${_tank} tests/cli/check_cases/tank_small.props
            ${_i30_tmp}/explains)
endif()
