# The LSST TMA example (examples/lsst-tma): the published sheet in
# ../shared/external imported with the example's parameters, checked against
# its requirements, compared with its 2023-10-05 version and reported, with
# no JSON edited by hand (tests/scenarios/lsst_tma.sh, one stage per test).
set(_lsst_external ${CEMV_LSST_DIR})
if(TARGET cemv_checker)
  set(_lsst_tmp ${CMAKE_CURRENT_BINARY_DIR}/lsst_tma)
  foreach(_stage import check diff evidence)
    cemv_cli_test(NAME examples.lsst-tma.${_stage} EXTERNAL EXIT 0
      COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/lsst_tma.sh ${_stage} $<TARGET_FILE:cemv> ${_lsst_external} ${_lsst_tmp})
  endforeach()
  # The check and evidence stages take 80-90 s alone,
  # several minutes beside the rest of the suite on two cores.
  set_tests_properties(examples.lsst-tma.check examples.lsst-tma.evidence PROPERTIES ENVIRONMENT CEMV_EXPECT_TIMEOUT=900)
  set_tests_properties(examples.lsst-tma.import PROPERTIES FIXTURES_SETUP lsst_tma)
  set_tests_properties(examples.lsst-tma.check examples.lsst-tma.diff examples.lsst-tma.evidence
                       PROPERTIES FIXTURES_REQUIRED lsst_tma)
endif()
