#pragma once

#include "rviz_plugins/labelled_point_tool.h"

namespace kinematic_coverage::rviz_plugins {

/// rviz tool "Set Start" (shortcut s): a left click sets the mission's start, published on
/// `start` for coverage_planner (docs/REFERENCE.md, Nodes and topics) and shown as a green sphere.
class StartTool : public LabelledPointTool {
 public:
  StartTool();
};

}  // namespace kinematic_coverage::rviz_plugins
