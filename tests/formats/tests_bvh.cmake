# BVH importer and exporter: fixtures under fixtures/bvh and fixtures/bad, corpus tests
# over ../shared/data (skipped visibly when absent).
# The BVH test helpers (bvh_test_support.h), compiled once for both suites.
add_library(mocapfill_test_bvh STATIC ${CMAKE_CURRENT_LIST_DIR}/bvh_test_support.cc)
target_link_libraries(mocapfill_test_bvh PUBLIC mocapfill_bvh mocapfill_test_support GTest::gtest)
mocapfill_set_warnings(mocapfill_test_bvh)

mocapfill_add_test(bvh_tests
  CORPUS [=[^BvhCorpusFiles\.]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/bvh_reader_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/bvh_syntax_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/bvh_bad_input_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/bvh_writer_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/bvh_corpus_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/bvh_parallel_test.cc
  LIBS mocapfill_test_bvh mocapfill_bvh)
# The streaming BVH-to-.glb converter against the clip path.
mocapfill_add_test(bvh_glb_tests
  CORPUS [=[^BvhGlbStream\.EveryCorpusClipGivesTheClipPathsBytes$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/bvh_glb_test.cc
  LIBS mocapfill_test_bvh mocapfill_formats mocapfill_bvh_glb mocapfill_gltf)
# Whole-file reads, LargeBuffer and SpreadThread.
mocapfill_add_test(file_io_tests
  PERF [=[^(LargeBuffer\.(IsMappedForWritingWhenMade|ShortTailStaysInSmallPagesAlreadyFaultedIn|SmallPageTailIsFaultedInUpFront)|ReserveMappedHeap\.SmallAllocationsFindTheirPagesMapped)$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/file_io_test.cc ${CMAKE_CURRENT_LIST_DIR}/spread_thread_test.cc
  LIBS mocapfill_format_common)
