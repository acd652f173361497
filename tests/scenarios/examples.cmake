# The bundled examples (examples/*/matrix.json) as CLI tests: each matrix must
# pass `cemv validate` with no error and only the intended warnings that
# examples/README.md explains ("Warnings", matched here rule by rule), and every
# scenario next to it must pass `cemv simulate` on the reference runtime
# (every example has at least one passing scenario).
# New examples and scenarios are picked up by the glob without editing this file.
set(_cemv_examples_dir ${CMAKE_CURRENT_LIST_DIR}/../../examples)
file(GLOB _cemv_example_matrices CONFIGURE_DEPENDS ${_cemv_examples_dir}/*/matrix.json)
list(SORT _cemv_example_matrices)
foreach(_matrix ${_cemv_example_matrices})
  get_filename_component(_dir ${_matrix} DIRECTORY)
  get_filename_component(_example ${_dir} NAME)
  # The rule ids of its warnings, in report order (examples/README.md "Warnings").
  set(_warnings "W-SIMULATION-UNRESTRICTED")
  if(_example STREQUAL "burner-management")
    set(_warnings "W-SIMULATION-UNRESTRICTED W-SOFT-BYPASS-UNTIMED")
  elseif(_example STREQUAL "pipeline-hipps")
    set(_warnings "W-SIMULATION-UNRESTRICTED W-SOFT-BYPASS-UNTIMED W-SOFT-BYPASS-UNTIMED")
  endif()
  cemv_cli_test(NAME examples.${_example}.validate EXIT 0
                MATCH "^${_warnings}$"
                COMMAND bash -c [=[
set -o pipefail
"$1" validate "$2" | awk '$1 == "error" || $1 == "warning" { printf "%s%s", sep, $2
  sep = " " }
END { print "" }'
]=] _ $<TARGET_FILE:cemv> ${_matrix})
  # The examples use every option of the format, so they are the realistic
  # round-trip case of the spreadsheet layout (6.6): export, import, same
  # signature (the SHA-256 of the canonical form).
  cemv_cli_test(NAME examples.${_example}.csv-roundtrip EXIT 0
                MATCH "^roundtrip [0-9a-f]{64}$"
                COMMAND bash -c [=[
set -e
cemv=$1
m=$2
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
"$cemv" export-csv "$m" -o "$t/m.csv"
"$cemv" import-csv "$t/m.csv" -o "$t/m.json"
a=$("$cemv" signature "$m")
b=$("$cemv" signature "$t/m.json")
if [ "$a" != "$b" ]
then
  echo "signature $a became $b after export-csv and import-csv"
  exit 1
fi
echo "roundtrip $a"]=] roundtrip $<TARGET_FILE:cemv> ${_matrix})
  file(GLOB _scenarios CONFIGURE_DEPENDS ${_dir}/scenario-*.json)
  list(SORT _scenarios)
  list(LENGTH _scenarios _count)
  if(_count EQUAL 0)
    message(FATAL_ERROR "example ${_example} has no scenario-*.json")
  endif()
  foreach(_scenario ${_scenarios})
    get_filename_component(_stem ${_scenario} NAME_WE)
    cemv_cli_test(NAME examples.${_example}.${_stem} EXIT 0
                  MATCH ", 0 failed"
                  COMMAND $<TARGET_FILE:cemv> simulate ${_matrix} ${_scenario})
  endforeach()
endforeach()
