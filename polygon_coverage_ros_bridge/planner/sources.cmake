kc_add_stage_library(kc_planner
  SOURCES
    polygon_coverage_ros_bridge/planner/coverage_planner.cpp
    polygon_coverage_ros_bridge/planner/planning_limits.cpp
    polygon_coverage_ros_bridge/planner/reachable_offset_parts.cpp
    polygon_coverage_ros_bridge/planner/replanner.cpp
  DEPENDS kc_geometry kc_validation kc_decomposition kc_sweeps kc_route kc_gtsp kc_repair
    kc_parameters kc_replanning)
