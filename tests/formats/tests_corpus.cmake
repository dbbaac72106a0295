# Corpus round trips over ../shared/data; skip visibly without the corpus.
add_library(mocapfill_gltf_reference_fk STATIC ${CMAKE_CURRENT_LIST_DIR}/../support/gltf_reference_fk.cc)
target_link_libraries(mocapfill_gltf_reference_fk PUBLIC Eigen3::Eigen mocapfill_test_tinygltf)
mocapfill_add_test(corpus_roundtrip_tests
  CORPUS [=[.]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corpus_roundtrip_test.cc
  LIBS mocapfill_formats mocapfill_gltf_reference_fk)
