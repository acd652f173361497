# `cemv check` on the real checker (examples/tank-overfill): the command end to
# end. Defined once the checker and the property language are built.
if(TARGET cemv_checker AND TARGET cemv_properties)
  set(_tank examples/tank-overfill/matrix.json)
  set(_c ${CMAKE_CURRENT_LIST_DIR}/check_cases)
  set(_tmp ${CMAKE_CURRENT_BINARY_DIR}/check_real)
  cemv_cli_test(NAME cli_check_real_tank_text EXIT 1
    MATCH "FALSIFIED +cli.bypass_keeps_xv101_open"
    COMMAND $<TARGET_FILE:cemv> check ${_tank} ${_c}/tank_small.props)
  cemv_cli_test(NAME cli_check_real_formats_valid_and_deterministic EXIT 0 MATCH "formats valid and deterministic"
    COMMAND bash ${_c}/run_formats.sh $<TARGET_FILE:cemv> ${_tank} ${_c}/tank_small.props 1 ${_tmp}/formats 3 1 0 1)
  cemv_cli_test(NAME cli_check_real_counterexample_replays EXIT 0 MATCH "counterexamples replayed: 1"
    COMMAND bash ${_c}/replay_cex.sh $<TARGET_FILE:cemv> ${_tank} ${_c}/tank_small.props ${_tmp}/replay)
  cemv_cli_test(NAME cli_check_real_property_error_exit_2 EXIT 2 MATCH "bad_real.props:1:[0-9]+: .*actve"
    COMMAND $<TARGET_FILE:cemv> check ${_tank} ${_c}/bad_real.props)
  cemv_cli_test(NAME cli_check_real_shards_partition EXIT 0 MATCH "3 shards partition 3 properties"
    COMMAND bash ${_c}/shards.sh $<TARGET_FILE:cemv> ${_tank} ${_c}/tank_small.props)
endif()
