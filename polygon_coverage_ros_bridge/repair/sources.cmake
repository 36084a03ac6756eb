kc_add_stage_library(kc_repair
  SOURCES
    polygon_coverage_ros_bridge/repair/exact_offset_excursions.cpp
    polygon_coverage_ros_bridge/repair/unseen_area_repair.cpp
  DEPENDS kc_geometry kc_route kc_sweeps kc_coverage)
