# The configuration report (11.4, docs/reports.md).
add_executable(test_reports_config_report ${CMAKE_CURRENT_LIST_DIR}/test_report.cpp)
target_link_libraries(test_reports_config_report PRIVATE cemv_reports GTest::gtest_main)
gtest_discover_tests(test_reports_config_report DISCOVERY_MODE PRE_TEST)

set(REPORT_TMP ${CMAKE_CURRENT_BINARY_DIR}/report_cli)
file(MAKE_DIRECTORY ${REPORT_TMP})
cemv_cli_test(NAME cli_report_md EXIT 0 MATCH "Matrix signature \\(SHA-256 of the canonical form\\): `[0-9a-f]{64}`"
  COMMAND $<TARGET_FILE:cemv> report examples/tank-overfill/matrix.json)
cemv_cli_test(NAME cli_report_html EXIT 0 MATCH "<!DOCTYPE html>"
  COMMAND $<TARGET_FILE:cemv> report examples/burner-management/matrix.json --format html)
cemv_cli_test(NAME cli_report_json EXIT 0 MATCH "\"format\": \"cemv-report/1\""
  COMMAND $<TARGET_FILE:cemv> report examples/pipeline-hipps/matrix.json --format json)
# Same bytes twice in every format (stdout and -o); the signature at the top and the bottom.
cemv_cli_test(NAME cli_report_deterministic EXIT 0 MATCH "deterministic, signature [0-9a-f]{64}"
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/cli_report_deterministic.sh $<TARGET_FILE:cemv>
          examples/compressor/matrix.json ${REPORT_TMP})
cemv_cli_test(NAME cli_report_bad_format EXIT 2 MATCH "format"
  COMMAND $<TARGET_FILE:cemv> report examples/tank-overfill/matrix.json --format pdf)
cemv_cli_test(NAME cli_report_missing_file EXIT 2 MATCH "error:"
  COMMAND $<TARGET_FILE:cemv> report tests/sheets/csv_cases/no_such_matrix.json)
