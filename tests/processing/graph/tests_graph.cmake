# The processing graph core: option checks, validation, ordering, running.
mocapfill_add_test(graph_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/graph_test.cc ${CMAKE_CURRENT_LIST_DIR}/option_check_test.cc
  LIBS mocapfill_graph mocapfill_formats)
