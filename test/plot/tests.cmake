kc_add_gtest(test_plot
  test/plot/coverage_plot_test.cpp
  test/plot/tracking_error_plot_test.cpp
  LIBRARIES kc_plot PkgConfig::CAIRO)
