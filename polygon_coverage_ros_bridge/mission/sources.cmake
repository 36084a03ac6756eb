kc_add_stage_library(kc_mission
  SOURCES
    polygon_coverage_ros_bridge/mission/geojson_mission_reader.cpp
    polygon_coverage_ros_bridge/mission/local_east_north_frame.cpp
    polygon_coverage_ros_bridge/mission/mission_file_reader.cpp
    polygon_coverage_ros_bridge/mission/mission_file_writer.cpp
    polygon_coverage_ros_bridge/mission/mission_planner.cpp
    polygon_coverage_ros_bridge/mission/pose_csv_reader.cpp
    polygon_coverage_ros_bridge/mission/read_mission.cpp
    polygon_coverage_ros_bridge/mission/trajectory_coverage.cpp
    polygon_coverage_ros_bridge/mission/trajectory_pipeline.cpp
    polygon_coverage_ros_bridge/mission/wall_clearance_warning.cpp
    polygon_coverage_ros_bridge/mission/yaml_parameter_reader.cpp
  DEPENDS kc_geometry kc_validation kc_sweeps kc_coverage kc_trajectory kc_parameters kc_planner
    yaml-cpp)
# GeographicLib (the local east-north frame of GeoJSON missions) stays out of the headers.
target_include_directories(kc_mission PRIVATE ${GeographicLib_INCLUDE_DIRS})
target_link_libraries(kc_mission PRIVATE ${GeographicLib_LIBRARIES})
# The drawing model of the rviz Draw Polygon tool: a library of its own, so that the rviz
# plugins link only it and the validator, not the planner.
kc_add_stage_library(kc_polygon_sketch
  SOURCES
    polygon_coverage_ros_bridge/mission/polygon_sketch.cpp
  DEPENDS kc_geometry kc_validation)
