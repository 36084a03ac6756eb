pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)

kc_add_stage_library(kc_plot
  SOURCES
    trajectory_generation_tools/plot/coverage_plot.cpp
    trajectory_generation_tools/plot/map_overlays.cpp
    trajectory_generation_tools/plot/path_style.cpp
    trajectory_generation_tools/plot/plot_canvas.cpp
    trajectory_generation_tools/plot/tracking_error_plot.cpp
  DEPENDS kc_geometry kc_sweeps)
# Cairo stays out of the headers, so only this library links it.
target_link_libraries(kc_plot PRIVATE PkgConfig::CAIRO)
