# Generated contractor sheets (tests/sheetgen/README.md): 200 seeded C&E
# sheets in the layouts contractors send, saved by LibreOffice as XLSX, ODS and
# CSV, each imported without a layout. Every import is read right (exactly the
# matrix the sheet means) or refused with its place in the file; an exit 0
# with another matrix fails, named by seed with the difference.
set(_sg ${CMAKE_CURRENT_LIST_DIR})
set(_sg_tmp ${CMAKE_CURRENT_BINARY_DIR}/sheetgen)
file(MAKE_DIRECTORY ${_sg_tmp})

# The generator is reproducible: the same seeds give the same bytes.
add_test(NAME sheetgen_reproducible
  COMMAND bash -c "rm -rf $1/a $1/b && python3 $0 --first 1 --count 25 --out $1/a >/dev/null && python3 $0 --first 1 --count 25 --out $1/b >/dev/null && diff -r $1/a $1/b && echo 'same 50 files from the same seeds'"
          ${_sg}/sheetgen.py ${_sg_tmp}/reproducible)
set_tests_properties(sheetgen_reproducible PROPERTIES TIMEOUT 120 PASS_REGULAR_EXPRESSION "same 50 files from the same seeds")

find_program(SOFFICE soffice)
if(SOFFICE)
  add_test(NAME cli_sheetgen_contractor_sheets
    COMMAND python3 ${_sg}/run_sheetgen.py --cemv $<TARGET_FILE:cemv> --soffice ${SOFFICE}
            --work ${_sg_tmp}/sheets --first 1 --count 200 --jobs 2)
  # LibreOffice on 200 workbooks takes about a minute; give a loaded machine room.
  set_tests_properties(cli_sheetgen_contractor_sheets PROPERTIES TIMEOUT 900 PROCESSORS 2)
endif()
