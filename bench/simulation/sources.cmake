# The thesis's experiments as a sensitivity study of the simulated robot's controllers
# (docs/EXPERIMENTS.md, by scripts/run_experiments.sh).
kc_add_executable(controller_study bench/simulation/controller_study.cpp)
target_link_libraries(${PROJECT_NAME}_controller_study PRIVATE kc_mission kc_parameters kc_simulation)
