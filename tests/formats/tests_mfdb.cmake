# .mfdb database files, motion folder labels and SVG plots.
mocapfill_add_test(mfdb_tests
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/mfdb_file_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/motion_folder_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/svg_plot_test.cc
  # The database the file tests store is built with processing/database's builder; the
  # format library itself links only the core.
  LIBS mocapfill_mfdb mocapfill_database mocapfill_plot)
