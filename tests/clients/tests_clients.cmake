# Clients of the library, each through its own front door: the Python module under pytest,
# and the installed CMake package used by a separate project (examples/cpp_fill) and by the
# Python example. Labelled `clients`. Not under the sanitizers: the Python interpreter and
# the example program are not instrumented, and ASan's runtime must be loaded first.
if(MOCAPFILL_SANITIZE)
  return()
endif()

if(MOCAPFILL_HAS_PYTHON)
  add_test(NAME clients.python_module
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_pytest.sh ${MOCAPFILL_PYTHON_EXECUTABLE}
                   ${PROJECT_SOURCE_DIR}/python/tests)
  set_tests_properties(clients.python_module PROPERTIES LABELS clients SKIP_RETURN_CODE 77 TIMEOUT 600
                       ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python;MOCAPFILL_DATA_DIR=${MOCAPFILL_DATA_DIR}")
endif()

add_test(NAME clients.installed_package
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/installed_package_test.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR}
                 "${MOCAPFILL_PYTHON_EXECUTABLE}")
set_tests_properties(clients.installed_package PROPERTIES LABELS clients TIMEOUT 600)
