# The .pca model file.
mocapfill_add_test(pcafile_tests
  CORPUS [=[^PcaFile\.]=]
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/pca_file_test.cc
  LIBS mocapfill_test_pca_data mocapfill_pcafile mocapfill_pca mocapfill_mfdb mocapfill_formats)
