# The rviz plugins (catkin builds only): the Set Start, Set Goal and Draw Polygon tools and
# the Activate panel. rviz is found here, not in catkin's COMPONENTS, so only this library links
# Ogre and Qt; AUTOMOC is on for this target only.
find_package(rviz REQUIRED)
find_package(pluginlib REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Widgets)

add_library(${PROJECT_NAME}_rviz_plugins SHARED
  rviz_plugins/activate_panel.cpp
  rviz_plugins/goal_tool.cpp
  rviz_plugins/labelled_point_tool.cpp
  rviz_plugins/polygon_tool.cpp
  rviz_plugins/start_tool.cpp)
set_target_properties(${PROJECT_NAME}_rviz_plugins PROPERTIES AUTOMOC ON)
add_dependencies(${PROJECT_NAME}_rviz_plugins ${PROJECT_NAME}_generate_messages_cpp)
target_include_directories(${PROJECT_NAME}_rviz_plugins PRIVATE ${PROJECT_SOURCE_DIR})
target_include_directories(${PROJECT_NAME}_rviz_plugins SYSTEM PRIVATE
  ${rviz_INCLUDE_DIRS} ${pluginlib_INCLUDE_DIRS} ${catkin_INCLUDE_DIRS})
# Draw Polygon edits a core::PolygonSketch: the drawing model and the validator only.
target_link_libraries(${PROJECT_NAME}_rviz_plugins PRIVATE kc_polygon_sketch
  ${rviz_LIBRARIES} ${pluginlib_LIBRARIES} ${catkin_LIBRARIES} Qt5::Widgets)
target_compile_options(${PROJECT_NAME}_rviz_plugins PRIVATE -Wall -Wextra)

install(TARGETS ${PROJECT_NAME}_rviz_plugins
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES rviz_plugins/plugin_description.xml
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/rviz_plugins)
