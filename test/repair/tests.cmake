kc_add_gtest(test_repair
  test/repair/exact_offset_excursions_test.cpp
  test/repair/unseen_area_repair_test.cpp
  test/support/hard_map_generator.cpp
  LIBRARIES kc_parameters kc_repair kc_mission)
