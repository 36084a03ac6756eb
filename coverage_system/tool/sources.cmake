# coverage_tool's subcommands, their argument parsing and their output files; the entry
# point itself (coverage_tool_main.cpp) is the executable of the root CMakeLists.txt.
kc_add_stage_library(kc_tool
  SOURCES
    coverage_system/tool/autopilot_mission_writer.cpp
    coverage_system/tool/command_line.cpp
    coverage_system/tool/coverage_metrics.cpp
    coverage_system/tool/evaluate_command.cpp
    coverage_system/tool/export_command.cpp
    coverage_system/tool/geojson_writer.cpp
    coverage_system/tool/json_object.cpp
    coverage_system/tool/parameters_command.cpp
    coverage_system/tool/plan_command.cpp
    coverage_system/tool/plan_output_writer.cpp
    coverage_system/tool/replan_command.cpp
    coverage_system/tool/simulate_command.cpp
    coverage_system/tool/trajectory_csv_writer.cpp
    coverage_system/tool/waypoint_csv_writer.cpp
  DEPENDS kc_geometry kc_validation kc_gtsp kc_route kc_coverage kc_smoothing kc_trajectory kc_plot
    kc_simulation kc_parameters kc_planner kc_mission)
