#include "rviz_plugins/start_tool.h"

#include <pluginlib/class_list_macros.hpp>

namespace kinematic_coverage::rviz_plugins {

// The planner's marker colour for the start (plan_markers.cpp), so both read alike.
StartTool::StartTool()
    : LabelledPointTool("start", "start", 's', Ogre::ColourValue(0.1f, 0.7f, 0.2f, 0.8f)) {}

}  // namespace kinematic_coverage::rviz_plugins

PLUGINLIB_EXPORT_CLASS(kinematic_coverage::rviz_plugins::StartTool, rviz::Tool)
