# kc_add_executable(NAME src...): an executable NAME whose target is ${PROJECT_NAME}_NAME, so
# that in a catkin workspace its target cannot clash with another package's (replanner,
# coverage_tool), while the program keeps its name (OUTPUT_NAME) for rosrun and launch files.
function(kc_add_executable name)
  add_executable(${PROJECT_NAME}_${name} ${ARGN})
  set_target_properties(${PROJECT_NAME}_${name} PROPERTIES OUTPUT_NAME ${name})
endfunction()
