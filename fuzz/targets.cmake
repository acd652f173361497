# The fuzz targets, one per importer (docs/fuzzing.md). Each line names the
# target (its source is fuzz/fuzz_<name>.cpp, its corpus fuzz/corpus/<name>/,
# its optional dictionary fuzz/dict/<name>.dict) and the library it links.
# Read by fuzz/CMakeLists.txt (the libFuzzer build, CEMV_FUZZ=ON), by
# tests/fuzz/fuzz.cmake (each corpus replayed in ctest) and by fuzz/run.sh.
# Adding a target: its source, its corpus folder, and one line here.
cemv_fuzz_target(matrix_json cemv_formats)
cemv_fuzz_target(csv cemv_sheets)
cemv_fuzz_target(scenario cemv_formats)
cemv_fuzz_target(properties cemv_properties)
cemv_fuzz_target(workbook cemv_sheets)
cemv_fuzz_target(sheet_layout cemv_sheets)
cemv_fuzz_target(plc cemv_plc)
