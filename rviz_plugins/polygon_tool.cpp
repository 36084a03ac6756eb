#include "rviz_plugins/polygon_tool.h"

#include <OgreColourValue.h>
#include <OgrePlane.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>
#include <OgreVector3.h>
#include <geometry_msgs/Polygon.h>
#include <ros/console.h>
#include <rviz/display_context.h>
#include <rviz/geometry.h>
#include <rviz/ogre_helpers/billboard_line.h>
#include <rviz/ogre_helpers/shape.h>
#include <rviz/properties/string_property.h>
#include <rviz/viewport_mouse_event.h>

#include <cstdlib>
#include <pluginlib/class_list_macros.hpp>
#include <string>

#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "rviz_plugins/topic_advertiser.h"

namespace kinematic_coverage::rviz_plugins {
namespace {

using core::PolygonSketch;

/// Drawing sizes in metres: visible on the 30 m lake at pipeline.rviz's zoom, thinner than
/// the start and goal spheres.
constexpr float kLineWidthM = 0.12f;
constexpr float kVertexDiameterM = 0.45f;
/// Just above the grid and the heatmap, so the rings are never hidden by them.
constexpr float kDrawHeightM = 0.02f;
/// The Topic property's default (relative, so rviz's namespace and remappings apply).
constexpr char kDefaultTopic[] = "polygon";
/// A vertex within this many pixels of the cursor is under it (grab, delete, close).
constexpr int kPickRadiusPx = 8;
/// A press that moves farther than this many pixels is a drag, not a click.
constexpr int kDragThresholdPx = 3;

const Ogre::ColourValue kValidColour(0.0f, 0.55f, 0.55f, 1.0f);
const Ogre::ColourValue kInvalidColour(0.9f, 0.1f, 0.1f, 1.0f);
const Ogre::ColourValue kOpenColour(1.0f, 0.65f, 0.0f, 1.0f);

/// The point of the ground plane z = 0 under the pixel (x, y), or none.
std::optional<core::Point2> groundPoint(Ogre::Viewport* viewport, int x, int y) {
  Ogre::Plane ground(Ogre::Vector3::UNIT_Z, 0.0f);
  Ogre::Vector3 point;
  if (!rviz::getPointOnPlaneFromWindowXY(viewport, ground, x, y, point)) return std::nullopt;
  return core::Point2(point.x, point.y);
}

QString formatPoint(const core::Point2& point) {
  return QString("(%1, %2)").arg(point.x(), 0, 'f', 2).arg(point.y(), 0, 'f', 2);
}

/// "vertex 2 of hole 0", as the validator numbers rings and vertices.
QString vertexName(const PolygonSketch::VertexId& vertex) {
  QString ring = "the open ring";
  if (vertex.ring == PolygonSketch::RingKind::kHull) ring = "the hull";
  if (vertex.ring == PolygonSketch::RingKind::kHole) ring = QString("hole %1").arg(vertex.hole);
  return QString("vertex %1 of %2").arg(vertex.index).arg(ring);
}

geometry_msgs::Polygon toMessage(const core::Ring& ring) {
  geometry_msgs::Polygon polygon;
  for (const core::Point2& point : ring) {
    geometry_msgs::Point32 vertex;
    vertex.x = static_cast<float>(point.x());
    vertex.y = static_cast<float>(point.y());
    polygon.points.push_back(vertex);
  }
  return polygon;
}

Ogre::Vector3 toOgre(const core::Point2& point) {
  return Ogre::Vector3(static_cast<float>(point.x()), static_cast<float>(point.y()), kDrawHeightM);
}

}  // namespace

PolygonTool::PolygonTool() {
  shortcut_key_ = 'p';
  topic_property_ = new rviz::StringProperty(
      "Topic", kDefaultTopic,
      "kinematic_coverage/PolygonWithHolesStamped topic on which a closed, valid drawing is "
      "published (relative names resolve in rviz's namespace).",
      getPropertyContainer(), SLOT(updateTopic()), this);
}

PolygonTool::~PolygonTool() {
  lines_.clear();
  vertices_.clear();
  if (scene_node_ != nullptr) scene_manager_->destroySceneNode(scene_node_);
}

void PolygonTool::onInitialize() {
  scene_node_ = scene_manager_->getRootSceneNode()->createChildSceneNode();
  updateTopic();
}

void PolygonTool::activate() { setStatus(statusText()); }

void PolygonTool::deactivate() {
  if (grabbed_ && grabbed_moved_) editDone(QString("Moved %1.").arg(vertexName(*grabbed_)));
  grabbed_.reset();
  grabbed_moved_ = false;
  press_adds_ = false;
  if (!sketch_.openRing().empty()) {
    sketch_.cancelOpenRing();
    redraw();
  }
}

int PolygonTool::processMouseEvent(rviz::ViewportMouseEvent& event) {
  const auto point = groundPoint(event.viewport, event.x, event.y);
  if (!point) {
    setStatus("The view does not show the ground plane z = 0 here.");
    return 0;
  }
  const auto edge = groundPoint(event.viewport, event.x + kPickRadiusPx, event.y);
  const double tolerance = edge ? (*edge - *point).norm() : 0.0;
  // Qt reports the second of two quick presses as a double click: a press all the same.
  if (event.leftDown() ||
      (event.type == QEvent::MouseButtonDblClick && event.acting_button == Qt::LeftButton)) {
    return pressLeft(event, *point, tolerance);
  }
  if (event.leftUp()) return releaseLeft(*point);
  if (event.rightUp()) {
    if (sketch_.closeRing()) {
      editDone("Ring closed.");
      return Render;
    }
    setStatus("A right click closes the open ring once it has 3 vertices. " + statusText());
    return 0;
  }
  if (grabbed_ && event.left() && event.type == QEvent::MouseMove) {
    if (!grabbed_moved_ &&
        std::abs(event.x - press_x_) + std::abs(event.y - press_y_) <= kDragThresholdPx) {
      return 0;
    }
    grabbed_moved_ = true;
    sketch_.moveVertex(*grabbed_, *point);
    redraw();
    setStatus(QString("Moving %1 to %2; release to place it.")
                  .arg(vertexName(*grabbed_), formatPoint(*point)));
    return Render;
  }
  setStatus(QString("%1 in %2. ").arg(formatPoint(*point), context_->getFixedFrame()) +
            statusText());
  return 0;
}

int PolygonTool::pressLeft(rviz::ViewportMouseEvent& event, const core::Point2& point,
                           double tolerance) {
  grabbed_.reset();
  grabbed_moved_ = false;
  press_adds_ = false;
  const auto vertex = sketch_.nearestVertex(point, tolerance);
  if (event.shift()) {
    if (!vertex) {
      setStatus("Shift + click on a vertex deletes it; there is none here. " + statusText());
      return 0;
    }
    const std::size_t rings = sketch_.holes().size() + (sketch_.hasHull() ? 1 : 0);
    QString what = QString("Deleted %1.").arg(vertexName(*vertex));
    sketch_.deleteVertex(*vertex);
    if (sketch_.holes().size() + (sketch_.hasHull() ? 1 : 0) < rings) {
      what += " The ring had 2 vertices left and was removed.";
    }
    editDone(what);
    return Render;
  }
  if (vertex) {
    grabbed_ = vertex;
    press_x_ = event.x;
    press_y_ = event.y;
  } else {
    press_adds_ = true;
  }
  return 0;
}

int PolygonTool::releaseLeft(const core::Point2& point) {
  if (grabbed_) {
    const PolygonSketch::VertexId vertex = *grabbed_;
    const bool moved = grabbed_moved_;
    grabbed_.reset();
    grabbed_moved_ = false;
    if (moved) {
      sketch_.moveVertex(vertex, point);
      editDone(QString("Moved %1 to %2.").arg(vertexName(vertex), formatPoint(point)));
      return Render;
    }
    if (vertex.ring == PolygonSketch::RingKind::kOpen && vertex.index == 0) {
      if (sketch_.closeRing()) {
        editDone("Ring closed.");
        return Render;
      }
      setStatus("A ring needs 3 vertices before it closes. " + statusText());
      return 0;
    }
    setStatus(QString("Drag %1 to move it; Shift + click deletes it.").arg(vertexName(vertex)));
    return 0;
  }
  if (!press_adds_) return 0;
  press_adds_ = false;
  sketch_.addVertex(point);
  editDone(QString("Vertex added at %1.").arg(formatPoint(point)));
  return Render;
}

void PolygonTool::editDone(const QString& what) {
  redraw();
  const auto polygon = sketch_.completePolygon();
  if (polygon) {
    publish(*polygon);
  } else if (sketch_.openRing().empty() && sketch_.hasHull()) {
    ROS_WARN("Draw Polygon: the polygon is invalid and not published: %s",
             sketch_.validity().value_or("").c_str());
  }
  setStatus(what + " " + statusText());
}

void PolygonTool::redraw() {
  lines_.clear();
  vertices_.clear();
  const auto draw = [this](const core::Ring& ring, const Ogre::ColourValue& colour, bool closed) {
    if (ring.empty()) return;
    auto line = std::make_unique<rviz::BillboardLine>(scene_manager_, scene_node_);
    line->setMaxPointsPerLine(static_cast<uint32_t>(ring.size() + 1));
    line->setLineWidth(kLineWidthM);
    for (const core::Point2& point : ring) line->addPoint(toOgre(point), colour);
    if (closed) line->addPoint(toOgre(ring.front()), colour);
    lines_.push_back(std::move(line));
    for (const core::Point2& point : ring) {
      auto sphere = std::make_unique<rviz::Shape>(rviz::Shape::Sphere, scene_manager_, scene_node_);
      sphere->setColor(colour);
      sphere->setScale(Ogre::Vector3(kVertexDiameterM, kVertexDiameterM, kVertexDiameterM));
      sphere->setPosition(toOgre(point));
      vertices_.push_back(std::move(sphere));
    }
  };
  const Ogre::ColourValue& closed = sketch_.validity() ? kInvalidColour : kValidColour;
  draw(sketch_.hull(), closed, true);
  for (const core::Ring& hole : sketch_.holes()) draw(hole, closed, true);
  draw(sketch_.openRing(), kOpenColour, false);
}

QString PolygonTool::statusText() const {
  const auto problem = sketch_.validity();
  QString text;
  if (!sketch_.openRing().empty()) {
    const QString ring =
        sketch_.hasHull() ? QString("hole %1").arg(sketch_.holes().size()) : QString("the hull");
    text += QString(
                "Drawing %1 (%2 vertices): click adds a vertex; a right click or a click on "
                "its first vertex closes it; Esc drops it.")
                .arg(ring)
                .arg(sketch_.openRing().size());
    if (sketch_.hasHull() && problem)
      text += " Invalid so far: " + QString::fromStdString(*problem);
    return text;
  }
  if (!sketch_.hasHull()) {
    return text +
           "Click the hull's vertices, then close it with a right click or a click on its "
           "first vertex.";
  }
  if (problem) {
    return text + "Invalid, not published: " + QString::fromStdString(*problem) +
           ". Drag a vertex to fix it or Shift + click to delete it.";
  }
  return text + QString(
                    "Valid: published on %1 in %2 (hull of %3 vertices, %4 holes). Click to "
                    "draw a hole; drag a vertex to move it; Shift + click deletes it.")
                    .arg(QString::fromStdString(publisher_.getTopic()), context_->getFixedFrame())
                    .arg(sketch_.hull().size())
                    .arg(sketch_.holes().size());
}

void PolygonTool::publish(const core::PolygonWithHoles& polygon) {
  kinematic_coverage::PolygonWithHolesStamped message;
  message.header.frame_id = context_->getFixedFrame().toStdString();
  message.header.stamp = ros::Time::now();
  message.polygon.hull = toMessage(polygon.hull);
  for (const core::Ring& hole : polygon.holes) message.polygon.holes.push_back(toMessage(hole));
  publisher_.publish(message);
}

void PolygonTool::updateTopic() {
  const std::string topic = topic_property_->getStdString();
  const std::optional<std::string> problem =
      advertiseTopic<kinematic_coverage::PolygonWithHolesStamped>(node_, topic, kDefaultTopic, true,
                                                                  &publisher_);
  if (!problem) return;
  const QString message =
      QString(
          "Topic \"%1\" is not a valid topic name (%2); the polygon is still published on "
          "%3.")
          .arg(QString::fromStdString(topic), QString::fromStdString(*problem),
               QString::fromStdString(publisher_.getTopic()));
  ROS_ERROR("Draw Polygon tool: %s", message.toStdString().c_str());
  setStatus(message);
}

}  // namespace kinematic_coverage::rviz_plugins

PLUGINLIB_EXPORT_CLASS(kinematic_coverage::rviz_plugins::PolygonTool, rviz::Tool)
