# Checker tests: every engine on every model, the re-checks of answers, and
# the SMT-LIB export confirmed by cvc5.
if(TARGET cemv_checker)
  add_library(cemv_checker_problems STATIC ${CMAKE_CURRENT_LIST_DIR}/problems.cpp)
  target_compile_definitions(cemv_checker_problems PUBLIC CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_link_libraries(cemv_checker_problems PUBLIC cemv_checker cemv_encoder cemv_formats cemv_model)

  add_executable(test_checker_engines ${CMAKE_CURRENT_LIST_DIR}/test_engines.cpp)
  target_link_libraries(test_checker_engines PRIVATE cemv_checker_problems cemv_testsupport GTest::gtest_main)
  gtest_discover_tests(test_checker_engines DISCOVERY_MODE PRE_TEST)
endif()

if(TARGET cemv_checker)
  add_executable(test_checker_check ${CMAKE_CURRENT_LIST_DIR}/test_check.cpp)
  target_link_libraries(test_checker_check PRIVATE cemv_checker_problems GTest::gtest_main)
  gtest_discover_tests(test_checker_check DISCOVERY_MODE PRE_TEST)
endif()

if(TARGET cemv_checker)
  add_executable(test_checker_reduce ${CMAKE_CURRENT_LIST_DIR}/test_reduce.cpp
                                     ${CMAKE_CURRENT_LIST_DIR}/test_round_values.cpp)
  target_link_libraries(test_checker_reduce PRIVATE cemv_checker_problems GTest::gtest_main)
  gtest_discover_tests(test_checker_reduce DISCOVERY_MODE PRE_TEST)
  add_executable(test_checker_localize ${CMAKE_CURRENT_LIST_DIR}/test_localize.cpp)
  target_link_libraries(test_checker_localize PRIVATE cemv_checker_problems GTest::gtest_main)
  gtest_discover_tests(test_checker_localize DISCOVERY_MODE PRE_TEST)
endif()

if(TARGET cemv_checker)
  add_executable(test_checker_portfolio ${CMAKE_CURRENT_LIST_DIR}/test_portfolio.cpp)
  target_link_libraries(test_checker_portfolio PRIVATE cemv_checker_problems GTest::gtest_main)
  gtest_discover_tests(test_checker_portfolio DISCOVERY_MODE PRE_TEST)
endif()

if(TARGET cemv_checker)
  add_executable(test_checker_pools ${CMAKE_CURRENT_LIST_DIR}/test_pools.cpp)
  target_link_libraries(test_checker_pools PRIVATE cemv_checker_problems GTest::gtest_main)
  gtest_discover_tests(test_checker_pools DISCOVERY_MODE PRE_TEST)
endif()

# Not in make test: cemv_checker_measure [SECONDS] prints the 18,000-cycle
# timer figures per engine, plain BMC and PDR side by side.
if(TARGET cemv_checker)
  add_executable(cemv_checker_measure ${CMAKE_CURRENT_LIST_DIR}/measure.cpp)
  target_link_libraries(cemv_checker_measure PRIVATE cemv_checker_problems)
endif()

# Not in make test: cemv_checker_probe MATRIX PROPS SECONDS [NAME...] runs
# every engine alone on every property, then the portfolio.
if(TARGET cemv_checker)
  add_executable(cemv_checker_probe ${CMAKE_CURRENT_LIST_DIR}/probe.cpp)
  target_link_libraries(cemv_checker_probe PRIVATE cemv_checker cemv_testsupport)
endif()

# The support of proofs: core, full and off, each reported support re-proved
# on the matrix without the other cells (issue 38, section 1).
if(TARGET cemv_checker)
  add_executable(test_checker_support ${CMAKE_CURRENT_LIST_DIR}/test_support.cpp)
  target_link_libraries(test_checker_support PRIVATE cemv_checker GTest::gtest_main)
  target_compile_definitions(test_checker_support PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_checker_support DISCOVERY_TIMEOUT 60)
endif()
