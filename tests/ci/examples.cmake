# The examples are what a new user gates on first (docs/ci.md): they are kept
# in canonical form, so `cemv fmt --check` passes on them as it would in CI.
cemv_cli_test(NAME ci_examples_canonical EXIT 0 MATCH "4 files: 0 not in canonical form"
  COMMAND $<TARGET_FILE:cemv> fmt --check examples/burner-management/matrix.json examples/compressor/matrix.json
          examples/pipeline-hipps/matrix.json examples/tank-overfill/matrix.json)

# The README's command table is one table holding a row for every command.
add_test(NAME ci_readme_command_table WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/readme_commands.py $<TARGET_FILE:cemv> README.md)
