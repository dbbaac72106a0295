# Fill methods on the embedded default database and the shipped sketch.
# The held-out evaluations (each fills every take of the corpus or database) are `slow`: under
# the sanitizers they take minutes each, and the smaller fill tests run the same code there.
mocapfill_add_test(fill_tests
  SLOW [=[^(Fill\.(SynthesisedLegsBlendFewerCandidates|TakesTravellingOnARootBoneAboveTheHipsBeatTheMeanPose|SynthesisedLegsAreMatchedOnTheHipsTheyHangFrom|MovingSketchesWithKeyedLegsTakeTheirUpperBodyByGaitNotPace|StandingSketchesTakeTheirUpperBodyFromStandingTakes|LeadDetailBringsTheJitterOfHeldOutTakesTowardsTheCaptures|TimidGesturesTakeDetailAsLivelyAsTheirKeys)|LocalRegression\.LowersTheErrorOfHeldOutTakes|LimbReach\.LowersTheErrorOfHeldOutTakes|ConsensusWeights\.LowersTheErrorOfHeldOutTakes|GaitSway\.(SynthesisedLegs|SlowWalks)StepOnTheFootTheHipsSwayOver|StretchedTravel\.SynthesisedLegsStepAtTheSketchsPace|SwingGain\.LowersTheErrorOfHeldOutTakes)$]=]
  CORPUS [=[^(Fill\.(HierarchicalBeatsTheMeanPoseOnACapturedWalkOfAnUnseenStyle|TakesTravellingOnARootBoneAboveTheHipsBeatTheMeanPose|SynthesisedLegsAreMatchedOnTheHipsTheyHangFrom|MovingSketchesWithKeyedLegsTakeTheirUpperBodyByGaitNotPace|StandingSketchesTakeTheirUpperBodyFromStandingTakes|SynthesisedJointsAreAboutAsSmoothAsTheCapture|LeadDetailBringsTheJitterOfHeldOutTakesTowardsTheCaptures|TimidGesturesTakeDetailAsLivelyAsTheirKeys|SynthesisedLegsBlendFewerCandidates)|LocalRegression\.LowersTheErrorOfHeldOutTakes|LimbReach\.LowersTheErrorOfHeldOutTakes|ConsensusWeights\.LowersTheErrorOfHeldOutTakes|GaitSway\.(SynthesisedLegs|SlowWalks)StepOnTheFootTheHipsSwayOver|StretchedTravel\.SynthesisedLegsStepAtTheSketchsPace|SwingGain\.LowersTheErrorOfHeldOutTakes)$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fill_test.cc ${CMAKE_CURRENT_LIST_DIR}/local_regression_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/limb_reach_test.cc ${CMAKE_CURRENT_LIST_DIR}/consensus_weights_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/held_out_fill.cc ${CMAKE_CURRENT_LIST_DIR}/gait_sway_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/swing_gain_test.cc ${CMAKE_CURRENT_LIST_DIR}/stretched_travel_test.cc
  LIBS mocapfill_test_default_db mocapfill_evaluation mocapfill_fill mocapfill_synthesis mocapfill_texturing
       mocapfill_formats)

# PCA-based fill methods: `pca` (closed form) and `hybrid`.
mocapfill_add_test(hybrid_fill_tests
  SLOW [=[^HybridFill\.FootPositionKeysHoldWithinACentimetre$]=]
  CORPUS [=[^HybridFill\.CapturedWalkOfAnUnseenStyleBeatsTheMeanPose$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/hybrid_fill_test.cc
  LIBS mocapfill_test_default_db mocapfill_evaluation mocapfill_fill mocapfill_hybrid mocapfill_pca mocapfill_formats)

# Leave-one-style-out over the shared corpus's walks: hybrid against hierarchical (skips visibly
# without ../shared/data).
mocapfill_add_test(hybrid_loso_tests
  SLOW [=[.]=]
  CORPUS [=[.]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/hybrid_loso_test.cc
  LIBS mocapfill_evaluation mocapfill_mfdb mocapfill_formats)

# Coverage of the sketch by the database: warnings and blending towards the mean pose.
mocapfill_add_test(coverage_tests
  SLOW [=[^Coverage\.DanceAgainstTheDefaultDatabaseWarnsAndIsNoWorseThanMean$]=]
  CORPUS [=[^Coverage\.(DanceAgainstTheDefaultDatabaseWarnsAndIsNoWorseThanMean|CapturedWalkOfAnotherStyleIsCovered)$]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/coverage_test.cc
  LIBS mocapfill_test_default_db mocapfill_sketch_fill mocapfill_evaluation mocapfill_fill mocapfill_synthesis
       mocapfill_formats)
