# Plant parameters (cemv-params/1, docs/params.md), import records and
# encodings (docs/format.md "Provenance", docs/csv.md): the library, then the
# command line.
add_executable(test_formats_params ${CMAKE_CURRENT_LIST_DIR}/test_params.cpp)
target_link_libraries(test_formats_params PRIVATE cemv_formats cemv_sheets GTest::gtest_main nlohmann_json::nlohmann_json)
gtest_discover_tests(test_formats_params DISCOVERY_MODE PRE_TEST)

set(PARAMS_CASES tests/formats/params_cases)
set(PARAMS_TMP ${CMAKE_CURRENT_BINARY_DIR}/params_cli)
file(MAKE_DIRECTORY ${PARAMS_TMP})
# import-csv --params: the parameters applied, said, recorded; the defaults left stated.
cemv_cli_test(NAME cli_import_csv_params EXIT 0
  MATCH "note: parameters small.params.json \\(sha256 [0-9a-f]+...\\): set 6 values, 1 footnote explained, 1 limitation stated"
  COMMAND $<TARGET_FILE:cemv> import-csv ${PARAMS_CASES}/small.csv --params ${PARAMS_CASES}/small.params.json
          -o ${PARAMS_TMP}/small.json)
# Without parameters, every default the grid import adopts is stated.
cemv_cli_test(NAME cli_import_csv_states_defaults EXIT 0
  MATCH "^  2 of 2 causes: the operator may soft-bypass it without time limit"
  COMMAND $<TARGET_FILE:cemv> import-csv ${PARAMS_CASES}/small.csv -o ${PARAMS_TMP}/plain.json)
# apply-params on an imported matrix gives the same matrix as import --params.
cemv_cli_test(NAME cli_apply_params_same_as_import EXIT 0 MATCH "^same$"
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/params_cases/apply_same_as_import.sh $<TARGET_FILE:cemv> ${PARAMS_CASES}
          ${PARAMS_TMP}/same)
cemv_cli_test(NAME cli_apply_params_error_place EXIT 2
  MATCH "bad.params.json:4:5: error: effects\\['A-9'\\]: the matrix has no effect named 'A-9'"
  COMMAND $<TARGET_FILE:cemv> apply-params ${PARAMS_TMP}/plain.json ${PARAMS_CASES}/bad.params.json)
set_tests_properties(cli_apply_params_error_place PROPERTIES DEPENDS cli_import_csv_states_defaults)
# Encodings: a Latin-1 sheet is refused at its byte, or read with --encoding.
cemv_cli_test(NAME cli_import_csv_latin1_refused EXIT 2
  MATCH "latin1.csv:3:8: error: byte 0xDC is not UTF-8: .*give --encoding windows-1252"
  COMMAND $<TARGET_FILE:cemv> import-csv ${PARAMS_CASES}/latin1.csv)
cemv_cli_test(NAME cli_import_csv_latin1_as_windows_1252 EXIT 0 MATCH "\"description\": \"Azimut Überdrehzahl\""
  COMMAND $<TARGET_FILE:cemv> import-csv ${PARAMS_CASES}/latin1.csv --encoding windows-1252 -q)
cemv_cli_test(NAME cli_import_csv_latin1_recorded EXIT 0 MATCH "\"encoding\": \"Windows-1252\""
  COMMAND $<TARGET_FILE:cemv> import-csv ${PARAMS_CASES}/latin1.csv --encoding windows-1252 -q)
