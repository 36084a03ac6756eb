#pragma once

#include "rviz_plugins/labelled_point_tool.h"

namespace kinematic_coverage::rviz_plugins {

/// rviz tool "Set Goal" (shortcut g): a left click sets the mission's goal, published on
/// `goal` for coverage_planner (docs/REFERENCE.md, Nodes and topics) and shown as a purple sphere.
class GoalTool : public LabelledPointTool {
 public:
  GoalTool();
};

}  // namespace kinematic_coverage::rviz_plugins
