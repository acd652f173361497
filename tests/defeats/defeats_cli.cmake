# cemv defeats at the command line (docs/defeats.md): an override of another
# effect read through Effect[2] is an indirect defeat of one action, which the
# gate --require-distance 2 fails on the SIL 2 group; bad options exit 2.
if(TARGET cemv_defeats)
  set(_m tests/defeats/through_override.json)
  cemv_cli_test(NAME defeats_cli_text EXIT 0
    MATCH "cause 1 -> effect 1 +0 +3 +1 +\\{cause_bypass_tag\\[BYP1\\]\\} +declared"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m})
  cemv_cli_test(NAME defeats_cli_gate EXIT 1
    MATCH "gate: SIF 1, cause 1 -> effect 1: 2 minimal defeat sets up to size 2 \\(1 declared, 1 indirect\\); defeat distance 1, below --require-distance 2 \\(SIL 2\\)"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --require-distance 2)
  cemv_cli_test(NAME defeats_cli_gate_met EXIT 0 MATCH "defeat distance 1"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --require-distance 1 --format junit)
  cemv_cli_test(NAME defeats_cli_json_schema EXIT 0 MATCH "\"schema\": \"cemv-defeats/1\""
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --format json)
  cemv_cli_test(NAME defeats_cli_junit_failure EXIT 1 MATCH "<failure"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --format junit --require-distance 2)
  cemv_cli_test(NAME defeats_cli_sarif_error EXIT 1 MATCH "\"level\": \"error\""
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --format sarif --require-distance 2)
  cemv_cli_test(NAME defeats_cli_unknown_sif EXIT 2 MATCH "declares no SIF group 9"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --sif 9)
  cemv_cli_test(NAME defeats_cli_bad_format EXIT 2 MATCH "not a format"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --format xml)
  cemv_cli_test(NAME defeats_cli_negative_size EXIT 2 MATCH "--max-size must not be negative"
    COMMAND $<TARGET_FILE:cemv> defeats ${_m} --max-size -1)
  cemv_cli_test(NAME defeats_cli_bad_matrix EXIT 2 MATCH "error:"
    COMMAND $<TARGET_FILE:cemv> defeats tests/defeats/defeats_cli.cmake)
endif()
# --out: each minimal set's counterexample as cemv-scenario/1, which cemv
# simulate replays on the runtime with its expectations met (exit 0).
if(TARGET cemv_defeats)
  set(_out ${CMAKE_CURRENT_BINARY_DIR}/defeats_cli_out)
  cemv_cli_test(NAME defeats_cli_out_replays EXIT 0 MATCH "defeat.c1.e1.a3.scenario.json"
    COMMAND bash -c "rm -rf ${_out} && $<TARGET_FILE:cemv> defeats tests/defeats/through_override.json --out ${_out} && $<TARGET_FILE:cemv> simulate tests/defeats/through_override.json ${_out}/defeat.c1.e1.a3.scenario.json > /dev/null && $<TARGET_FILE:cemv> simulate tests/defeats/through_override.json ${_out}/defeat.c1.e1.a1.scenario.json > /dev/null")
endif()
# The committed defeat sets of every example carry the signature of the matrix
# as it is now (a stale report fails), and the evidence report takes them.
if(TARGET cemv_defeats)
  foreach(ex burner-management compressor pipeline-hipps tank-overfill)
    add_test(NAME defeats_signature_${ex} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
      COMMAND bash -c "grep -q \"\\\"matrix_signature\\\": \\\"$(${PROJECT_BINARY_DIR}/cemv signature examples/${ex}/matrix.json)\\\"\" examples/${ex}/defeats.json")
  endforeach()
  cemv_cli_test(NAME defeats_cli_evidence_marks EXIT 0 MATCH "defeat1"
    COMMAND bash -c "$<TARGET_FILE:cemv> evidence examples/compressor/matrix.json --defeats examples/compressor/defeats.json --out ${CMAKE_CURRENT_BINARY_DIR}/defeats_evidence.html -q && grep -o 'cause defeat1' ${CMAKE_CURRENT_BINARY_DIR}/defeats_evidence.html | head -1 | sed 's/cause //'")
  cemv_cli_test(NAME defeats_cli_evidence_refuses_other_matrix EXIT 2 MATCH "regenerate them"
    COMMAND $<TARGET_FILE:cemv> evidence examples/tank-overfill/matrix.json --defeats examples/compressor/defeats.json --out ${CMAKE_CURRENT_BINARY_DIR}/refused.html)
endif()
# --response: each path's T taken from cemv response's report of the same
# matrix gives the same report, byte for byte, as proving it again; a report
# of another matrix is refused (exit 2).
if(TARGET cemv_defeats AND TARGET cemv_response)
  set(_r ${CMAKE_CURRENT_BINARY_DIR}/defeats_cli_response)
  cemv_cli_test(NAME defeats_cli_response_same_report EXIT 0 MATCH "same report"
    COMMAND bash -c "mkdir -p ${_r} && $<TARGET_FILE:cemv> response tests/defeats/through_override.json --format json -o ${_r}/r.json && $<TARGET_FILE:cemv> defeats tests/defeats/through_override.json --format json -o ${_r}/again.json && $<TARGET_FILE:cemv> defeats tests/defeats/through_override.json --response ${_r}/r.json --format json -o ${_r}/given.json && cmp ${_r}/again.json ${_r}/given.json && echo same report")
  cemv_cli_test(NAME defeats_cli_response_other_matrix EXIT 2 MATCH "matrix_signature: these results are for the matrix with signature"
    COMMAND bash -c "mkdir -p ${_r} && ($<TARGET_FILE:cemv> response examples/tank-overfill/matrix.json --sif 1 --format json -o ${_r}/tank.json || true) && $<TARGET_FILE:cemv> defeats tests/defeats/through_override.json --response ${_r}/tank.json")
endif()
