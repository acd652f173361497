# Timing diagrams (SVG) and value change dumps (VCD) of a run (reports/timing_svg.hpp,
# reports/vcd.hpp, docs/reports.md): golden files, and the VCD read back.
add_executable(test_reports_timing_pictures ${CMAKE_CURRENT_LIST_DIR}/test_timing_pictures.cpp)
target_link_libraries(test_reports_timing_pictures PRIVATE cemv_reports cemv_formats cemv_runtime GTest::gtest_main)
target_compile_definitions(test_reports_timing_pictures PRIVATE CEMV_GOLDEN_DIR="${CMAKE_CURRENT_LIST_DIR}/golden"
                           CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(test_reports_timing_pictures DISCOVERY_MODE PRE_TEST)

# The evidence report of an example loads in headless Chromium without errors
# and is byte-reproducible under SOURCE_DATE_EPOCH (docs/reports.md).
if(TARGET cemv_checker)
  cemv_cli_test(NAME cli_evidence_loads_in_chromium EXIT 0 MATCH "evidence report loads in chromium"
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/evidence_headless.sh $<TARGET_FILE:cemv>
            examples/tank-overfill/matrix.json examples/tank-overfill/requirements.props
            ${CMAKE_CURRENT_BINARY_DIR}/evidence_headless)
endif()
# The pictures on the command line: simulate names its files; check writes one per counterexample.
set(PICTURES_TMP ${CMAKE_CURRENT_BINARY_DIR}/pictures_cli)
file(MAKE_DIRECTORY ${PICTURES_TMP})
cemv_cli_test(NAME cli_simulate_svg_vcd EXIT 0 MATCH "diagram: .*scenario1.svg\nwaveforms: .*scenario1.vcd\nPASS"
  COMMAND $<TARGET_FILE:cemv> simulate examples/tank-overfill/scenario-1-overfill-trip.json
          --svg ${PICTURES_TMP}/scenario1.svg --vcd ${PICTURES_TMP}/scenario1.vcd)
