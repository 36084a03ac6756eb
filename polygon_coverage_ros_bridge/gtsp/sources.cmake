kc_add_stage_library(kc_gtsp
  SOURCES
    polygon_coverage_ros_bridge/gtsp/cluster_optimizer.cpp
    polygon_coverage_ros_bridge/gtsp/exact_gtsp_solver.cpp
    polygon_coverage_ros_bridge/gtsp/gtsp_instance.cpp
    polygon_coverage_ros_bridge/gtsp/gtsp_command.cpp
    polygon_coverage_ros_bridge/gtsp/gtsp_local_search.cpp
    polygon_coverage_ros_bridge/gtsp/gtsplib_reader.cpp
    polygon_coverage_ros_bridge/gtsp/memetic_gtsp_solver.cpp
  DEPENDS kc_geometry)
# The memetic heuristic improves a generation's children on every hardware thread.
target_link_libraries(kc_gtsp PUBLIC Threads::Threads)
