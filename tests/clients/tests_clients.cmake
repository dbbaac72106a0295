# The client checks: what mocapfill writes, read by Blender's glTF importer and three.js's
# BVHLoader and compared with mocapfill's forward kinematics (ctest label `clients`; each
# skips, exit 77, when its client is not installed).
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
