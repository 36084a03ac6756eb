kc_add_stage_library(kc_geometry
  SOURCES
    polygon_coverage_ros_bridge/geometry/boundary_simplification.cpp
    polygon_coverage_ros_bridge/geometry/edge_grid.cpp
    polygon_coverage_ros_bridge/geometry/nearest_segment_index.cpp
    polygon_coverage_ros_bridge/geometry/planar_geometry.cpp
    polygon_coverage_ros_bridge/geometry/wall_offset.cpp
    polygon_coverage_ros_bridge/geometry/region_intersection.cpp
  CGAL)
# The wall offset's mitred offsets and Boolean operations: Clipper 1 (libpolyclipping-dev).
pkg_check_modules(POLYCLIPPING REQUIRED IMPORTED_TARGET polyclipping)
target_link_libraries(kc_geometry PRIVATE PkgConfig::POLYCLIPPING)
