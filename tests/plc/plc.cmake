# The PLC program front end and interpreter (docs/plc.md): the ST parser and
# its refusals, PLCopen XML, the printer's round trip on seeded random
# programs, the standard blocks on hand-computed scan sequences.
if(TARGET cemv_plc)
  add_executable(test_plc
    ${CMAKE_CURRENT_LIST_DIR}/test_parser.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_refused.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_plcopen.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_plcopen_variants.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_round_trip.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_st_variants.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_interpreter.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_blocks.cpp)
  target_link_libraries(test_plc PRIVATE cemv_plc GTest::gtest_main)
  gtest_discover_tests(test_plc DISCOVERY_MODE PRE_TEST)
endif()
