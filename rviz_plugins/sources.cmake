# The rviz plugins (catkin builds only): the Set Start and Set Goal tools and the
# Activate panel. rviz is found here, not in catkin's COMPONENTS, so only this library links
# Ogre and Qt; AUTOMOC is on for this target only.
find_package(rviz REQUIRED)
find_package(pluginlib REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Widgets)

add_library(kinematic_coverage_rviz_plugins SHARED
  rviz_plugins/labelled_point_tool.cpp
  rviz_plugins/start_tool.cpp
  rviz_plugins/goal_tool.cpp
  rviz_plugins/activate_panel.cpp)
set_target_properties(kinematic_coverage_rviz_plugins PROPERTIES AUTOMOC ON)
target_include_directories(kinematic_coverage_rviz_plugins PRIVATE ${PROJECT_SOURCE_DIR})
target_include_directories(kinematic_coverage_rviz_plugins SYSTEM PRIVATE
  ${rviz_INCLUDE_DIRS} ${pluginlib_INCLUDE_DIRS} ${catkin_INCLUDE_DIRS})
target_link_libraries(kinematic_coverage_rviz_plugins PRIVATE
  ${rviz_LIBRARIES} ${pluginlib_LIBRARIES} ${catkin_LIBRARIES} Qt5::Widgets)
target_compile_options(kinematic_coverage_rviz_plugins PRIVATE -Wall -Wextra)

install(TARGETS kinematic_coverage_rviz_plugins
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES rviz_plugins/plugin_description.xml
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/rviz_plugins)
