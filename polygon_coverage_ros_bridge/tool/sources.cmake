# coverage_tool's subcommands, their argument parsing and their output files; the entry
# point itself (coverage_tool_main.cpp) is the executable of the root CMakeLists.txt.
kc_add_stage_library(kc_tool
  SOURCES
    polygon_coverage_ros_bridge/tool/command_line.cpp
    polygon_coverage_ros_bridge/tool/coverage_metrics.cpp
    polygon_coverage_ros_bridge/tool/evaluate_command.cpp
    polygon_coverage_ros_bridge/tool/export_command.cpp
    polygon_coverage_ros_bridge/tool/geojson_writer.cpp
    polygon_coverage_ros_bridge/tool/json_object.cpp
    polygon_coverage_ros_bridge/tool/parameters_command.cpp
    polygon_coverage_ros_bridge/tool/plan_command.cpp
    polygon_coverage_ros_bridge/tool/plan_output_writer.cpp
    polygon_coverage_ros_bridge/tool/replan_command.cpp
    polygon_coverage_ros_bridge/tool/simulate_command.cpp
    polygon_coverage_ros_bridge/tool/trajectory_csv_writer.cpp
    polygon_coverage_ros_bridge/tool/waypoint_csv_writer.cpp
  DEPENDS kc_geometry kc_validation kc_gtsp kc_route kc_coverage kc_smoothing kc_trajectory kc_plot
    kc_simulation kc_parameters kc_planner kc_mission)
