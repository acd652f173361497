# The direction of every dependency (docs/architecture.md): model/ includes
# nothing of cemv but model/; runtime/ and encoder/ include only model/ (and
# themselves); formats/ only model/; reports/ only model/ and formats/ (and
# checker/result.hpp).
# grep exits 1 when no include breaks the rule.
set(_cemv_inc "#include *[<\"](\\.\\./)*")
cemv_cli_test(NAME layout_model_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(formats|reports|runtime|encoder|properties|checker|testgen|cli)/"
          ${PROJECT_SOURCE_DIR}/model)
cemv_cli_test(NAME layout_runtime_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(formats|reports|encoder|properties|checker|testgen|cli)/"
          ${PROJECT_SOURCE_DIR}/runtime)
cemv_cli_test(NAME layout_encoder_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(formats|reports|runtime|properties|checker|testgen|cli)/"
          ${PROJECT_SOURCE_DIR}/encoder)
cemv_cli_test(NAME layout_formats_includes_only_model EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(reports|runtime|encoder|properties|checker|testgen|cli)/"
          ${PROJECT_SOURCE_DIR}/formats)
# reports/ may also include checker/result.hpp, the plain data the check
# printers render (and nothing else of checker/).
cemv_cli_test(NAME layout_reports_includes_only_model_and_formats EXIT 1
  COMMAND bash -c "grep -rnE '${_cemv_inc}(runtime|encoder|properties|checker|testgen|cli)/' ${PROJECT_SOURCE_DIR}/reports | grep -v 'checker/result.hpp\"'"
)
# diff/ uses the checker, runtime, formats, model and reports' SARIF helpers;
# never the command line, the test generator, mutation or response time.
cemv_cli_test(NAME layout_diff_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(properties|encoder|testgen|mutate|response|cli)/" ${PROJECT_SOURCE_DIR}/diff)
# defeats/ builds on response/ and the checker; never the command line, the
# test generator, mutation or change comparison.
cemv_cli_test(NAME layout_defeats_includes_only_its_row EXIT 1
  COMMAND grep -rnE "${_cemv_inc}(runtime|encoder|testgen|mutate|diff|cli)/" ${PROJECT_SOURCE_DIR}/defeats)
