# CLI contract tests of db build/info, filter and analyze.
mocapfill_add_test(db_cli_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/db_cli_test.cc LIBS nlohmann_json::nlohmann_json)
add_dependencies(db_cli_tests mocapfill)
