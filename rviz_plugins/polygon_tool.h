#pragma once

#ifndef Q_MOC_RUN
#include <OgrePrerequisites.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <rviz/tool.h>

#include "coverage_system/mission/polygon_sketch.h"
#endif

#include <memory>
#include <optional>
#include <vector>

namespace rviz {
class BillboardLine;
class Shape;
class StringProperty;
}  // namespace rviz

namespace kinematic_coverage::rviz_plugins {

/// rviz tool "Draw Polygon" (shortcut p): the survey operator draws the area to cover on the
/// ground plane z = 0 of the fixed frame, the hull first, then each hole. A left click adds a
/// vertex to the open ring; a right click, or a click on the open ring's first vertex, closes
/// it; dragging a vertex moves it; Shift + left click on a vertex deletes it (a closed ring
/// left with 2 vertices is removed); leaving the tool (Esc) drops the open ring. Every edit is
/// checked with PolygonValidator (core::PolygonSketch): the closed rings are drawn red when
/// invalid, and the status bar names the problem in the validator's words. Whenever all rings
/// are closed and valid the polygon is published as kinematic_coverage/PolygonWithHolesStamped
/// (latched) in the fixed frame for coverage_planner; an invalid or unfinished drawing is never
/// published, so the nodes keep the last valid polygon.
class PolygonTool : public rviz::Tool {
  Q_OBJECT

 public:
  PolygonTool();
  ~PolygonTool() override;

  void onInitialize() override;
  void activate() override;
  /// Drops the open ring (Esc leaves every rviz tool); the closed rings stay drawn.
  void deactivate() override;

  /// Adds, closes, moves and deletes vertices (class comment) and shows in the status bar
  /// what a click does or what is wrong.
  int processMouseEvent(rviz::ViewportMouseEvent& event) override;

 private Q_SLOTS:
  /// Advertises on the topic the Topic property names. An invalid name (ros::names::validate)
  /// keeps the topic advertised so far and says so in the status bar and with ROS_ERROR.
  void updateTopic();

 private:
  /// Handles a left press: deletes (with Shift) or grabs the vertex under the cursor.
  int pressLeft(rviz::ViewportMouseEvent& event, const core::Point2& point, double tolerance);
  /// Handles a left release: ends a drag, closes the open ring on its first vertex or adds a
  /// vertex.
  int releaseLeft(const core::Point2& point);
  /// After an edit: redraws, tells the status, and publishes a complete valid polygon.
  void editDone(const QString& what);
  /// Draws every ring in its colour (valid, invalid, open) with a sphere at each vertex.
  void redraw();
  /// The status line for the sketch as it is: what is wrong or how to go on.
  QString statusText() const;
  void publish(const core::PolygonWithHoles& polygon);

  rviz::StringProperty* topic_property_;
  ros::NodeHandle node_;
  ros::Publisher publisher_;
  core::PolygonSketch sketch_;
  /// The vertex under the left button since its press, and whether it has been dragged.
  std::optional<core::PolygonSketch::VertexId> grabbed_;
  bool grabbed_moved_ = false;
  int press_x_ = 0;
  int press_y_ = 0;
  /// Whether the left button went down on the ground away from any vertex (a release adds).
  bool press_adds_ = false;
  Ogre::SceneNode* scene_node_ = nullptr;
  std::vector<std::unique_ptr<rviz::BillboardLine>> lines_;
  std::vector<std::unique_ptr<rviz::Shape>> vertices_;
};

}  // namespace kinematic_coverage::rviz_plugins
