# CLI contract tests of `mocapfill rig show`.
mocapfill_add_test(rig_cli_tests PREFIX rig_cli. SOURCES ${CMAKE_CURRENT_LIST_DIR}/rig_cli_test.cc LIBS nlohmann_json::nlohmann_json)
add_dependencies(rig_cli_tests mocapfill)
