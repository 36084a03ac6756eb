kc_add_stage_library(kc_mission
  SOURCES
    polygon_coverage_ros_bridge/mission/command_line.cpp
    polygon_coverage_ros_bridge/mission/evaluate_command.cpp
    polygon_coverage_ros_bridge/mission/json_object.cpp
    polygon_coverage_ros_bridge/mission/mission_file_reader.cpp
    polygon_coverage_ros_bridge/mission/mission_planner.cpp
    polygon_coverage_ros_bridge/mission/plan_command.cpp
    polygon_coverage_ros_bridge/mission/plan_output_writer.cpp
    polygon_coverage_ros_bridge/mission/pose_csv_reader.cpp
    polygon_coverage_ros_bridge/mission/replan_command.cpp
    polygon_coverage_ros_bridge/mission/simulate_command.cpp
    polygon_coverage_ros_bridge/mission/trajectory_coverage.cpp
    polygon_coverage_ros_bridge/mission/waypoint_csv_writer.cpp
  DEPENDS kc_validation kc_planner kc_trajectory kc_coverage kc_replanning kc_plot kc_simulation kc_geometry yaml-cpp)
