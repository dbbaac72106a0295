# Resampling, tangent space, pyramid filtering, analysis and motion database.
mocapfill_add_test(processing_db_tests
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/resample_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/tangent_space_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/pyramid_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/motion_filter_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/phases_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/correlation_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/motion_database_test.cc
  LIBS mocapfill_database mocapfill_analysis mocapfill_filtering mocapfill_motion)

# Real-data tests: shipped fixtures always, the Bandai-Namco corpus when present.
mocapfill_add_test(database_corpus_tests
  CORPUS [=[^BandaiNamco\.]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/database_corpus_test.cc
  LIBS mocapfill_mfdb mocapfill_database mocapfill_filtering)
