kc_add_gtest(test_planner
  test/planner/coverage_planner_test.cpp
  test/planner/lazy_transition_costs_test.cpp
  test/planner/mission_plans_test.cpp
  test/planner/plan_properties.cpp
  test/planner/planning_limits_test.cpp
  test/planner/reachable_offset_parts_test.cpp
  test/planner/replanner_test.cpp
  test/support/hard_map_generator.cpp
  LIBRARIES kc_planner kc_coverage kc_mission kc_validation kc_trajectory)
