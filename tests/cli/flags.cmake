# Every hint names an option of the command that prints it: each `--flag` in a
# string literal of cli/, formats/ and sheets/ is listed by the --help of the
# commands that can print that message (tests/cli/flags_in_messages.py).
cemv_cli_test(NAME cli_flags_named_in_messages_exist EXIT 0
  MATCH "^every flag named in a message exists on its command: [0-9]+ checked"
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/flags_in_messages.py $<TARGET_FILE:cemv> ${PROJECT_SOURCE_DIR})

# No command bounds the wall clock unless asked: every --timeout and
# --total-timeout defaults to none (tests/cli/no_default_clock.py).
cemv_cli_test(NAME cli_no_default_wall_clock_limit EXIT 0
  MATCH "^no command bounds the wall clock by default: [0-9]+ time limits"
  COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/no_default_clock.py $<TARGET_FILE:cemv>)
