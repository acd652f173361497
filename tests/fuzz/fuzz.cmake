# Every fuzz target (fuzz/targets.cmake) built with the normal compiler and a
# standalone main that feeds it each file of its corpus (fuzz/corpus/<name>/,
# which holds the seeds and every finding): a regression in an importer that
# the fuzzer once found fails here, without clang or libFuzzer. docs/fuzzing.md.
function(cemv_fuzz_target name library)
  add_executable(fuzz_replay_${name} ${PROJECT_SOURCE_DIR}/fuzz/fuzz_${name}.cpp
                                     ${PROJECT_SOURCE_DIR}/fuzz/replay_main.cpp)
  target_link_libraries(fuzz_replay_${name} PRIVATE ${library})
  target_include_directories(fuzz_replay_${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_definitions(fuzz_replay_${name} PRIVATE CEMV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  add_test(NAME fuzz_corpus_${name}
           COMMAND fuzz_replay_${name} ${PROJECT_SOURCE_DIR}/fuzz/corpus/${name})
endfunction()
include(${PROJECT_SOURCE_DIR}/fuzz/targets.cmake)
