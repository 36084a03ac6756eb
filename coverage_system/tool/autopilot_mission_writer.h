#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "coverage_system/mission/autopilot_mission.h"
#include "coverage_system/mission/mission_frame.h"

namespace kinematic_coverage::core {

/// What the vehicle's mission files say beyond the waypoints.
struct AutopilotMissionSettings {
  double depth = 0.0;                  ///< m below the surface (mission_depth)
  double corner_cutting_radius = 0.0;  ///< m, written as each waypoint's acceptance radius
};

/// Writes an AutopilotMission for ArduSub and PX4 ground stations, in WGS84 through the
/// mission's local frame: QGroundControl's plan file (JSON; docs.qgroundcontrol.com, Plan
/// File Format: a mission of SimpleItems, version 2) and the plain-text `QGC WPL 110`
/// format (mavlink.io, File Formats: a home line, then one tab-separated item per line).
/// Both hold the same items: a MAV_CMD_DO_CHANGE_SPEED (178; ground speed, m/s) wherever the
/// speed changes, before the waypoint it leads to, and a MAV_CMD_NAV_WAYPOINT (16) per
/// waypoint in MAV_FRAME_GLOBAL_RELATIVE_ALT (3), at the altitude -depth (ArduSub reads a
/// negative altitude relative to the surface as depth), with the corner-cutting radius as its
/// acceptance radius and, at a held waypoint, a hold of one second (the autopilot reaches it
/// and stops). The home position is the first waypoint at the surface.
class AutopilotMissionWriter {
 public:
  /// ArduPilot boards keep about 700 mission items in their FRAM (ArduPilot issues 2391 and
  /// 7254; boards that store missions on an SD card hold more): plan warns above it.
  static constexpr std::size_t kArduPilotItemLimit = 700;

  /// The items of `mission`, its waypoints in WGS84 through `frame`.
  AutopilotMissionWriter(const MissionFrame& frame, const AutopilotMissionSettings& settings,
                         const AutopilotMission& mission);

  /// The mission items, as both formats count them (without the WPL file's home line).
  std::size_t itemCount() const { return items_.size(); }

  /// mission.plan: QGroundControl plan JSON; its `kinematic_coverage` object notes the
  /// corner-cutting radius the plan assumes (QGroundControl ignores it).
  std::string planJson() const;

  /// mission.waypoints: the QGC WPL 110 text.
  std::string waypointsText() const;

 private:
  /// One item: its command, frame and seven parameters.
  struct Item {
    int command = 0;
    int frame = 0;
    double params[7] = {0, 0, 0, 0, 0, 0, 0};
  };

  AutopilotMissionSettings settings_;
  std::vector<Item> items_;
  GeoPoint home_;              ///< the first waypoint (the datum without waypoints)
  double cruise_speed_ = 0.0;  ///< the first waypoint's speed
};

}  // namespace kinematic_coverage::core
