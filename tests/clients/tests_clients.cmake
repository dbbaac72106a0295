# Clients of the library and of what the tool writes, each through its own front door: the
# Python module under pytest; the installed CMake package used by a separate project
# (examples/cpp_fill) and by the Python example; files the tool writes, read by Blender's glTF
# importer and three.js's BVHLoader and compared with mocapfill's forward kinematics. Labelled
# `clients`; each skips (exit 77) when its client is not installed. Not under the sanitizers:
# Python, Blender and the example program are not instrumented, and ASan's runtime must be
# loaded first.
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

add_executable(mocapfill_fk_dump ${CMAKE_CURRENT_LIST_DIR}/fk_dump.cc)
target_link_libraries(mocapfill_fk_dump PRIVATE mocapfill_formats mocapfill_core)
mocapfill_set_warnings(mocapfill_fk_dump)

foreach(client blender threejs)
  if(client STREQUAL "blender")
    set(name clients.BlenderImportsConvertedGlbAsOneArmatureOnTheJoints)
  else()
    set(name clients.ThreejsReadsStandardBvhAsTheSourceMotion)
  endif()
  add_test(NAME ${name}
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_client_checks.sh ${client} $<TARGET_FILE:mocapfill>
                   $<TARGET_FILE:mocapfill_fk_dump> ${PROJECT_BINARY_DIR}/test-output/clients ${PROJECT_SOURCE_DIR}
                   ${MOCAPFILL_DATA_DIR})
  set_tests_properties(${name} PROPERTIES LABELS clients SKIP_RETURN_CODE 77 TIMEOUT 600)
endforeach()
