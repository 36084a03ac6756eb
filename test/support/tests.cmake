kc_add_gtest(test_support
  test/support/hard_map_generator.cpp
  test/support/hard_map_generator_test.cpp
  test/support/lake_map_generator.cpp
  test/support/lake_map_generator_test.cpp
  LIBRARIES kc_parameters kc_validation kc_sweeps kc_mission)
