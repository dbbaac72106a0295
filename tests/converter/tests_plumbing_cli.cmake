# CLI contract tests of the plumbing every verb shares: - for standard input and output,
# folders as convert inputs, --json, --db default, inline maps, joint-name suggestions,
# global flags after the verb.
mocapfill_add_test(plumbing_cli_tests PREFIX plumbing_cli. SOURCES ${CMAKE_CURRENT_LIST_DIR}/plumbing_cli_test.cc
                   LIBS mocapfill_formats nlohmann_json::nlohmann_json)
add_dependencies(plumbing_cli_tests mocapfill mocapfill_full)
