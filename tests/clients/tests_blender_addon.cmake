# The Blender add-on (blender/mocapfill_blender) in a headless Blender, through its operator:
# it keys hips and legs of a character (the corpus' Geno.fbx, or a shipped fixture rig when the
# corpus is absent), fills the action and checks the keys hold and the rest moves. Labelled
# `clients`; skipped (77) without Blender. Not under the sanitizers: Blender is not instrumented.
if(MOCAPFILL_SANITIZE)
  return()
endif()

# --coverage warn: a sketch on a rig other than the database's comes out of the retargeting
# onto the database's rig with per-bone yaw offsets (its rest is a captured frame or the
# database's mean pose), so coverage judges it unexplained and `blend` would fade the
# synthesised bones to the mean pose; the add-on is tested as an interface here, and that
# defect is the fill's (issue notes, 2026-12-04).
if(MOCAPFILL_HAS_PYTHON)
  add_test(NAME clients.blender_addon
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_blender.sh ${CMAKE_CURRENT_LIST_DIR}/blender_addon_test.py
                   ${MOCAPFILL_DATA_DIR}/geno/Geno.fbx --coverage warn)
  set_tests_properties(clients.blender_addon PROPERTIES LABELS clients SKIP_RETURN_CODE 77 TIMEOUT 120
                       ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python")
endif()
