# PCA model, edits, closed-form and Ceres key fits, on the shared corpus.
mocapfill_add_test(pca_tests
  CORPUS [=[^Pca(Model|Edit|Fit)\.]=]
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/pca_model_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/pca_fit_test.cc
  LIBS mocapfill_test_pca_data mocapfill_pca mocapfill_evaluation mocapfill_mfdb mocapfill_formats)

# Speed of the key fit, stage by stage, against a direct sparse solve (bench/pca_bench.sh).
if(MOCAPFILL_BUILD_BENCHMARKS)
  add_executable(pca_bench ${CMAKE_CURRENT_LIST_DIR}/../bench/pca_bench.cc)
  target_link_libraries(pca_bench PRIVATE mocapfill_pca mocapfill_evaluation mocapfill_mfdb mocapfill_formats)
  target_compile_definitions(pca_bench PRIVATE MOCAPFILL_DATA_DIR="${MOCAPFILL_DATA_DIR}")
  mocapfill_set_warnings(pca_bench)
endif()
