# Humanoid rig mapping, rest-pose choice and proportions over real rigs (fixtures always,
# the shared corpus when present).
mocapfill_add_test(retargeting_tests
  CORPUS [=[^retargeting\.(RigMappingCorpus\.|RigMappingByPose\.NamesWithoutSidesCorpus$|RigMappingErrors\.NonHumanoidCorpus$|RestPose\.Geno$)]=]
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/retargeting_test.cc
  PREFIX retargeting.
  LIBS mocapfill_retargeting mocapfill_formats)
