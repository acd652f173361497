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
# The outputs' cones and their groups.
if(TARGET cemv_plc_check AND TARGET cemv_plc)
  add_executable(test_plc_cones ${CMAKE_CURRENT_LIST_DIR}/test_plc_cones.cpp)
  target_link_libraries(test_plc_cones PRIVATE cemv_plc_check GTest::gtest_main)
  gtest_discover_tests(test_plc_cones DISCOVERY_TIMEOUT 60)
endif()
# plc-check on the tank example: the hand-written program and its three seeded errors.
if(TARGET cemv_plc_check AND TARGET cemv_plc)
  add_executable(test_plc_check ${CMAKE_CURRENT_LIST_DIR}/test_plc_check.cpp)
  target_link_libraries(test_plc_check PRIVATE cemv_plc_check GTest::gtest_main)
  target_compile_definitions(test_plc_check PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_plc_check DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endif()
# The command line: the hand-written program proved equal and safe-side on
# every output (exit 0), each seeded error refuted with the output named
# (exit 1), an incomplete map (exit 2). No --timeout: a verdict that does
# not depend on the machine's load.
if(TARGET cemv_plc_check AND TARGET cemv_plc)
  set(PLC_TANK ${PROJECT_SOURCE_DIR}/examples/tank-overfill)
  cemv_cli_test(NAME cli_plc_check_reset_dominant_exit1 EXIT 1
    MATCH "XV_101 \\(effect 1 CLOSE_XV101\\) = XV_101: differs in scan 1: matrix 0, program 1.*tank_t100_reset_dominant.st:118:1"
    COMMAND bash -c "set -o pipefail && \"$1\" plc-check \"$2\"/matrix.json \"$2\"/plc/tank_t100_reset_dominant.st --map \"$2\"/plc/tank_t100.map.json | tr '\\n' ' '" plc
            $<TARGET_FILE:cemv> ${PLC_TANK})
  set(PLC_RUN "set -o pipefail && \"$1\" plc-check \"$2\"/matrix.json \"$2\"/plc/$3.st --map \"$2\"/plc/tank_t100.map.json $4 | tr '\\n' ' '")
  cemv_cli_test(NAME cli_plc_check_tank_equal_exit0 EXIT 0
    MATCH "XV_101 \\(effect 1 CLOSE_XV101\\) = XV_101: proved by correspondence invariants P_101_RUN \\(effect 2 STOP_P101\\) = P_101_RUN: proved by correspondence invariants P_102_RUN \\(effect 3 STOP_P102\\) = P_102_RUN: proved by correspondence invariants 3 outputs: 3 equal, 0 differ, 0 unknown"
    COMMAND bash -c "${PLC_RUN}" plc $<TARGET_FILE:cemv> ${PLC_TANK} tank_t100 "")
  cemv_cli_test(NAME cli_plc_check_tank_safe_side_exit0 EXIT 0
    MATCH "3 outputs: 3 safe-side, 0 differ, 0 unknown"
    COMMAND bash -c "${PLC_RUN}" plc $<TARGET_FILE:cemv> ${PLC_TANK} tank_t100 "--relation safe-side")
  cemv_cli_test(NAME cli_plc_check_off_delay_exit1 EXIT 1
    MATCH "P_101_RUN \\(effect 2 STOP_P101\\) = P_101_RUN: differs in scan 1: matrix 1, program 0.*P_102_RUN \\(effect 3 STOP_P102\\) = P_102_RUN: proved"
    COMMAND bash -c "${PLC_RUN}" plc $<TARGET_FILE:cemv> ${PLC_TANK} tank_t100_off_delay "")
  cemv_cli_test(NAME cli_plc_check_one_of_three_exit1 EXIT 1
    MATCH "XV_101 \\(effect 1 CLOSE_XV101\\) = XV_101: differs in scan 21: matrix 1, program 0.*P_101_RUN \\(effect 2 STOP_P101\\) = P_101_RUN: differs in scan 21: matrix 1, program 0"
    COMMAND bash -c "${PLC_RUN}" plc $<TARGET_FILE:cemv> ${PLC_TANK} tank_t100_one_of_three "")
  # The 1oo3 copy's P_101_RUN run holds LT_100B at its limit from the first
  # scan without changing it: the diagram draws it all the same, and not
  # LT_102, which the run leaves at rest (the reduction left it out).
  cemv_cli_test(NAME cli_plc_check_diagram_draws_held_inputs EXIT 0
    MATCH "held inputs drawn"
    COMMAND bash -c "\"$1\" plc-check \"$2\"/matrix.json \"$2\"/plc/tank_t100_one_of_three.st --map \"$2\"/plc/tank_t100.map.json --out \"$3\" -q 2>/dev/null && exit 9 || test $? -eq 1 && grep -q '>LT_100B<' \"$3\"/plc.P_101_RUN.svg && ! grep -q '>LT_102<' \"$3\"/plc.P_101_RUN.svg && echo held inputs drawn"
            plc $<TARGET_FILE:cemv> ${PLC_TANK} ${CMAKE_BINARY_DIR}/plc_check/diagram_1oo3)
  cemv_cli_test(NAME cli_plc_check_no_map_exit2 EXIT 2
    MATCH "tank_t100.st: error: operator commands the matrix accepts without a program variable"
    COMMAND $<TARGET_FILE:cemv> plc-check ${PLC_TANK}/matrix.json ${PLC_TANK}/plc/tank_t100.st)
endif()
# The runs that trip an effect's causes together.
if(TARGET cemv_plc_check AND TARGET cemv_plc)
  add_executable(test_plc_sampling ${CMAKE_CURRENT_LIST_DIR}/test_plc_sampling.cpp)
  target_link_libraries(test_plc_sampling PRIVATE cemv_plc_check cemv_formats GTest::gtest_main)
  target_compile_definitions(test_plc_sampling PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_plc_sampling DISCOVERY_TIMEOUT 60)
endif()
# A Houdini query's premise without the clauses its equalities repeat.
if(TARGET cemv_plc_check AND TARGET cemv_plc)
  add_executable(test_plc_premise ${CMAKE_CURRENT_LIST_DIR}/test_plc_premise.cpp)
  target_link_libraries(test_plc_premise PRIVATE cemv_plc_check GTest::gtest_main)
  gtest_discover_tests(test_plc_premise DISCOVERY_TIMEOUT 60)
endif()
# The correspondence templates: which guarded equalities are candidates.
if(TARGET cemv_plc_check AND TARGET cemv_plc)
  add_executable(test_plc_templates ${CMAKE_CURRENT_LIST_DIR}/test_plc_templates.cpp)
  target_link_libraries(test_plc_templates PRIVATE cemv_plc_check GTest::gtest_main)
  gtest_discover_tests(test_plc_templates DISCOVERY_TIMEOUT 60)
endif()
