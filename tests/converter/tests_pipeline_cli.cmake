# `mocapfill run`: pipeline files, validation errors (exit 1, nothing written), the
# shipped example pipelines end to end (glTF under test-output/pipeline for the validator).
mocapfill_add_test(pipeline_cli_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/pipeline_cli_test.cc ${CMAKE_CURRENT_LIST_DIR}/pipeline_file_test.cc
  LIBS mocapfill_cli nlohmann_json::nlohmann_json)
add_dependencies(pipeline_cli_tests mocapfill)
