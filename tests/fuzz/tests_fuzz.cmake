# Fuzz targets (tests/fuzz/fuzz_targets.h): a library of them, the replay test that runs the
# kept regression inputs and the fixtures through them in every test run, and, with
# MOCAPFILL_FUZZ (clang, set by tools/fuzz.sh), one libFuzzer program per target.
add_library(mocapfill_fuzz_targets STATIC
  ${CMAKE_CURRENT_LIST_DIR}/fuzz_targets.cc
  ${CMAKE_CURRENT_LIST_DIR}/fuzz_formats.cc
  ${CMAKE_CURRENT_LIST_DIR}/fuzz_config.cc)
target_link_libraries(mocapfill_fuzz_targets PUBLIC mocapfill_cli mocapfill_formats mocapfill_mfdb mocapfill_pcafile
                      mocapfill_retargeting mocapfill_graph)
target_compile_definitions(mocapfill_fuzz_targets PRIVATE MOCAPFILL_FIXTURES_DIR="${PROJECT_SOURCE_DIR}/fixtures")
mocapfill_set_warnings(mocapfill_fuzz_targets)

mocapfill_add_test(fuzz_replay_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fuzz_replay_test.cc
  LIBS mocapfill_fuzz_targets)
target_compile_definitions(fuzz_replay_tests PRIVATE
  MOCAPFILL_FUZZ_REGRESSIONS_DIR="${CMAKE_CURRENT_LIST_DIR}/regressions")

if(MOCAPFILL_FUZZ)
  add_custom_target(fuzzers)
  foreach(name bvh gltf mfdb pca pipeline maps fbx wire)
    string(SUBSTRING ${name} 0 1 first)
    string(TOUPPER ${first} first)
    string(SUBSTRING ${name} 1 -1 rest)
    add_executable(fuzz_${name} ${CMAKE_CURRENT_LIST_DIR}/fuzz_entry.cc)
    target_compile_definitions(fuzz_${name} PRIVATE MOCAPFILL_FUZZ_FUNCTION=Fuzz${first}${rest})
    target_link_libraries(fuzz_${name} PRIVATE mocapfill_fuzz_targets)
    target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
    mocapfill_set_warnings(fuzz_${name})
    add_dependencies(fuzzers fuzz_${name})
  endforeach()
endif()
