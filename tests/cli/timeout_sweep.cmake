# Issue 38, section 0: --total-timeout interrupts every long-running command
# at many points (a sweep of limits over a generated 16 x 16 matrix and the
# 128 x 128 x 1024 big_matrix), and each run ends with exit 0-3 and complete,
# valid output (tests/cli/timeout_cases/sweep.sh).
if(TARGET cemv_checker AND TARGET cemv_testgen AND TARGET cemv_defeats AND TARGET cemv_matrix_json)
  set(_sweep ${CMAKE_CURRENT_LIST_DIR}/timeout_cases/sweep.sh)
  set(_tmp ${CMAKE_CURRENT_BINARY_DIR}/timeout_sweep)
  function(cemv_timeout_sweep command size)
    add_test(NAME timeout_sweep_${command}_${size} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
      COMMAND bash ${_sweep} $<TARGET_FILE:cemv> $<TARGET_FILE:cemv_matrix_json> ${_tmp}/${command}_${size}
              ${command} ${size} ${ARGN})
  endfunction()
  cemv_timeout_sweep(check 16 0.05 0.3 1 2)
  cemv_timeout_sweep(check 128 0.5 1.5 3 5)
  cemv_timeout_sweep(testgen 16 0.05 0.5 1.5)
  # The field suite comes first and polls the token between loops (128 x 128
  # ran past the limit before).
  cemv_timeout_sweep(testgen 128 1 3)
  cemv_timeout_sweep(response 16 0.05 0.5 1.5)
  cemv_timeout_sweep(defeats 16 0.05 0.5 1.5)
  cemv_timeout_sweep(mutate 16 0.05 0.5 1.5)
  cemv_timeout_sweep(diff 16 0.05 0.5 1.5)
  cemv_timeout_sweep(evidence 16 0.05 0.5 1.5)
endif()
