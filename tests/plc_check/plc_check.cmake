# `cemv plc-check` (docs/plc.md): the map between a matrix and a program.
if(TARGET cemv_plc_check)
  add_executable(test_plc_map ${CMAKE_CURRENT_LIST_DIR}/test_plc_map.cpp)
  target_link_libraries(test_plc_map PRIVATE cemv_plc_check cemv_formats GTest::gtest_main)
  target_compile_definitions(test_plc_map PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_plc_map DISCOVERY_TIMEOUT 60)
endif()
# The program's two semantics, interpreter and encoding, on seeded random programs.
if(TARGET cemv_plc_encoder)
  add_executable(test_plc_encoder_diff ${CMAKE_CURRENT_LIST_DIR}/test_plc_encoder_diff.cpp)
  target_link_libraries(test_plc_encoder_diff PRIVATE cemv_plc_encoder cemv_plc GTest::gtest_main)
  gtest_discover_tests(test_plc_encoder_diff DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
endif()
