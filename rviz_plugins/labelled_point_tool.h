#pragma once

#ifndef Q_MOC_RUN
#include <OgreColourValue.h>
#include <OgrePrerequisites.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <rviz/tool.h>
#endif

#include <memory>
#include <string>

namespace rviz {
class MovableText;
class Shape;
class StringProperty;
}  // namespace rviz

namespace kinematic_coverage::rviz_plugins {

/// An rviz tool that sets one named point of the mission (start or goal) with a left click on
/// the ground plane z = 0 of the fixed frame: it publishes the point as
/// geometry_msgs/PointStamped in the fixed frame and shows it as a sphere labelled with the
/// point's name, until the next click moves it. It replaces rviz's Publish Point, whose one
/// topic for every point made a wrong click unrecoverable (thesis Fig. 3.14); the planner
/// only plans on `activate` (by default), so a point can be set again any number of
/// times before.
class LabelledPointTool : public rviz::Tool {
  Q_OBJECT

 public:
  /// `label` names the point in the scene and the status bar ("start"), `default_topic` is
  /// the Topic property's default (relative, so rviz's namespace and remappings apply),
  /// `shortcut_key` selects the tool in the render panel, `colour` is the marker's.
  LabelledPointTool(const std::string& label, const std::string& default_topic, char shortcut_key,
                    const Ogre::ColourValue& colour);
  ~LabelledPointTool() override;

  void onInitialize() override;
  void activate() override;
  void deactivate() override;

  /// Shows where a click would set the point; a left click sets it, publishes it and hands
  /// back to the default tool, as rviz's own point and goal tools do.
  int processMouseEvent(rviz::ViewportMouseEvent& event) override;

 private Q_SLOTS:
  /// Advertises on the topic the Topic property names. An invalid name (ros::names::validate,
  /// e.g. "bad topic!" or "1abc") keeps the topic advertised so far and says so in the
  /// status bar and with ROS_ERROR.
  void updateTopic();

 private:
  /// Publishes `point` (fixed frame) and moves the marker there.
  void setPoint(const Ogre::Vector3& point);

  std::string label_;
  std::string default_topic_;
  Ogre::ColourValue colour_;
  rviz::StringProperty* topic_property_;
  ros::NodeHandle node_;
  ros::Publisher publisher_;
  Ogre::SceneNode* marker_node_ = nullptr;
  std::unique_ptr<rviz::Shape> sphere_;
  std::unique_ptr<rviz::MovableText> text_;
};

}  // namespace kinematic_coverage::rviz_plugins
