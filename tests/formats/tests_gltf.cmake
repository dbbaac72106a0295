# glTF reader/writer tests. Every glTF they write goes to <build>/test-output/gltf, which
# tools/test.sh validates afterwards with the Khronos glTF-Validator. The BVH reader
# provides real motion (fixtures/bvh) for round trips.
#
# libdraco (pulled in by Assimp) exports an older tinygltf under the same symbol names.
# It is linked first here, the worst case, so that every reader test proves mocapfill_gltf's
# privately named copy is unaffected, and gltf_linking_test.cc that the test support's
# calls into Debian's libtinygltf still bind to libtinygltf.
set(MOCAPFILL_GLTF_TEST_DRACO "")
if(TARGET draco::draco)
  set(MOCAPFILL_GLTF_TEST_DRACO draco::draco)
endif()
mocapfill_add_test(gltf_tests
  CORPUS [=[^(GltfImport\.CorpusSkins|GltfJsonWriter\.EveryCorpusFileReadsBackAsWritten)$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/gltf_roundtrip_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_import_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_bad_input_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_keyframes_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_bvh_fixture_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_linking_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_glb_writer_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_json_writer_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_tracks_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_skeleton_skin_test.cc
  LIBS ${MOCAPFILL_GLTF_TEST_DRACO} mocapfill_test_gltf mocapfill_gltf mocapfill_formats mocapfill_format_common mocapfill_bvh
       nlohmann_json::nlohmann_json mocapfill_test_tinygltf)
