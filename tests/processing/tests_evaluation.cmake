# Sketch making, fill metrics and the fill methods on real data.
mocapfill_add_test(evaluation_tests
  CORPUS [=[^(SketchMaker\.|FillMetrics\.(TruthAgainstItselfScoresZero|SketchAgainstTruthMeasuresTheMissingUpperBody|SummariesPoolFootSkatingOverContactFrames|FloorGlideMeasuresFeetDraggedAlongTheGround|SlideSeparatesAFootDraggedFromAStepOutOfTime)$|FoldPlan\.Corpus)]=]
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/evaluation_test.cc
    ${CMAKE_CURRENT_LIST_DIR}/protocol_test.cc
  LIBS mocapfill_evaluation mocapfill_formats mocapfill_mfdb)
