# Rest-pose-aware retargeting between real rigs and the any-rig fill use case.
add_library(mocapfill_test_bone_directions STATIC ${CMAKE_CURRENT_LIST_DIR}/../support/bone_directions.cc)
target_link_libraries(mocapfill_test_bone_directions PUBLIC mocapfill_retargeting)
mocapfill_set_warnings(mocapfill_test_bone_directions)

mocapfill_add_test(retarget_transfer_tests
  CORPUS [=[^RetargetTransfer\.GenoBindAndStanceFirstFramesAgree$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/retarget_transfer_test.cc
  LIBS mocapfill_retargeting mocapfill_formats mocapfill_test_bone_directions)

mocapfill_add_test(sketch_fill_tests
  SLOW [=[^(SketchFill\.(PositionKeysHoldTheFeet|PositionKeysHoldTheFeetOnGeno|GenoSketchScoresLikeTheBandaiRig|GenoSynthesisedFeetStandOnTheTakesContacts)|FootPlant\.(FilledContactsMatchTheCapture|SynthesisedFeetStandWhereTheTakesStood|StandingSynthesisedFeetStayStillAndOnTheGround|SparselyKeyedFeetAlsoStandWhereTheirTexturesTakeStood|SparselyKeyedFeetStandAtTheKeysTheyStandOn|SparselyKeyedFeetAreHeldWhereTheirTakeStoodFarFromTheSlerp|FeetKeyedStillStandBetweenSparseKeys|StillHipsStayStillOverPlantedFeet|SynthesisedLegsTravelWithTheRoot|SparselyKeyedFeetStandWhileTheHipsPassOverThem|KeyedLegsLetLargeCorrectionsGoSlowly|SparselyKeyedSwingsClearTheFloorLikeTheCapture|SparselyKeyedRunsStandOnTheTakesContactsBetweenKeys|HoldsEndAtTheirStillKeysWhereTheKeysMoveTheFootOn|KeyedHoldsStartNoNearerTheirKeyThanTheFootCanReach))$]=]
  CORPUS [=[^(SketchFill\.(CmuCorpusSketchHasNoFlips|PositionKeysHoldTheFeetOnGeno|GenoSketchScoresLikeTheBandaiRig|GenoSynthesisedFeetStandOnTheTakesContacts)|FootPlant\.(FilledContactsMatchTheCapture|SynthesisedFeetStandWhereTheTakesStood|StandingSynthesisedFeetStayStillAndOnTheGround|SparselyKeyedFeetAlsoStandWhereTheirTexturesTakeStood|SparselyKeyedFeetStandAtTheKeysTheyStandOn|SparselyKeyedFeetAreHeldWhereTheirTakeStoodFarFromTheSlerp|FeetKeyedStillStandBetweenSparseKeys|StillHipsStayStillOverPlantedFeet|SynthesisedLegsTravelWithTheRoot|SparselyKeyedFeetStandWhileTheHipsPassOverThem|KeyedLegsLetLargeCorrectionsGoSlowly|SparselyKeyedSwingsClearTheFloorLikeTheCapture|SparselyKeyedRunsStandOnTheTakesContactsBetweenKeys|HoldsEndAtTheirStillKeysWhereTheKeysMoveTheFootOn|KeyedHoldsStartNoNearerTheirKeyThanTheFootCanReach))$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sketch_fill_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/foot_plant_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/../support/sparse_sketch.cc
  LIBS mocapfill_test_default_db mocapfill_test_gltf mocapfill_sketch_fill mocapfill_evaluation mocapfill_formats mocapfill_mfdb mocapfill_gltf mocapfill_test_tinygltf
       mocapfill_test_bone_directions)

# Two-bone IK (processing/motion/two_bone_ik.h), which holds position keys on any rig.
mocapfill_add_test(two_bone_ik_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/two_bone_ik_test.cc
  LIBS mocapfill_motion mocapfill_formats)

# Swing clearance's timing (processing/motion/swing_clearance.h).
mocapfill_add_test(swing_clearance_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/swing_clearance_test.cc
  LIBS mocapfill_motion)

# Left/right mirroring of clips on their own rig (processing/motion/mirror.h).
mocapfill_add_test(mirror_tests
  CORPUS [=[^Mirror\.GenoFingersPairByName$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/mirror_test.cc
  LIBS mocapfill_database mocapfill_motion mocapfill_retargeting mocapfill_formats)
