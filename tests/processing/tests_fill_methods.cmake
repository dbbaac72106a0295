# Fill methods on the embedded default database and the shipped sketch (issue #4).
mocapfill_add_test(fill_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fill_test.cc
  LIBS mocapfill_evaluation mocapfill_synthesis mocapfill_formats)
