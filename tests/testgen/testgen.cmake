if(TARGET cemv_testgen)
  # Not in make test: prints the objectives of a matrix (a developer's tool).
  add_executable(cemv_testgen_objectives ${CMAKE_CURRENT_LIST_DIR}/tool_objectives.cpp)
  target_link_libraries(cemv_testgen_objectives PRIVATE cemv_testgen)
endif()
