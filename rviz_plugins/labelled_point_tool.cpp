#include "rviz_plugins/labelled_point_tool.h"

#include <OgrePlane.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>
#include <OgreVector3.h>
#include <geometry_msgs/PointStamped.h>
#include <ros/console.h>
#include <rviz/display_context.h>
#include <rviz/geometry.h>
#include <rviz/ogre_helpers/movable_text.h>
#include <rviz/ogre_helpers/shape.h>
#include <rviz/properties/string_property.h>
#include <rviz/viewport_mouse_event.h>

#include "rviz_plugins/topic_advertiser.h"

namespace kinematic_coverage::rviz_plugins {
namespace {

/// Marker sizes in metres: large enough to see on the 30 m lake at rviz's default zoom.
constexpr float kSphereDiameterM = 0.8f;
constexpr float kTextHeightM = 0.9f;

}  // namespace

LabelledPointTool::LabelledPointTool(const std::string& label, const std::string& default_topic,
                                     char shortcut_key, const Ogre::ColourValue& colour)
    : label_(label), default_topic_(default_topic), colour_(colour) {
  shortcut_key_ = shortcut_key;
  topic_property_ = new rviz::StringProperty(
      "Topic", QString::fromStdString(default_topic),
      QString("geometry_msgs/PointStamped topic on which a click publishes the %1 "
              "(relative names resolve in rviz's namespace).")
          .arg(QString::fromStdString(label)),
      getPropertyContainer(), SLOT(updateTopic()), this);
}

LabelledPointTool::~LabelledPointTool() {
  sphere_.reset();
  text_.reset();
  if (marker_node_ != nullptr) scene_manager_->destroySceneNode(marker_node_);
}

void LabelledPointTool::onInitialize() {
  marker_node_ = scene_manager_->getRootSceneNode()->createChildSceneNode();
  sphere_ = std::make_unique<rviz::Shape>(rviz::Shape::Sphere, scene_manager_, marker_node_);
  sphere_->setColor(colour_);
  sphere_->setScale(Ogre::Vector3(kSphereDiameterM, kSphereDiameterM, kSphereDiameterM));
  text_ = std::make_unique<rviz::MovableText>(label_, "Liberation Sans", kTextHeightM, colour_);
  text_->setTextAlignment(rviz::MovableText::H_CENTER, rviz::MovableText::V_ABOVE);
  text_->setLocalTranslation(Ogre::Vector3(0.0f, kSphereDiameterM, 0.0f));
  text_->showOnTop();
  marker_node_->attachObject(text_.get());
  marker_node_->setVisible(false);
  updateTopic();
}

void LabelledPointTool::activate() {
  setStatus(QString("Left click on the ground plane sets the %1. Esc leaves the tool.")
                .arg(QString::fromStdString(label_)));
}

void LabelledPointTool::deactivate() {}

int LabelledPointTool::processMouseEvent(rviz::ViewportMouseEvent& event) {
  Ogre::Plane ground(Ogre::Vector3::UNIT_Z, 0.0f);
  Ogre::Vector3 point;
  if (!rviz::getPointOnPlaneFromWindowXY(event.viewport, ground, event.x, event.y, point)) {
    setStatus("The view does not show the ground plane z = 0 here.");
    return 0;
  }
  const QString label = QString::fromStdString(label_);
  if (!event.leftUp()) {
    setStatus(QString("Left click sets the %1 at (%2, %3) in %4.")
                  .arg(label)
                  .arg(point.x, 0, 'f', 2)
                  .arg(point.y, 0, 'f', 2)
                  .arg(context_->getFixedFrame()));
    return 0;
  }
  setPoint(point);
  setStatus(QString("%1 set to (%2, %3) in %4.")
                .arg(label)
                .arg(point.x, 0, 'f', 2)
                .arg(point.y, 0, 'f', 2)
                .arg(context_->getFixedFrame()));
  return Render | Finished;
}

void LabelledPointTool::updateTopic() {
  const std::string topic = topic_property_->getStdString();
  const std::optional<std::string> problem =
      advertiseTopic<geometry_msgs::PointStamped>(node_, topic, default_topic_, false, &publisher_);
  if (!problem) return;
  const QString message =
      QString(
          "Topic \"%1\" is not a valid topic name (%2); the %3 is still "
          "published on %4.")
          .arg(QString::fromStdString(topic), QString::fromStdString(*problem),
               QString::fromStdString(label_), QString::fromStdString(publisher_.getTopic()));
  ROS_ERROR("%s tool: %s", label_.c_str(), message.toStdString().c_str());
  setStatus(message);
}

void LabelledPointTool::setPoint(const Ogre::Vector3& point) {
  geometry_msgs::PointStamped message;
  message.header.frame_id = context_->getFixedFrame().toStdString();
  message.header.stamp = ros::Time::now();
  message.point.x = point.x;
  message.point.y = point.y;
  message.point.z = 0.0;
  publisher_.publish(message);
  marker_node_->setPosition(point.x, point.y, 0.0f);
  marker_node_->setVisible(true);
}

}  // namespace kinematic_coverage::rviz_plugins
