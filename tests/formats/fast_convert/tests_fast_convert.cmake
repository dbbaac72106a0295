# The convert fast path (formats/fast_convert/), in builds that have it: the streaming
# BVH-to-.glb converter and the two-thread row parser against the general path, mapped inputs,
# large buffers and spread threads. Without it, ConvertFile's general path is what the
# converter and round-trip tests exercise.
if(MOCAPFILL_FAST_CONVERT)
  mocapfill_add_test(fast_convert_tests
    CORPUS [=[^BvhGlbStream\.EveryCorpusClipGivesTheClipPathsBytes$]=]
    PERF [=[^(LargeBuffer\.(IsMappedForWritingWhenMade|ShortTailStaysInSmallPagesAlreadyFaultedIn|SmallPageTailIsFaultedInUpFront)|ReserveMappedHeap\.SmallAllocationsFindTheirPagesMapped)$]=]
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/bvh_to_glb_test.cc
            ${CMAKE_CURRENT_LIST_DIR}/rows_in_parallel_test.cc
            ${CMAKE_CURRENT_LIST_DIR}/file_text_test.cc
            ${CMAKE_CURRENT_LIST_DIR}/spread_thread_test.cc
    LIBS mocapfill_test_bvh mocapfill_fast_convert mocapfill_formats mocapfill_gltf)
endif()
