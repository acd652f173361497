# Workbooks (6.6, docs/workbook.md): ODS and XLSX, the six tables, limits.
add_executable(test_sheets_workbook ${CMAKE_CURRENT_LIST_DIR}/test_workbook.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_workbook_malformed.cpp ${CMAKE_CURRENT_LIST_DIR}/test_workbook_formats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_workbook_vendor.cpp)
target_link_libraries(test_sheets_workbook PRIVATE cemv_sheets cemv_testsupport GTest::gtest_main pugixml::pugixml)
target_compile_definitions(test_sheets_workbook PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_sheets_workbook DISCOVERY_MODE PRE_TEST)

set(WB_CASES ${CMAKE_CURRENT_LIST_DIR}/workbook_cases)
# The table of malformed workbooks through the binary: each exits 2 with its message.
set(_wb_malformed ${CMAKE_CURRENT_LIST_DIR}/workbook_malformed)
file(STRINGS ${_wb_malformed}/EXPECTED.tsv _wb_rows REGEX "^[^#]")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_wb_malformed}/EXPECTED.tsv)
foreach(_row IN LISTS _wb_rows)
  string(FIND "${_row}" "\t" _tab)
  string(SUBSTRING "${_row}" 0 ${_tab} _file)
  string(REGEX REPLACE "[^A-Za-z0-9]" "_" _name "${_file}")
  # The binary names the file by its path: match the message after the name.
  math(EXPR _start "${_tab} + 1")
  string(SUBSTRING "${_row}" ${_start} -1 _regex)
  string(REGEX REPLACE "^\\^" "" _regex "${_regex}")
  cemv_cli_test(NAME cli_import_workbook_malformed_${_name} EXIT 2 MATCH "${_regex}"
    COMMAND $<TARGET_FILE:cemv> import-workbook tests/sheets/workbook_malformed/${_file})
endforeach()
set(WB_TMP ${CMAKE_CURRENT_BINARY_DIR}/workbook_cli)
file(MAKE_DIRECTORY ${WB_TMP})
# Every example through the command line, both formats: the same signature back.
file(GLOB wb_example_matrices RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/*/matrix.json)
foreach(matrix ${wb_example_matrices})
  get_filename_component(example_dir ${matrix} DIRECTORY)
  get_filename_component(example ${example_dir} NAME)
  cemv_cli_test(NAME cli_workbook_round_trip_${example} EXIT 0 MATCH "xlsx: same signature [0-9a-f]+"
    COMMAND bash ${WB_CASES}/cli_round_trip.sh $<TARGET_FILE:cemv> ${matrix} ${WB_TMP}/round_trip)
endforeach()
cemv_cli_test(NAME cli_import_workbook_missing_file EXIT 2 MATCH "no_such.ods: error: cannot open"
  COMMAND $<TARGET_FILE:cemv> import-workbook ${WB_CASES}/no_such.ods)
cemv_cli_test(NAME cli_import_workbook_not_a_zip EXIT 2
  MATCH "matrix.json: error: not a workbook: the file is not a readable zip archive"
  COMMAND $<TARGET_FILE:cemv> import-workbook examples/tank-overfill/matrix.json)
cemv_cli_test(NAME cli_export_workbook_bad_extension EXIT 2 MATCH "must end in .ods or .xlsx"
  COMMAND $<TARGET_FILE:cemv> export-workbook examples/tank-overfill/matrix.json -o ${WB_TMP}/m.txt)
cemv_cli_test(NAME cli_export_workbook_needs_output EXIT 2 MATCH "output"
  COMMAND $<TARGET_FILE:cemv> export-workbook examples/tank-overfill/matrix.json)
# 6.6.3: after an import into an existing matrix, what changed.
cemv_cli_test(NAME cli_import_workbook_into EXIT 0
  MATCH "matrix comparison \\(6.6.3\\), source .*edited.xlsx, reference .*matrix.json: 1 change, 1 critical.*time.ms: 2000 -> 5000"
  COMMAND bash ${WB_CASES}/cli_into.sh $<TARGET_FILE:cemv> examples/tank-overfill/matrix.json ${WB_TMP}/into)
cemv_cli_test(NAME cli_import_workbook_into_unchanged EXIT 0 MATCH "reference .*: no change"
  COMMAND bash -c "$<TARGET_FILE:cemv> export-workbook examples/compressor/matrix.json -o ${WB_TMP}/same.ods && $<TARGET_FILE:cemv> import-workbook ${WB_TMP}/same.ods --into examples/compressor/matrix.json -o ${WB_TMP}/same.json")

# Real spreadsheet software (LibreOffice, headless): a workbook re-saved by it
# (every example and edge-values) imports with the same signature; the LSST table saved as XLSX imports as its CSV.
# Each run has its own LibreOffice profile, so these run in parallel.
find_program(SOFFICE soffice)
if(SOFFICE)
  # add_test, not cemv_cli_test: LibreOffice may take longer than its 120 s on a loaded machine.
  add_test(NAME cli_workbook_libreoffice_examples
    COMMAND bash ${WB_CASES}/libreoffice_round_trip.sh $<TARGET_FILE:cemv> ${SOFFICE} ${WB_TMP}/libreoffice_examples
            ${wb_example_matrices} tests/sheets/workbook_cases/edge-values/matrix.json
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  # edge-values: texts with runs of blanks, leading and trailing blanks, '; ' in notes, the REAL extremes.
  list(LENGTH wb_example_matrices wb_examples)
  math(EXPR wb_examples "${wb_examples} + 1")
  set_tests_properties(cli_workbook_libreoffice_examples PROPERTIES TIMEOUT 600
    PASS_REGULAR_EXPRESSION "all ${wb_examples} matrices: same signature after LibreOffice re-saved them")
  add_test(NAME cli_workbook_libreoffice_lsst
    COMMAND ${CEMV_WITH_LSST} bash ${WB_CASES}/libreoffice_lsst.sh $<TARGET_FILE:cemv> ${SOFFICE}
            ${CEMV_LSST_DIR}/lsst-tma-interlock-table.csv ${WB_TMP}/libreoffice_lsst
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli_workbook_libreoffice_lsst PROPERTIES TIMEOUT 600
    PASS_REGULAR_EXPRESSION "LSST saved as XLSX by LibreOffice imports as its CSV: 36 causes, 17 effects, 102 intersections")
  cemv_external_test(cli_workbook_libreoffice_lsst)
  # A contractor's SIS workbook (docs/workbook.md "Vendor C&E workbooks"), built
  # by LibreOffice from the committed flat ODS as XLSX, ODS and the CSV of its
  # matrix sheet: every variant read right or refused with the cell named.
  add_test(NAME cli_workbook_libreoffice_vendor
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/vendor_cases/vendor_workbook.sh $<TARGET_FILE:cemv> ${SOFFICE}
            ${CMAKE_CURRENT_LIST_DIR}/vendor_cases ${WB_TMP}/libreoffice_vendor
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli_workbook_libreoffice_vendor PROPERTIES TIMEOUT 600
    PASS_REGULAR_EXPRESSION "vendor workbook: all [0-9]+ variants read right \\(signature [0-9a-f]+\\) or refused with the cell named; none misread")
endif()

# Output is never lost silently (README): a full disk is exit 2 naming the
# destination, an unwritable -o fails before the work, '-' reads standard input.
set(_wb_tank examples/tank-overfill/matrix.json)
cemv_cli_test(NAME cli_devfull_export_workbook EXIT 2 MATCH "^error: /dev/full: cannot write: No space left on device$"
  COMMAND $<TARGET_FILE:cemv> export-workbook ${_wb_tank} -o /dev/full --format ods)
cemv_cli_test(NAME cli_devfull_export_workbook_stdout EXIT 2 MATCH "^error: <stdout>: cannot write: No space left on device$"
  COMMAND bash -c "$0 export-workbook ${_wb_tank} -o - --format xlsx > /dev/full" $<TARGET_FILE:cemv>)
cemv_cli_test(NAME cli_devfull_import_workbook EXIT 2 MATCH "error: <stdout>: cannot write: No space left on device"
  COMMAND bash -c "$0 export-workbook ${_wb_tank} -o ${WB_TMP}/full.ods && $0 import-workbook ${WB_TMP}/full.ods > /dev/full" $<TARGET_FILE:cemv>)
cemv_cli_test(NAME cli_export_workbook_unwritable EXIT 2 MATCH "^error: /no/such/dir/x.ods: cannot write: No such file or directory$"
  COMMAND $<TARGET_FILE:cemv> export-workbook ${_wb_tank} -o /no/such/dir/x.ods)
cemv_cli_test(NAME cli_import_workbook_stdin EXIT 0 MATCH "<stdin>: note: read 4 causes, 3 effects and 8 intersections from the six tables"
  COMMAND bash -c "$0 export-workbook ${_wb_tank} -o ${WB_TMP}/stdin.xlsx && $0 import-workbook - -o ${WB_TMP}/stdin.json < ${WB_TMP}/stdin.xlsx" $<TARGET_FILE:cemv>)

# The stacked effect headers of docs/csv.md "Stacked effect header", saved by
# LibreOffice as XLSX and ODS: read as their CSV, the output tags as the tags.
if(SOFFICE)
  add_test(NAME cli_workbook_libreoffice_stacked_headers
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/stacked_cases/stacked_workbooks.sh $<TARGET_FILE:cemv> ${SOFFICE}
            ${CMAKE_CURRENT_LIST_DIR}/stacked_cases ${WB_TMP}/libreoffice_stacked
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli_workbook_libreoffice_stacked_headers PROPERTIES TIMEOUT 600
    PASS_REGULAR_EXPRESSION "stacked effect headers: all 5 variants read alike from CSV, XLSX and ODS")
endif()
