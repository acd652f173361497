# Every hint names an option of the command that prints it: each `--flag` in a
# string literal of cli/, formats/ and sheets/ is listed by the --help of the
# commands that can print that message (tests/cli/flags_in_messages.py).
cemv_cli_test(NAME cli_flags_named_in_messages_exist EXIT 0
  MATCH "^every flag named in a message exists on its command: [0-9]+ checked"
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/flags_in_messages.py $<TARGET_FILE:cemv> ${PROJECT_SOURCE_DIR})
