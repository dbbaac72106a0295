# `mocapfill pca` verbs; edited glTF goes to test-output/pca for the validator.
mocapfill_add_test(pca_cli_tests
  CORPUS [=[^PcaCli\.]=]
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/pca_cli_test.cc
  LIBS mocapfill_test_pca_data mocapfill_mfdb mocapfill_formats nlohmann_json::nlohmann_json)
add_dependencies(pca_cli_tests mocapfill)
