kc_add_stage_library(kc_planner
  SOURCES
    coverage_system/planner/coverage_planner.cpp
    coverage_system/planner/lazy_transition_costs.cpp
    coverage_system/planner/planning_limits.cpp
    coverage_system/planner/reachable_offset_parts.cpp
    coverage_system/planner/replanner.cpp
  DEPENDS kc_geometry kc_validation kc_decomposition kc_sweeps kc_route kc_gtsp kc_repair
    kc_parameters kc_replanning)
