kc_add_stage_library(kc_mission
  SOURCES
    coverage_system/mission/autopilot_mission.cpp
    coverage_system/mission/geojson_mission_reader.cpp
    coverage_system/mission/local_east_north_frame.cpp
    coverage_system/mission/mission_file_reader.cpp
    coverage_system/mission/mission_file_writer.cpp
    coverage_system/mission/mission_frame.cpp
    coverage_system/mission/mission_planner.cpp
    coverage_system/mission/pose_csv_reader.cpp
    coverage_system/mission/read_mission.cpp
    coverage_system/mission/trajectory_coverage.cpp
    coverage_system/mission/trajectory_pipeline.cpp
    coverage_system/mission/utm_zone_frame.cpp
    coverage_system/mission/wall_clearance_warning.cpp
    coverage_system/mission/yaml_parameter_reader.cpp
  DEPENDS kc_geometry kc_validation kc_sweeps kc_path kc_coverage kc_trajectory kc_parameters
    kc_planner
    yaml-cpp)
# GeographicLib (the local and UTM frames of GeoJSON missions) stays out of the headers.
target_include_directories(kc_mission PRIVATE ${GeographicLib_INCLUDE_DIRS})
target_link_libraries(kc_mission PRIVATE ${GeographicLib_LIBRARIES})
# The drawing model of the rviz Draw Polygon tool: a library of its own, so that the rviz
# plugins link only it and the validator, not the planner.
kc_add_stage_library(kc_polygon_sketch
  SOURCES
    coverage_system/mission/polygon_sketch.cpp
  DEPENDS kc_geometry kc_validation)
