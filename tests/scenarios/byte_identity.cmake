# The same inputs give the same bytes for any --jobs and any load
# (tests/scenarios/byte_identity.sh; docs/checker.md "Budgets").
if(TARGET cemv_testgen AND TARGET cemv_response)
  add_test(NAME byte_identity_jobs_and_load
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/byte_identity.sh $<TARGET_FILE:cemv> ${PROJECT_SOURCE_DIR}/examples
            ${CMAKE_CURRENT_BINARY_DIR}/byte_identity)
  set_tests_properties(byte_identity_jobs_and_load PROPERTIES TIMEOUT 1200
    PASS_REGULAR_EXPRESSION "byte-identical: [0-9]+ files of check, testgen and response")
endif()

# --timeout ends the language's longest hold on time and in bounded memory
# (tests/checker/long_property.sh).
add_test(NAME long_property_ends_on_time
  COMMAND bash ${PROJECT_SOURCE_DIR}/tests/checker/long_property.sh $<TARGET_FILE:cemv>
          ${PROJECT_SOURCE_DIR}/examples/tank-overfill/matrix.json ${CMAKE_CURRENT_BINARY_DIR}/long_property)
set_tests_properties(long_property_ends_on_time PROPERTIES PASS_REGULAR_EXPRESSION "ended on time")
