# Tests of the scenario format and of the runtime against the manual's tables
# (6.1.6, 6.3.1, appendix B) and timer boundaries (docs/semantics.md T.2). They need
# the reference runtime; until runtime/ builds a library they are not defined.
if(TARGET cemv_runtime)
  foreach(t scenario runtime_voting_tables runtime_cause_functions runtime_timers)
    add_executable(test_${t} ${CMAKE_CURRENT_LIST_DIR}/test_${t}.cpp)
    target_link_libraries(test_${t} PRIVATE cemv_runtime cemv_formats GTest::gtest_main)
    target_include_directories(test_${t} PRIVATE ${CMAKE_CURRENT_LIST_DIR})
    gtest_discover_tests(test_${t} DISCOVERY_MODE PRE_TEST)
  endforeach()
endif()
