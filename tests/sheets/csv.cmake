# The C&E grid and the layout description (6.6, docs/csv.md); the RFC 4180
# tokenizer and the record layout are tests/formats/csv_records.cmake.
add_executable(test_sheets_csv ${CMAKE_CURRENT_LIST_DIR}/test_csv_grid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_csv_layouts.cpp ${CMAKE_CURRENT_LIST_DIR}/test_sheet_layout.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_csv_vendor.cpp ${CMAKE_CURRENT_LIST_DIR}/test_csv_stacked_header.cpp)
target_link_libraries(test_sheets_csv PRIVATE cemv_sheets GTest::gtest_main)
target_compile_definitions(test_sheets_csv PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}" CEMV_LSST_DIR="${CEMV_LSST_DIR}")
# The tests that read the published LSST tables exit 77 where they are absent
# (tests/support/external_tables.hpp): CTest reports them skipped.
gtest_discover_tests(test_sheets_csv DISCOVERY_MODE PRE_TEST PROPERTIES SKIP_RETURN_CODE 77)

# The command line: exit statuses and messages (cwd = repo root).
set(CSV_CASES tests/sheets/csv_cases)
set(LSST ${CEMV_LSST_DIR}/lsst-tma-interlock-table.csv)
set(CSV_TMP ${CMAKE_CURRENT_BINARY_DIR}/csv_cli)
file(MAKE_DIRECTORY ${CSV_TMP})
cemv_cli_test(NAME cli_import_csv_lsst EXTERNAL EXIT 0
  MATCH ":35:2: warning: cause id 'TMA-D-40' repeats line 25.*kept as separate causes"
  COMMAND $<TARGET_FILE:cemv> import-csv ${LSST} -o ${CSV_TMP}/lsst.json)
cemv_cli_test(NAME cli_import_csv_lsst_stdout EXTERNAL EXIT 0
  MATCH "\"name\": \"TMA_D_40_2\""
  COMMAND $<TARGET_FILE:cemv> import-csv ${LSST})
# What the grid does not state, validate reports: the override time of each effect with R.
cemv_cli_test(NAME cli_import_csv_lsst_validate EXTERNAL EXIT 1
  MATCH "TMA_A_1 .*override.*TMA_A_2 .*override.*TMA_A_4 .*override.*TMA_A_5 .*override"
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/csv_cases/cli_import_then_validate.sh $<TARGET_FILE:cemv> ${LSST} ${CSV_TMP}/validate)
cemv_cli_test(NAME cli_import_csv_forced_grid EXTERNAL EXIT 0 MATCH "effect id 'TMA-A-17' out of order"
  COMMAND $<TARGET_FILE:cemv> import-csv --layout grid ${LSST} -o ${CSV_TMP}/lsst3.json)
cemv_cli_test(NAME cli_import_csv_separator_option EXIT 0 MATCH "\"name\": \"E_2\""
  COMMAND $<TARGET_FILE:cemv> import-csv --separator tab --orientation causes-as-rows ${CSV_CASES}/tab_grid.tsv)
# No corner labels, ids 1, 2 and T-1: no evidence of the orientation, so a refusal that asks for it.
cemv_cli_test(NAME cli_import_csv_orientation_unknown EXIT 2
  MATCH "tab_grid.tsv:2: error: cannot tell whether the causes are the rows or the columns.*--orientation"
  COMMAND $<TARGET_FILE:cemv> import-csv --separator tab ${CSV_CASES}/tab_grid.tsv)
cemv_cli_test(NAME cli_import_csv_missing_file EXIT 2 MATCH "no_such_file.csv: error: cannot open"
  COMMAND $<TARGET_FILE:cemv> import-csv ${CSV_CASES}/no_such_file.csv)
cemv_cli_test(NAME cli_import_csv_unterminated_quote EXIT 2
  MATCH "^tests/sheets/csv_cases/bad_unterminated_quote.csv:3:3: error: quoted field never closed"
  COMMAND $<TARGET_FILE:cemv> import-csv ${CSV_CASES}/bad_unterminated_quote.csv)
cemv_cli_test(NAME cli_import_csv_bad_values EXIT 2
  MATCH "bad_values.csv:6:4: error: type: 'Z' is not one of"
  COMMAND $<TARGET_FILE:cemv> import-csv ${CSV_CASES}/bad_values.csv)
cemv_cli_test(NAME cli_import_csv_not_a_grid EXIT 2 MATCH "not a C&E grid"
  COMMAND $<TARGET_FILE:cemv> import-csv ${CSV_CASES}/not_a_grid.csv)
cemv_cli_test(NAME cli_import_csv_bad_layout EXIT 2 MATCH "layout"
  COMMAND $<TARGET_FILE:cemv> import-csv --layout sideways ${CSV_CASES}/tab_grid.tsv)
cemv_cli_test(NAME cli_export_csv_missing_file EXIT 2 MATCH "error:"
  COMMAND $<TARGET_FILE:cemv> export-csv ${CSV_CASES}/no_such_matrix.json)
# Export, import, export again: byte-identical CSV, and the same canonical matrix.
foreach(example tank-overfill burner-management pipeline-hipps compressor)
  cemv_cli_test(NAME cli_csv_round_trip_${example} EXIT 0 MATCH "round trip identical"
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/csv_cases/cli_round_trip.sh $<TARGET_FILE:cemv>
            examples/${example}/matrix.json ${CSV_TMP}/round_trip)
endforeach()

# Grid layouts (docs/csv.md "The grid layout"): the summary, --orientation, --strict and grid export.
cemv_cli_test(NAME cli_import_csv_lsst_summary EXTERNAL EXIT 0
  MATCH "note: .*read 36 causes \\(rows 3-38, ids in column 2\\), 17 effects \\(columns 3-19, ids in row 2\\), 102 intersections; orientation causes-as-rows from the corner labels"
  COMMAND $<TARGET_FILE:cemv> import-csv ${LSST} -o ${CSV_TMP}/lsst_summary.json)
cemv_cli_test(NAME cli_import_csv_transposed_auto EXTERNAL EXIT 0
  MATCH "transposed table: 102 intersections as published; note: .*read 36 causes \\(columns 3-38, ids in row 2\\), 17 effects \\(rows 3-19, ids in column 2\\), 102 intersections; orientation effects-as-rows from the corner labels"
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/csv_cases/cli_transposed_lsst.sh $<TARGET_FILE:cemv> ${LSST} ${CSV_TMP}/transposed_auto)
cemv_cli_test(NAME cli_import_csv_transposed_orientation EXTERNAL EXIT 0
  MATCH "transposed table: 102 intersections as published; note: .*orientation effects-as-rows as given by --orientation"
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/csv_cases/cli_transposed_lsst.sh $<TARGET_FILE:cemv> ${LSST} ${CSV_TMP}/transposed_option --orientation effects-as-rows)
cemv_cli_test(NAME cli_import_csv_strict_refuses_lsst EXTERNAL EXIT 2
  MATCH "lsst-tma-interlock-table.csv: error: 11 import warnings are an error under --strict"
  COMMAND $<TARGET_FILE:cemv> import-csv --strict ${LSST} -o ${CSV_TMP}/lsst_strict.json)
cemv_cli_test(NAME cli_import_csv_strict_clean_grid EXIT 0
  MATCH "note: .*read 4 causes"
  COMMAND bash -c "$<TARGET_FILE:cemv> export-csv --layout grid examples/tank-overfill/matrix.json -o ${CSV_TMP}/clean_grid.csv && $<TARGET_FILE:cemv> import-csv --strict ${CSV_TMP}/clean_grid.csv -o ${CSV_TMP}/clean_grid.json")
cemv_cli_test(NAME cli_export_csv_bad_layout EXIT 2 MATCH "layout"
  COMMAND $<TARGET_FILE:cemv> export-csv --layout sideways examples/tank-overfill/matrix.json)
# Every example, in both orientations (the script fails on the first difference).
file(GLOB example_matrices RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/*/matrix.json)
foreach(matrix ${example_matrices})
  get_filename_component(example_dir ${matrix} DIRECTORY)
  get_filename_component(example ${example_dir} NAME)
  cemv_cli_test(NAME cli_csv_grid_round_trip_${example} EXIT 0
    MATCH "^effects-as-rows: [0-9]+ intersections identical"
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/csv_cases/cli_grid_round_trip.sh $<TARGET_FILE:cemv>
            ${matrix} ${CSV_TMP}/grid_round_trip)
endforeach()

# Vendor sheets (docs/csv.md "Vendor sheets"): the layout description through
# the command line: a malformed one refused at its line and column, the layout
# used saved and given again, and what a grid cannot take refused.
file(WRITE ${CSV_TMP}/bad_layout.json "{\"format\": \"cemv-sheet-layout/1\",\n \"marks\": {\"NP\": {\"type\": \"nothing\"}}}\n")
cemv_cli_test(NAME cli_import_csv_sheet_layout_malformed EXIT 2
  MATCH "bad_layout.json:2:19: error: marks.NP.type: must be N, S, V, R, X, \\* or none, not \"nothing\""
  COMMAND $<TARGET_FILE:cemv> import-csv ${CSV_CASES}/tab_grid.tsv --sheet-layout ${CSV_TMP}/bad_layout.json -o ${CSV_TMP}/bad_layout_out.json)
cemv_cli_test(NAME cli_import_csv_sheet_layout_saved_and_given_again EXTERNAL EXIT 0
  MATCH "^same matrix with the layout saved: [0-9a-f]+$"
  COMMAND bash -c "$0 import-csv ${LSST} -o ${CSV_TMP}/first.json --save-layout ${CSV_TMP}/lsst_layout.json 2>/dev/null && $0 import-csv ${LSST} --sheet-layout ${CSV_TMP}/lsst_layout.json -o ${CSV_TMP}/again.json 2>/dev/null && python3 $1 ${CSV_TMP}/first.json ${CSV_TMP}/first_bare.json && python3 $1 ${CSV_TMP}/again.json ${CSV_TMP}/again_bare.json && cmp ${CSV_TMP}/first_bare.json ${CSV_TMP}/again_bare.json && echo \"same matrix with the layout saved: $($0 signature ${CSV_TMP}/again_bare.json)\"" $<TARGET_FILE:cemv> ${CMAKE_CURRENT_LIST_DIR}/without_import_records.py)
cemv_cli_test(NAME cli_import_csv_layout_used_note EXTERNAL EXIT 0
  MATCH "note: layout used \\(found in the sheet. --save-layout keeps it\\): \\{\"format\":\"cemv-sheet-layout/1\",\"orientation\":\"causes-as-rows\",\"causes\":\\{\"id\":\"B\",\"description\":\"A\"\\},\"effects\":\\{\"id\":2,\"description\":1\\}"
  COMMAND $<TARGET_FILE:cemv> import-csv ${LSST} -o ${CSV_TMP}/lsst_note.json)
cemv_cli_test(NAME cli_import_csv_sheet_layout_with_records_refused EXIT 2
  MATCH "--separator, --name and --orientation apply to grids, not to --layout records \\(so do --sheet-layout and --save-layout\\)"
  COMMAND $<TARGET_FILE:cemv> import-csv ${CSV_CASES}/tab_grid.tsv --layout records --sheet-layout ${CSV_TMP}/bad_layout.json)
cemv_cli_test(NAME cli_import_workbook_sheet_for_six_tables_refused EXIT 2
  MATCH "holds the six tables of 6.6.2 \\(sheet 'Causes configuration'\\), which say where everything is"
  COMMAND bash -c "$0 export-workbook examples/tank-overfill/matrix.json -o ${CSV_TMP}/tables.ods && $0 import-workbook ${CSV_TMP}/tables.ods --sheet 2" $<TARGET_FILE:cemv>)
