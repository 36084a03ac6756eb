kc_add_stage_library(kc_decomposition
  SOURCES
    polygon_coverage_ros_bridge/decomposition/sweep_direction.cpp
    polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.cpp
    polygon_coverage_ros_bridge/decomposition/best_decomposition.cpp
  DEPENDS kc_geometry)
# The candidate sweep directions are decomposed on every hardware thread.
target_link_libraries(kc_decomposition PUBLIC Threads::Threads)
