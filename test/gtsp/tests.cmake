kc_add_gtest(test_gtsp
  test/gtsp/gtsp_solver_test.cpp
  test/gtsp/gtsplib_reader_test.cpp
  test/gtsp/gtsp_command_test.cpp
  LIBRARIES kc_gtsp)
