# CLI contract tests run the built executable.
mocapfill_add_test(cli_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_test.cc LIBS nlohmann_json::nlohmann_json)
add_dependencies(cli_tests mocapfill)
