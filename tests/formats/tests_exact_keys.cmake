# Exact key times and values through glTF/FBX import and glTF export, and the key-fidelity
# measures (processing/motion/key_fidelity). The glTF these tests write land under
# <build>/test-output/exact_keys, validated by tools/test.sh with the Khronos validator.
mocapfill_add_test(exact_keys_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/exact_keys_test.cc
  LIBS ${MOCAPFILL_GLTF_TEST_DRACO} mocapfill_test_gltf mocapfill_formats mocapfill_gltf mocapfill_format_common mocapfill_bvh
       mocapfill_motion nlohmann_json::nlohmann_json mocapfill_test_tinygltf)
