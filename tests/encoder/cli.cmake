# `cemv export-smt` through the CLI (docs/encoding.md, "Export"), with a second solver.
set(_hipps ${PROJECT_SOURCE_DIR}/examples/pipeline-hipps/matrix.json)
cemv_cli_test(NAME cli_export_smt_cvc5_reach_sat EXIT 0 MATCH "^sat"
  COMMAND bash -c "$<TARGET_FILE:cemv> export-smt ${_hipps} --roots effect:1 --depth 3 --reach 'effect[1].active' -o ${CMAKE_CURRENT_BINARY_DIR}/hipps_reach.smt2 && cvc5 --lang smt2 ${CMAKE_CURRENT_BINARY_DIR}/hipps_reach.smt2")
cemv_cli_test(NAME cli_export_smt_cvc5_trivial_unsat EXIT 0 MATCH "^unsat"
  COMMAND bash -c "$<TARGET_FILE:cemv> export-smt ${_hipps} --roots effect:1 --depth 2 | cvc5 --lang smt2")
cemv_cli_test(NAME cli_export_vmt EXIT 0 MATCH ":invar-property 0"
  COMMAND $<TARGET_FILE:cemv> export-smt ${_hipps} --format vmt --roots effect:1 --property "effect[1].active")
cemv_cli_test(NAME cli_export_smt_bad_roots_exit_2 EXIT 2 MATCH "bad root 'valve:1'"
  COMMAND $<TARGET_FILE:cemv> export-smt ${_hipps} --roots valve:1)
cemv_cli_test(NAME cli_export_smt_unknown_root_exit_2 EXIT 2 MATCH "no processed effect\\[999\\]"
  COMMAND $<TARGET_FILE:cemv> export-smt ${_hipps} --roots effect:999)
cemv_cli_test(NAME cli_export_smt_unknown_property_exit_2 EXIT 2 MATCH "no term named 'effect\\[1\\].nope'"
  COMMAND $<TARGET_FILE:cemv> export-smt ${_hipps} --property "effect[1].nope")
cemv_cli_test(NAME cli_export_smt_bad_format_exit_2 EXIT 2 MATCH "format"
  COMMAND $<TARGET_FILE:cemv> export-smt ${_hipps} --format dimacs)
cemv_cli_test(NAME cli_export_smt_missing_file_exit_2 EXIT 2 MATCH "no_such_matrix.json"
  COMMAND $<TARGET_FILE:cemv> export-smt no_such_matrix.json)

# Independence (docs/architecture.md, "Two independent implementations"): nothing under encoder/ includes the runtime.
cemv_cli_test(NAME encoder_does_not_include_runtime EXIT 1
  COMMAND grep -rnE "#include *[<\"](\\.\\./)*runtime/" ${PROJECT_SOURCE_DIR}/encoder)
