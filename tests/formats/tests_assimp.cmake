# FBX (and other Assimp formats) import: the shipped fixture, bad inputs, and the
# importer's Assimp-free helpers.
mocapfill_add_test(assimp_tests
  CORPUS [=[^AssimpCorpus\.]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/assimp_reader_test.cc ${CMAKE_CURRENT_LIST_DIR}/assimp_fixups_test.cc
  LIBS mocapfill_assimp)

# FBX -> glb -> import through ImportFile/ExportFile; the glb files stay in
# <build>/test-output/fbx for the CI glTF-Validator pass.
mocapfill_add_test(assimp_roundtrip_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/assimp_roundtrip_test.cc
  LIBS mocapfill_formats)

# Assimp in a child process: the scene handed back bit for bit, and crashes, hangs, memory
# exhaustion and garbage answers turned into errors naming the file.
mocapfill_add_test(isolated_read_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/isolated_read_test.cc
  LIBS mocapfill_formats mocapfill_assimp)
