# FBX (and other Assimp formats) import: the shipped fixture, bad inputs, and the
# importer's Assimp-free helpers.
mocapfill_add_test(assimp_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/assimp_reader_test.cc ${CMAKE_CURRENT_LIST_DIR}/assimp_fixups_test.cc
  LIBS mocapfill_assimp)
