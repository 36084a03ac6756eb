kc_add_gtest(test_validation
  test/validation/polygon_validator_test.cpp
  test/validation/polygon_cleaner_test.cpp
  test/validation/free_area_builder_test.cpp
  LIBRARIES kc_validation)
