#include "coverage_system/ros/message_conversion.h"

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::nodes {
namespace {

core::Ring ringFromMessage(const geometry_msgs::Polygon& polygon) {
  core::Ring ring;
  ring.reserve(polygon.points.size());
  for (const geometry_msgs::Point32& p : polygon.points) ring.emplace_back(p.x, p.y);
  return ring;
}

geometry_msgs::Polygon ringToMessage(const core::Ring& ring) {
  geometry_msgs::Polygon polygon;
  for (const core::Point2& p : ring) {
    geometry_msgs::Point32 point;
    point.x = static_cast<float>(p.x());
    point.y = static_cast<float>(p.y());
    polygon.points.push_back(point);
  }
  return polygon;
}

geometry_msgs::Pose poseMessage(double x, double y, double yaw) {
  geometry_msgs::Pose pose;
  pose.position.x = x;
  pose.position.y = y;
  tf2::Quaternion quaternion;
  quaternion.setRPY(0.0, 0.0, yaw);
  pose.orientation = tf2::toMsg(quaternion);
  return pose;
}

/// Largest deviation of a quaternion's squared norm from 1 (rviz's own tolerance).
constexpr double kUnitQuaternionTolerance = 0.01;

/// Poses with x, y and yaw members as a PoseArray.
template <typename Pose>
geometry_msgs::PoseArray poseArray(const std::vector<Pose>& poses, const std_msgs::Header& header) {
  geometry_msgs::PoseArray message;
  message.header = header;
  message.poses.reserve(poses.size());
  for (const Pose& pose : poses) message.poses.push_back(poseMessage(pose.x, pose.y, pose.yaw));
  return message;
}

}  // namespace

core::PolygonWithHoles fromMessage(const ::kinematic_coverage::PolygonWithHoles& message) {
  core::PolygonWithHoles polygon;
  polygon.hull = ringFromMessage(message.hull);
  for (const geometry_msgs::Polygon& hole : message.holes) {
    polygon.holes.push_back(ringFromMessage(hole));
  }
  return polygon;
}

::kinematic_coverage::PolygonWithHolesStamped toMessage(const core::PolygonWithHoles& polygon,
                                                        const std_msgs::Header& header) {
  ::kinematic_coverage::PolygonWithHolesStamped message;
  message.header = header;
  message.polygon.hull = ringToMessage(polygon.hull);
  for (const core::Ring& hole : polygon.holes) message.polygon.holes.push_back(ringToMessage(hole));
  return message;
}

core::Point2 fromMessage(const geometry_msgs::Point& point) { return {point.x, point.y}; }

geometry_msgs::PoseArray toPoseArray(const std::vector<core::Pose2>& poses,
                                     const std_msgs::Header& header) {
  return poseArray(poses, header);
}

geometry_msgs::PoseArray toPoseArray(const std::vector<core::TrajectoryPose>& poses,
                                     const std_msgs::Header& header) {
  return poseArray(poses, header);
}

nav_msgs::Path toPath(const std::vector<core::TrajectoryPose>& poses,
                      const std_msgs::Header& header) {
  nav_msgs::Path path;
  path.header = header;
  path.poses.reserve(poses.size());
  for (const core::TrajectoryPose& pose : poses) {
    geometry_msgs::PoseStamped stamped;
    stamped.header.frame_id = header.frame_id;
    stamped.header.stamp = header.stamp + ros::Duration(pose.t);
    stamped.pose = poseMessage(pose.x, pose.y, pose.yaw);
    path.poses.push_back(stamped);
  }
  return path;
}

::kinematic_coverage::PlanStatus statusMessage(const std::string& stage, bool success,
                                               const std::string& message, double duration_s,
                                               const std::string& frame_id) {
  ::kinematic_coverage::PlanStatus status;
  status.header.stamp = ros::Time::now();
  status.header.frame_id = frame_id;
  status.stage = stage;
  status.success = success;
  status.message = message;
  status.duration_s = duration_s;
  return status;
}

double yawOf(const geometry_msgs::Quaternion& orientation) {
  tf2::Quaternion quaternion;
  tf2::fromMsg(orientation, quaternion);
  if (quaternion.length2() == 0.0) return 0.0;
  quaternion.normalize();
  double roll = 0.0;
  double pitch = 0.0;
  double yaw = 0.0;
  tf2::Matrix3x3(quaternion).getRPY(roll, pitch, yaw);
  return yaw;
}

std::string frameOf(const std_msgs::Header& header) {
  return header.frame_id.empty() ? "map" : header.frame_id;
}

core::Pose2 checkedPose(const geometry_msgs::Pose& pose, const std::string& what) {
  if (!std::isfinite(pose.position.x) || !std::isfinite(pose.position.y)) {
    std::ostringstream message;
    message << what << " has a non-finite position (" << pose.position.x << ", " << pose.position.y
            << ")";
    throw core::InvalidInputError(message.str());
  }
  const geometry_msgs::Quaternion& q = pose.orientation;
  const double norm2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (!std::isfinite(norm2) || std::abs(norm2 - 1.0) > kUnitQuaternionTolerance) {
    std::ostringstream message;
    message << what << " has an orientation that is not a unit quaternion (x " << q.x << ", y "
            << q.y << ", z " << q.z << ", w " << q.w << ")";
    throw core::InvalidInputError(message.str());
  }
  return {pose.position.x, pose.position.y, yawOf(q)};
}

std::vector<core::Pose2> checkedPoses(const geometry_msgs::PoseArray& message,
                                      const std::string& what) {
  std::vector<core::Pose2> poses;
  poses.reserve(message.poses.size());
  for (std::size_t i = 0; i < message.poses.size(); ++i) {
    poses.push_back(checkedPose(message.poses[i], what + " " + std::to_string(i)));
  }
  return poses;
}

}  // namespace kinematic_coverage::nodes
