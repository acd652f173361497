# The committed suites of the examples (examples/*/acceptance, automated
# and field, checklists included) are what cemv testgen writes now, byte for
# byte (tests/testgen/regenerate.sh), and every committed automated suite
# detects every non-equivalent mutant of its matrix (docs/mutation.md:
# `cemv mutate --equivalence --suite` exits 1 when one survives, 3 when an
# equivalence stays undecided).
# The four examples, the compressor's included (about 4 min 45 s of CPU with
# --jobs 2, the longest: its two 8 h soft bypasses, tests of 576,000 cycles,
# needed 2.1 GB while runs were held as traces; they are judged cycle by
# cycle now, docs/testgen.md "Synthesis and minimisation"). Each
# regeneration compares the field suite too (acceptance/field).
if(TARGET cemv_testgen)
  foreach(ex burner-management compressor pipeline-hipps tank-overfill)
    add_test(NAME testgen_regenerate_${ex} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
      COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/regenerate.sh ${PROJECT_BINARY_DIR}/cemv ${ex})
    set_tests_properties(testgen_regenerate_${ex} PROPERTIES TIMEOUT 1800)
  endforeach()
  # Every committed automated suite, the compressor's too (its mutants take
  # minutes of CPU: 157 replays of its 1.15 M cycles, each test stopped at its
  # first failure, and 23 equivalences proved; docs/performance.md "make
  # test's longest tests"), two mutants at once as regenerate.sh generates
  # with --jobs 2: wall limits for a machine shared with other builds.
  foreach(ex burner-management compressor pipeline-hipps tank-overfill)
    cemv_cli_test(NAME testgen_suite_detects_every_mutant_${ex} EXIT 0
      MATCH "survived 0, undecided 0"
      COMMAND ${PROJECT_BINARY_DIR}/cemv mutate examples/${ex}/matrix.json --equivalence
              --suite examples/${ex}/acceptance --jobs 2 --out ${CMAKE_CURRENT_BINARY_DIR}/suite_mutants_${ex})
    set_tests_properties(testgen_suite_detects_every_mutant_${ex} PROPERTIES TIMEOUT 3600
      ENVIRONMENT CEMV_EXPECT_TIMEOUT=3500)  # expect.sh stops a command after 120 s by default
  endforeach()
endif()
