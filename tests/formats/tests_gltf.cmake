# glTF reader/writer tests. Every glTF they write goes to <build>/test-output/gltf, which
# tools/test.sh validates afterwards with the Khronos glTF-Validator.
mocapfill_add_test(gltf_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/gltf_test_support.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_roundtrip_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_import_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_bad_input_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/gltf_keyframes_test.cc
  LIBS mocapfill_gltf mocapfill_format_common TinyGLTF::TinyGLTF nlohmann_json::nlohmann_json)
