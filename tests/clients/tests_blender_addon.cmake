# The Blender add-on (blender/mocapfill_blender) in a headless Blender, through its operator:
# it keys hips and legs of a character (the corpus' Geno.fbx, or a shipped fixture rig when the
# corpus is absent), fills the action and checks the keys hold and the rest moves. Labelled
# `clients`; skipped (77) without Blender. Not under the sanitizers: Blender is not instrumented.
if(MOCAPFILL_SANITIZE)
  return()
endif()

# With the operator's defaults (coverage blend): the sketch on Geno's rig must reach the
# database as well covered as on the database's own rig, or its synthesised bones would be
# faded to the mean pose and the test's "synthesised bones move" check fails.
if(MOCAPFILL_HAS_PYTHON)
  add_test(NAME clients.blender_addon
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_blender.sh ${CMAKE_CURRENT_LIST_DIR}/blender_addon_test.py
                   ${MOCAPFILL_DATA_DIR}/geno/Geno.fbx)
  set_tests_properties(clients.blender_addon PROPERTIES LABELS clients SKIP_RETURN_CODE 77 TIMEOUT 120
                       ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python")
endif()
