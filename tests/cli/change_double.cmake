# `cemv` with a test double of observable equivalence
# (tests/cli/change_double/README.md): the exit codes 3 and 4 of `cemv diff`
# and `cemv mutate` without engines that time out or a bug. Never part of the
# product.
if(TARGET cemv_diff AND TARGET cemv_mutate)
  add_executable(cemv_change_double
    ${PROJECT_SOURCE_DIR}/cli/main.cpp
    ${PROJECT_SOURCE_DIR}/cli/cmd_diff.cpp
    ${PROJECT_SOURCE_DIR}/cli/cmd_mutate.cpp
    ${CMAKE_CURRENT_LIST_DIR}/change_double/equivalence_double.cpp
  )
  target_link_libraries(cemv_change_double PRIVATE cemv_cli_commands cemv_diff cemv_mutate)
  target_compile_definitions(cemv_change_double PRIVATE CEMV_WITH_VERIFICATION CEMV_VERSION="${PROJECT_VERSION}")
endif()
