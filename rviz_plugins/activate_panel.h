#pragma once

#ifndef Q_MOC_RUN
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_client.h>
#include <rviz/panel.h>
#endif

class QLabel;

namespace kinematic_coverage::rviz_plugins {

/// rviz panel with an "Activate" button (Alt+A) that publishes std_msgs/Empty on `activate`:
/// coverage_planner then plans with the newest polygon, start and goal (docs/REFERENCE.md,
/// Nodes and topics). Together with the Start and Goal tools it is the thesis's set-then-activate
/// workflow (Fig. 3.14). A line under the button says when it last sent and whether anyone
/// listens. "Save mission..." writes the polygon, start and goal coverage_planner holds, with
/// its parameters, as a mission file (its `~save_mission` service) that `coverage_tool plan`
/// and mission.launch read back.
class ActivatePanel : public rviz::Panel {
  Q_OBJECT

 public:
  explicit ActivatePanel(QWidget* parent = nullptr);

 private Q_SLOTS:
  /// Publishes one activate message and reports it.
  void sendActivate();
  /// Asks for a file name and calls coverage_planner's `~save_mission` with it.
  void saveMission();

 private:
  ros::NodeHandle node_;
  ros::Publisher publisher_;
  ros::ServiceClient save_client_;
  QLabel* status_label_;
};

}  // namespace kinematic_coverage::rviz_plugins
