# `mocapfill fill` end to end on shipped sketches and the embedded default database (issue #4).
mocapfill_add_test(fill_cli_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fill_cli_test.cc
  LIBS mocapfill_formats nlohmann_json::nlohmann_json)
add_dependencies(fill_cli_tests mocapfill)
