#include "rviz_plugins/goal_tool.h"

#include <pluginlib/class_list_macros.hpp>

namespace kinematic_coverage::rviz_plugins {

// The planner's marker colour for the goal (plan_markers.cpp), so both read alike.
GoalTool::GoalTool()
    : LabelledPointTool("goal", "goal", 'g', Ogre::ColourValue(0.5f, 0.2f, 0.6f, 0.8f)) {}

}  // namespace kinematic_coverage::rviz_plugins

PLUGINLIB_EXPORT_CLASS(kinematic_coverage::rviz_plugins::GoalTool, rviz::Tool)
