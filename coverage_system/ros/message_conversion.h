#pragma once

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseArray.h>
#include <nav_msgs/Path.h>
#include <std_msgs/Header.h>

#include <string>
#include <vector>

#include "kinematic_coverage/PlanStatus.h"
#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::nodes {

/// The core's polygon from a message (z ignored; docs/REFERENCE.md, Messages). Non-finite
/// coordinates pass through: PolygonValidator names them.
core::PolygonWithHoles fromMessage(const ::kinematic_coverage::PolygonWithHoles& message);

/// A polygon message in `frame_id`.
::kinematic_coverage::PolygonWithHolesStamped toMessage(const core::PolygonWithHoles& polygon,
                                                        const std_msgs::Header& header);

/// A point message's x and y.
core::Point2 fromMessage(const geometry_msgs::Point& point);

/// Poses as a PoseArray: positions at z = 0, orientations the headings as yaw quaternions
/// (docs/REFERENCE.md, Messages).
geometry_msgs::PoseArray toPoseArray(const std::vector<core::Pose2>& poses,
                                     const std_msgs::Header& header);

/// Trajectory poses as a PoseArray (headings as yaw quaternions).
geometry_msgs::PoseArray toPoseArray(const std::vector<core::TrajectoryPose>& poses,
                                     const std_msgs::Header& header);

/// Trajectory poses as a nav_msgs/Path: the header as given (stamped with the time of
/// planning), each pose stamped with that time plus its planned time offset t.
nav_msgs::Path toPath(const std::vector<core::TrajectoryPose>& poses,
                      const std_msgs::Header& header);

/// A `~status` message (docs/REFERENCE.md, Messages) stamped now, in `frame_id`.
::kinematic_coverage::PlanStatus statusMessage(const std::string& stage, bool success,
                                               const std::string& message, double duration_s,
                                               const std::string& frame_id);

/// The yaw of a quaternion message (0 for a zero quaternion).
double yawOf(const geometry_msgs::Quaternion& orientation);

/// The frame a header names: `map` when it is empty (docs/REFERENCE.md, Messages).
std::string frameOf(const std_msgs::Header& header);

/// The x, y and yaw of a pose message. Throws core::InvalidInputError, naming the pose as
/// `what`, for a non-finite x or y, or an orientation that is not a unit quaternion
/// (non-finite, or a squared norm off 1 by more than 0.01, rviz's tolerance).
core::Pose2 checkedPose(const geometry_msgs::Pose& pose, const std::string& what);

/// checkedPose of every pose of a PoseArray, each named `what` and its index.
std::vector<core::Pose2> checkedPoses(const geometry_msgs::PoseArray& message,
                                      const std::string& what);

}  // namespace kinematic_coverage::nodes
