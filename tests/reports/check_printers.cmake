# The printers of `cemv check` results (reports/check_*.hpp, docs/checker.md).
add_executable(test_reports_check_printers ${CMAKE_CURRENT_LIST_DIR}/test_check_printers.cpp)
target_link_libraries(test_reports_check_printers PRIVATE cemv_reports nlohmann_json::nlohmann_json GTest::gtest_main)
target_compile_definitions(test_reports_check_printers PRIVATE CEMV_GOLDEN_DIR="${CMAKE_CURRENT_LIST_DIR}/golden")
gtest_discover_tests(test_reports_check_printers DISCOVERY_MODE PRE_TEST)
# The golden files are what the printers write (the test above): check them
# as a CI server would read them.
add_test(NAME reports_check_junit_parses_as_xml
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/validate_outputs.py junit ${CMAKE_CURRENT_LIST_DIR}/golden/check.junit.xml 7 4 1)
add_test(NAME reports_check_sarif_required_fields
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/validate_outputs.py sarif ${CMAKE_CURRENT_LIST_DIR}/golden/check.sarif 5)
add_test(NAME reports_check_json_schema_fields
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/validate_outputs.py json ${CMAKE_CURRENT_LIST_DIR}/golden/check.json 7)
