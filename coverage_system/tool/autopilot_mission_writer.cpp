#include "coverage_system/tool/autopilot_mission_writer.h"

#include <sstream>
#include <vector>

#include "coverage_system/tool/json_object.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"

namespace kinematic_coverage::core {
namespace {

/// MAVLink's MAV_CMD and MAV_FRAME values (mavlink.io, common message set).
constexpr int kNavWaypoint = 16;
constexpr int kDoChangeSpeed = 178;
constexpr int kFrameGlobal = 0;
constexpr int kFrameMission = 2;
constexpr int kFrameGlobalRelativeAlt = 3;
/// NAV_WAYPOINT's hold time at a held waypoint, s: the autopilot stops there instead of
/// turning early for the next one.
constexpr double kHoldSeconds = 1.0;
/// DO_CHANGE_SPEED's speed type: ground speed.
constexpr double kGroundSpeed = 1.0;
/// DO_CHANGE_SPEED's throttle: unchanged.
constexpr double kThrottleUnchanged = -1.0;
/// QGroundControl's values for an ArduPilot submarine (MAV_AUTOPILOT_ARDUPILOTMEGA,
/// MAV_TYPE_SUBMARINE) and its plan-wide altitude mode "relative".
constexpr int kFirmwareArduPilot = 3;
constexpr int kVehicleSubmarine = 12;
constexpr int kAltitudeModeRelative = 1;
/// Decimals of the waypoints' degrees: 1e-7, the resolution of MAVLink's integer
/// MISSION_ITEM_INT positions.
constexpr int kDegreeDecimals = 7;

}  // namespace

AutopilotMissionWriter::AutopilotMissionWriter(const MissionFrame& frame,
                                               const AutopilotMissionSettings& settings,
                                               const AutopilotMission& mission)
    : settings_(settings),
      home_(frame.toGeographic(mission.waypoints.empty() ? Point2::Zero()
                                                         : mission.waypoints.front().position)),
      cruise_speed_(mission.waypoints.empty() ? 0.0 : mission.waypoints.front().speed) {
  double speed = -1.0;
  for (const AutopilotWaypoint& waypoint : mission.waypoints) {
    if (waypoint.speed != speed) {
      speed = waypoint.speed;
      items_.push_back(
          {kDoChangeSpeed, kFrameMission, {kGroundSpeed, speed, kThrottleUnchanged, 0, 0, 0, 0}});
    }
    const GeoPoint geo = frame.toGeographic(waypoint.position);
    items_.push_back({kNavWaypoint,
                      kFrameGlobalRelativeAlt,
                      {waypoint.hold ? kHoldSeconds : 0.0, settings_.corner_cutting_radius, 0, 0,
                       roundToDecimals(geo.latitude, kDegreeDecimals),
                       roundToDecimals(geo.longitude, kDegreeDecimals),
                       settings_.depth > 0.0 ? -settings_.depth : 0.0}});
  }
}

std::string AutopilotMissionWriter::planJson() const {
  std::ostringstream list;
  list << "[";
  int jump_id = 0;
  for (const Item& item : items_) {
    const double altitude = item.frame == kFrameGlobalRelativeAlt ? item.params[6] : 0.0;
    ++jump_id;
    list << (jump_id > 1 ? ",\n" : "\n")
         << "{\"AMSLAltAboveTerrain\": null, \"Altitude\": " << formatRoundTrip(altitude)
         << ", \"AltitudeMode\": " << kAltitudeModeRelative
         << ", \"autoContinue\": true, \"command\": " << item.command
         << ", \"doJumpId\": " << jump_id << ", \"frame\": " << item.frame << ", \"params\": [";
    for (int k = 0; k < 7; ++k) list << (k ? ", " : "") << formatRoundTrip(item.params[k]);
    list << "], \"type\": \"SimpleItem\"}";
  }
  list << "\n]";
  JsonObject mission_object;
  mission_object.set("cruiseSpeed", cruise_speed_)
      .set("firmwareType", kFirmwareArduPilot)
      .set("globalPlanAltitudeMode", kAltitudeModeRelative)
      .set("hoverSpeed", cruise_speed_)
      .setJson("items", list.str())
      .set("plannedHomePosition", std::vector<double>{home_.latitude, home_.longitude, 0.0})
      .set("vehicleType", kVehicleSubmarine)
      .set("version", 2.0);
  JsonObject empty_fence;
  empty_fence.setJson("circles", "[]").setJson("polygons", "[]").set("version", 2.0);
  JsonObject empty_rally;
  empty_rally.setJson("points", "[]").set("version", 2.0);
  JsonObject notes;
  notes.set("corner_cutting_radius_m", settings_.corner_cutting_radius)
      .set("note",
           "Planned for an autopilot that turns for the next waypoint within "
           "corner_cutting_radius_m of the current one (ArduSub: WPNAV_RADIUS); set it so.");
  JsonObject plan;
  plan.set("fileType", std::string("Plan"))
      .set("geoFence", empty_fence)
      .set("groundStation", std::string("kinematic_coverage"))
      .set("kinematic_coverage", notes)
      .set("mission", mission_object)
      .set("rallyPoints", empty_rally)
      .set("version", 1.0);
  return plan.toString();
}

std::string AutopilotMissionWriter::waypointsText() const {
  std::ostringstream text;
  text << "QGC WPL 110\n";
  const auto line = [&](int index, int current, int frame, int command, const double* params) {
    text << index << '\t' << current << '\t' << frame << '\t' << command;
    for (int k = 0; k < 7; ++k) text << '\t' << formatRoundTrip(params[k]);
    text << "\t1\n";
  };
  const double home_params[7] = {0, 0, 0, 0, home_.latitude, home_.longitude, 0};
  line(0, 1, kFrameGlobal, kNavWaypoint, home_params);
  int index = 1;
  for (const Item& item : items_) line(index++, 0, item.frame, item.command, item.params);
  return text.str();
}

}  // namespace kinematic_coverage::core
