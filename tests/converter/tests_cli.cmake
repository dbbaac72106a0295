# CLI contract tests run the built executable.
# Hostile sizes (hostile_input_test.cc) are generated at test time; the gigabyte BVH and
# the ten-million-accessor glTF are slow.
mocapfill_add_test(cli_tests
  SLOW [=[^HostileInput\.(GigabyteOfBvhRowsIsRefusedWithinTheMemoryBound|GltfOfTenMillionAccessorsIsRefusedWithinTheMemoryBound)$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_test.cc ${CMAKE_CURRENT_LIST_DIR}/batch_cli_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/hostile_input_test.cc
  LIBS nlohmann_json::nlohmann_json)
add_dependencies(cli_tests mocapfill)
