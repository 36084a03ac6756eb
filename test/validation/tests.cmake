kc_add_gtest(test_validation
  test/validation/parameter_validator_test.cpp
  test/validation/polygon_validator_test.cpp
  test/validation/polygon_cleaner_test.cpp
  LIBRARIES kc_validation)
