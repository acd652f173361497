# The direction of every dependency (docs/architecture.md): model/ includes
# nothing of cemv but model/; runtime/ and encoder/ include only model/ (and
# themselves); formats/ only model/; sheets/ only model/ and formats/;
# reports/ only model/ and formats/ (and checker/result.hpp). Of the code
# folders only cli/ includes sheets/.
# grep exits 1 when no include breaks the rule.
set(_cemv_inc "#include *[<\"](\\.\\./)*")
cemv_cli_test(NAME layout_model_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(formats|reports|runtime|encoder|plc|properties|checker|testgen|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/model)
cemv_cli_test(NAME layout_runtime_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(formats|reports|encoder|properties|checker|testgen|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/runtime)
cemv_cli_test(NAME layout_encoder_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(formats|reports|runtime|properties|checker|testgen|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/encoder)
# plc/ uses model and formats only: never the matrix's runtime or encoder,
# nor anything above them.
cemv_cli_test(NAME layout_plc_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|encoder|properties|checker|testgen|mutate|diff|response|defeats|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/plc)
cemv_cli_test(NAME layout_formats_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|encoder|plc|properties|checker|testgen|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/formats)
# sheets/, the readers of foreign sheets, stand on formats/ and model/ alone;
# formats/ (cemv's own formats) never includes them.
cemv_cli_test(NAME layout_sheets_includes_only_formats_and_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|encoder|plc|plc_encoder|plc_check|properties|checker|testgen|mutate|diff|response|defeats|cli)/"
          ${PROJECT_SOURCE_DIR}/sheets)
# reports/ may also include checker/result.hpp, the plain data the check
# printers render (and nothing else of checker/).
cemv_cli_test(NAME layout_reports_includes_only_model_and_formats EXIT 1
  COMMAND bash -c "grep -rnE '${_cemv_inc}(runtime|encoder|properties|checker|testgen|cli|sheets)/' ${PROJECT_SOURCE_DIR}/reports | grep -v 'checker/result.hpp\"'"
)
# diff/ uses the checker, runtime, formats, model and reports' SARIF helpers;
# never the command line, the test generator, mutation or response time.
cemv_cli_test(NAME layout_diff_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(properties|encoder|testgen|mutate|response|cli|sheets)/" ${PROJECT_SOURCE_DIR}/diff)
# properties/ uses model, formats and encoder (the monitor) only.
cemv_cli_test(NAME layout_properties_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|checker|testgen|mutate|diff|response|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/properties)
# checker/ uses the layers below it; never reports, the consumers or the CLI.
cemv_cli_test(NAME layout_checker_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|testgen|mutate|diff|response|cli|sheets)/" ${PROJECT_SOURCE_DIR}/checker)
# testgen/ uses the checker and what it stands on, and reports' XML text; no
# other consumer of the checker, nor the CLI.
cemv_cli_test(NAME layout_testgen_includes_only_its_row EXIT 1
  COMMAND bash -c "grep -rnE '${_cemv_inc}(mutate|diff|response|cli|reports|sheets)/' ${PROJECT_SOURCE_DIR}/testgen | grep -v 'reports/xml_text.hpp\"'"
)
# mutate/: the mutants use model alone; the mutation report also formats,
# checker and testgen.
cemv_cli_test(NAME layout_mutants_include_only_model EXIT 1
  COMMAND grep -nE "${_cemv_inc}(formats|reports|runtime|encoder|properties|checker|testgen|diff|response|cli|sheets)/"
          ${PROJECT_SOURCE_DIR}/mutate/mutants.hpp ${PROJECT_SOURCE_DIR}/mutate/mutants.cpp)
cemv_cli_test(NAME layout_mutate_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|encoder|properties|diff|response|cli|sheets)/" ${PROJECT_SOURCE_DIR}/mutate)
# response/ uses model, formats, properties, checker and reports; never the
# runtime or the encoder directly (the checker runs them), nor another consumer.
cemv_cli_test(NAME layout_response_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(runtime|encoder|testgen|mutate|diff|cli|sheets)/" ${PROJECT_SOURCE_DIR}/response)
# defeats/ builds on response/ and the checker, and unrolls the encoder's
# transition system of a path itself (its one encoding, space.cpp); never the
# runtime directly (the checker replays), the command line, the test
# generator, mutation or change comparison.
cemv_cli_test(NAME layout_defeats_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(runtime|testgen|mutate|diff|cli|sheets)/" ${PROJECT_SOURCE_DIR}/defeats)
# plc_encoder/ is the program's second semantics: plc/'s AST and model/ only,
# never the interpreter's files, the matrix's encoder or runtime, nor any
# consumer (docs/architecture.md "Two independent implementations").
cemv_cli_test(NAME layout_plc_encoder_includes_only_plc_and_model EXIT 1
  COMMAND bash -c "grep -rnE '${_cemv_inc}(formats|reports|runtime|encoder|properties|checker|testgen|mutate|diff|response|defeats|plc_check|cli|sheets)/|${_cemv_inc}plc/(interpreter|blocks)' ${PROJECT_SOURCE_DIR}/plc_encoder")
# plc_check/ stands on the checker and both program semantics; never the CLI
# or another consumer of the checker.
cemv_cli_test(NAME layout_plc_check_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(properties|testgen|mutate|diff|response|defeats|cli|sheets)/" ${PROJECT_SOURCE_DIR}/plc_check)
# plc_export/ writes a matrix as a program from docs/semantics.md: model,
# formats and plc/'s AST only, never the matrix's runtime or encoder (the
# program is a diverse implementation that plc-check relates to them).
cemv_cli_test(NAME layout_plc_export_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|encoder|properties|checker|testgen|mutate|diff|response|defeats|plc_encoder|plc_check|cli|sheets)/|${_cemv_inc}plc/(interpreter|blocks|values)"
          ${PROJECT_SOURCE_DIR}/plc_export)
