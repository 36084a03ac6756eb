kc_add_stage_library(kc_mission
  SOURCES
    polygon_coverage_ros_bridge/mission/mission_file_reader.cpp
    polygon_coverage_ros_bridge/mission/mission_planner.cpp
    polygon_coverage_ros_bridge/mission/pose_csv_reader.cpp
    polygon_coverage_ros_bridge/mission/trajectory_coverage.cpp
  DEPENDS kc_geometry kc_validation kc_sweeps kc_coverage kc_parameters kc_planner yaml-cpp)
