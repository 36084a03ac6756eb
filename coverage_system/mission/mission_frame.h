#pragma once

#include <optional>
#include <string>
#include <variant>

#include "coverage_system/mission/local_east_north_frame.h"
#include "coverage_system/mission/mission.h"
#include "coverage_system/mission/utm_zone_frame.h"
#include "coverage_system/parameters/map_projection.h"

namespace kinematic_coverage::core {

/// The plane frame of a geo-referenced mission, in metres with the datum at the origin:
/// the local east-north frame (projection `local`) or the grid of the datum's UTM zone
/// (`utm`). Readers and writers of geographic positions go through it, so that a
/// mission's inputs and outputs share one projection.
class MissionFrame {
 public:
  /// Throws InvalidInputError as the chosen frame's constructor does.
  MissionFrame(const GeoPoint& datum, MapProjection projection);

  /// The frame of a mission at `datum` with the projection its parameters name.
  static MissionFrame of(const GeoPoint& datum, const PlannerParameters& parameters);

  const GeoPoint& datum() const;
  MapProjection projection() const { return projection_; }
  /// "local" or "utm", as the parameter `projection` names it.
  std::string projectionName() const;
  /// The UTM zone and hemisphere (e.g. "32N") of a `utm` frame; none for `local`.
  std::optional<std::string> utmZone() const;

  /// The plane position of `point`. Throws InvalidInputError, naming the point `what`, for
  /// coordinates out of range or beyond the projection's reach (LocalEastNorthFrame's
  /// kMaxRadius, UtmZoneFrame's point scale), naming the projection that reaches it.
  Point2 toLocal(const GeoPoint& point, const std::string& what) const;

  /// The geographic position of a plane point.
  GeoPoint toGeographic(const Point2& local) const;

  /// The direction of true north at a plane point: radians counter-clockwise from the
  /// frame's x axis (pi/2 at a local frame's datum; the meridian convergence away from it).
  double northDirection(const Point2& local) const;

 private:
  MapProjection projection_;
  std::variant<LocalEastNorthFrame, UtmZoneFrame> frame_;
};

}  // namespace kinematic_coverage::core
