# cemv where CI runs (docs/ci.md): the Debian package of the built tree and
# what it installs, `cmake --install`, the slim configuration, every command
# of docs/ci.md, and the GitHub action and GitLab template run as written.
set(_ci ${CMAKE_CURRENT_LIST_DIR})
set(_ci_tmp ${PROJECT_BINARY_DIR}/tests/ci)

add_test(NAME ci_package_installs_a_working_cemv WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash ${_ci}/package.sh ${PROJECT_BINARY_DIR} ${_ci_tmp}/package)
# The package the recipes' test installs, as a package job of the pipeline gives it.
set_tests_properties(ci_package_installs_a_working_cemv PROPERTIES FIXTURES_SETUP cemv_deb RESOURCE_LOCK cemv_cpack)

add_test(NAME ci_cmake_install_and_slim_configuration WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND bash ${_ci}/install.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR} ${_ci_tmp}/install)

# docs/ci.md packages the built tree itself (scripts/build-package): one
# cpack at a time.
add_test(NAME ci_docs_every_command_runs WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND python3 ${_ci}/docs_ci.py ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR} ${_ci_tmp}/docs)
set_tests_properties(ci_docs_every_command_runs PROPERTIES RESOURCE_LOCK cemv_cpack)

add_test(NAME ci_recipes_work_as_written WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND python3 ${_ci}/recipes.py ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR} ${_ci_tmp}/package/pkg ${_ci_tmp}/recipes)
set_tests_properties(ci_recipes_work_as_written PROPERTIES FIXTURES_REQUIRED cemv_deb)

# cemv-gate, the script the recipes run, is clean to shellcheck.
add_test(NAME ci_scripts_shellcheck WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMAND shellcheck ci/cemv-gate scripts/build-package scripts/install-deps cmake/man_page.sh
          ${_ci}/package.sh ${_ci}/install.sh)
