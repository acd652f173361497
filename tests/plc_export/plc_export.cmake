# `cemv export-st` (docs/plc.md "Generated programs"): the generated programs
# read back, their maps complete, their interpreter against the matrix runtime.
if(TARGET cemv_plc_export AND TARGET cemv_plc_check)
  add_executable(test_plc_export ${CMAKE_CURRENT_LIST_DIR}/test_export.cpp)
  target_link_libraries(test_plc_export PRIVATE cemv_plc_export cemv_plc_check cemv_runtime cemv_testsupport
                        GTest::gtest_main)
  target_compile_definitions(test_plc_export PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_plc_export DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 900)
endif()
