# `mocapfill fill` end to end on shipped sketches and the embedded default database.
mocapfill_add_test(fill_cli_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fill_cli_test.cc
  LIBS mocapfill_formats nlohmann_json::nlohmann_json)
add_dependencies(fill_cli_tests mocapfill)

# `fill --method pca|hybrid` and `eval` with the PCA-based methods.
mocapfill_add_test(hybrid_cli_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/hybrid_cli_test.cc
  LIBS nlohmann_json::nlohmann_json)
add_dependencies(hybrid_cli_tests mocapfill)
