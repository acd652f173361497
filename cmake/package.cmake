# Installing cemv and packaging it (docs/ci.md, "Installing cemv"):
# `cmake --install build --prefix P` installs P/bin/cemv, P/bin/cemv-gate, the
# man pages and the documentation with the examples; `make package` (the
# CMake target `package`) builds the Debian package of the same files, its
# Depends computed from the binary's shared libraries by dpkg-shlibdeps, its
# version the exact build (cmake/build_version.cmake).
include(GNUInstallDirs)
# Installing and packaging build nothing: `make package` and
# scripts/build-package build first. So cpack on a built tree (the package
# test, while other tests run) never compiles or relinks, and a package's
# version is always the one of the binary it holds, both from the last build.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

install(TARGETS cemv RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS ${PROJECT_SOURCE_DIR}/ci/cemv-gate DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/cmake/copyright
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# The man pages, generated from --help by help2man (scripts/install-deps
# installs it) whenever the binary changes.
find_program(HELP2MAN help2man)
if(NOT HELP2MAN)
  message(FATAL_ERROR "help2man not found: it writes the man page (scripts/install-deps runtime installs it)")
endif()
set(CEMV_MAN_PAGES ${PROJECT_BINARY_DIR}/man/cemv.1.gz ${PROJECT_BINARY_DIR}/man/cemv-gate.1.gz)
add_custom_command(OUTPUT ${CEMV_MAN_PAGES}
  COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/man_page.sh $<TARGET_FILE:cemv> ${PROJECT_SOURCE_DIR}/ci/cemv-gate
          ${PROJECT_BINARY_DIR}/man ${PROJECT_SOURCE_DIR}
  DEPENDS cemv ${PROJECT_SOURCE_DIR}/cmake/man_page.sh ${PROJECT_SOURCE_DIR}/ci/cemv-gate
  COMMENT "man pages (help2man)")
add_custom_target(cemv_man_pages ALL DEPENDS ${CEMV_MAN_PAGES})
install(FILES ${CEMV_MAN_PAGES} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# The Debian package.
set(CEMV_PACKAGE_MAINTAINER "cemv maintainers <cemv@localhost>" CACHE STRING
    "The Maintainer field of the Debian package (Name <address>)")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME cemv)
set(CPACK_PACKAGE_VENDOR "cemv")
set(CPACK_PACKAGE_CONTACT "${CEMV_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CEMV_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "verification and acceptance tests for safety cause & effect matrices")
# The first line of Description is the summary above; this is the rest.
string(CONCAT CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "cemv models a cause & effect matrix of a safety instrumented system exactly,\n"
  "runs it on a reference runtime, proves requirements or gives replayed\n"
  "counterexamples, generates acceptance tests and checklists, compares\n"
  "versions and computes each safety function's response time. cemv-gate runs\n"
  "its checks in a CI pipeline (JUnit and SARIF reports).")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})  # replaced by the exact build at package time:
configure_file(${PROJECT_SOURCE_DIR}/cmake/cpack_version.cmake.in ${PROJECT_BINARY_DIR}/cpack_version.cmake @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/cpack_version.cmake)
include(CPack)
