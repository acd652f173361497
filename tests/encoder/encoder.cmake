# Encoder tests (docs/encoding.md): unit tests, the differential test against the
# runtime (sharded so ctest runs the shards in parallel), and the --long runner.
if(TARGET cemv_encoder AND TARGET cemv_testsupport)
  add_executable(test_encoder ${CMAKE_CURRENT_LIST_DIR}/test_encoder.cpp)
  target_link_libraries(test_encoder PRIVATE cemv_encoder cemv_testsupport GTest::gtest_main)
  gtest_discover_tests(test_encoder DISCOVERY_MODE PRE_TEST)
endif()

if(TARGET cemv_encoder AND TARGET cemv_runtime AND TARGET cemv_testsupport)
  add_library(cemv_encoder_diff STATIC ${CMAKE_CURRENT_LIST_DIR}/diff_support.cpp)
  target_link_libraries(cemv_encoder_diff PUBLIC cemv_encoder cemv_runtime cemv_formats cemv_testsupport)

  add_executable(test_encoder_differential ${CMAKE_CURRENT_LIST_DIR}/test_differential.cpp)
  target_compile_definitions(test_encoder_differential PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_link_libraries(test_encoder_differential PRIVATE cemv_encoder_diff GTest::gtest_main)
  gtest_discover_tests(test_encoder_differential DISCOVERY_MODE PRE_TEST)

  # Not in make test: cemv_diff_long --long 30 (minutes).
  add_executable(cemv_diff_long ${CMAKE_CURRENT_LIST_DIR}/diff_long.cpp)
  target_link_libraries(cemv_diff_long PRIVATE cemv_encoder_diff)
endif()
