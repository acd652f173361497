# cemv response at the command line: the tank example's seeded defect (SIF 2
# responds 1.7 s after its process safety time, examples/tank-overfill/README.md)
# exits 1 naming the SIF, the path and the margin; bad options exit 2.
if(TARGET cemv_response)
  cemv_cli_test(NAME response_cli_seeded_defect EXIT 1
    MATCH "over: SIF 2, cause 4 -> effect 3: logic 50 cycles \\(5000 ms\\), total 6700 ms, process safety time 5000 ms, margin -1700 ms \\(-34.0 %\\)"
    COMMAND $<TARGET_FILE:cemv> response examples/tank-overfill/matrix.json --sif 2)
  cemv_cli_test(NAME response_cli_json_schema EXIT 1
    MATCH "\"schema\": \"cemv-response/1\""
    COMMAND $<TARGET_FILE:cemv> response examples/tank-overfill/matrix.json --sif 2 --format json)
  cemv_cli_test(NAME response_cli_unknown_sif EXIT 2 MATCH "declares no SIF group 9"
    COMMAND $<TARGET_FILE:cemv> response examples/tank-overfill/matrix.json --sif 9)
  cemv_cli_test(NAME response_cli_bad_format EXIT 2 MATCH "not a format"
    COMMAND $<TARGET_FILE:cemv> response examples/tank-overfill/matrix.json --format xml)
  cemv_cli_test(NAME response_cli_conservative_needs_watchdog EXIT 2 MATCH "watchdog_ms"
    COMMAND $<TARGET_FILE:cemv> response tests/response/no_watchdog.json --conservative)
endif()
