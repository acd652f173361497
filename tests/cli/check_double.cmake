# `cemv` with a test double of the checker and of the property parser
# (tests/cli/check_double/README.md): the CLI's paths of `cemv check` without
# the engines. Never part of the product.
add_executable(cemv_check_double
  ${PROJECT_SOURCE_DIR}/cli/main.cpp
  ${PROJECT_SOURCE_DIR}/cli/cmd_check.cpp
  ${PROJECT_SOURCE_DIR}/cli/check_gate.cpp
  ${PROJECT_SOURCE_DIR}/cli/result_cache.cpp
  ${CMAKE_CURRENT_LIST_DIR}/check_double/check_double.cpp
)
target_include_directories(cemv_check_double BEFORE PRIVATE ${CMAKE_CURRENT_LIST_DIR}/check_double/include)
target_link_libraries(cemv_check_double PRIVATE cemv_cli_commands cemv_reports OpenSSL::Crypto)
target_compile_definitions(cemv_check_double PRIVATE CEMV_WITH_CHECK CEMV_VERSION="${PROJECT_VERSION}")
