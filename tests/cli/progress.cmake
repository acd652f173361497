# The progress line of long commands (cli/progress.hpp): on a terminal only,
# never with --quiet, and the report files are the same either way.
if(TARGET cemv_checker AND TARGET cemv_properties)
  cemv_cli_test(NAME cli_progress_only_on_a_terminal EXIT 0 MATCH "progress on a terminal only"
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/progress_tty.sh $<TARGET_FILE:cemv> examples/tank-overfill/matrix.json
            tests/cli/check_cases/tank_small.props ${CMAKE_CURRENT_BINARY_DIR}/progress_tty)
endif()
