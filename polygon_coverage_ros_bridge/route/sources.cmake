kc_add_stage_library(kc_route
  SOURCES
    polygon_coverage_ros_bridge/route/segment_cost.cpp
    polygon_coverage_ros_bridge/route/boundary_grid.cpp
    polygon_coverage_ros_bridge/route/visibility_graph.cpp
    polygon_coverage_ros_bridge/route/jog_removal.cpp
    polygon_coverage_ros_bridge/route/offset_part_joiner.cpp
  DEPENDS kc_geometry)
# The visibility graph's tests run on every hardware thread (base/parallel_for.h).
target_link_libraries(kc_route PUBLIC Threads::Threads)
