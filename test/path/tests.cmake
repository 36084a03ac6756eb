kc_add_gtest(test_path
  test/path/path_primitive_test.cpp
  LIBRARIES kc_path)
