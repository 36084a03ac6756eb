#include "coverage_system/mission/mission_frame.h"

#include <cmath>

#include "coverage_system/parameters/parameter_choices.h"

namespace kinematic_coverage::core {
namespace {

/// The latitude step (degrees, about 1 m) over which northDirection measures north.
constexpr double kNorthStepDegrees = 1e-5;

std::variant<LocalEastNorthFrame, UtmZoneFrame> frameOf(const GeoPoint& datum,
                                                        MapProjection projection) {
  if (projection == MapProjection::kUtm) return UtmZoneFrame(datum);
  return LocalEastNorthFrame(datum);
}

}  // namespace

MissionFrame::MissionFrame(const GeoPoint& datum, MapProjection projection)
    : projection_(projection), frame_(frameOf(datum, projection)) {}

MissionFrame MissionFrame::of(const GeoPoint& datum, const PlannerParameters& parameters) {
  return MissionFrame(datum, choiceOf(parameters.projection, kMapProjections));
}

const GeoPoint& MissionFrame::datum() const {
  return std::visit([](const auto& frame) -> const GeoPoint& { return frame.datum(); }, frame_);
}

std::string MissionFrame::projectionName() const { return nameOf(projection_, kMapProjections); }

std::optional<std::string> MissionFrame::utmZone() const {
  if (const auto* utm = std::get_if<UtmZoneFrame>(&frame_)) return utm->zoneName();
  return std::nullopt;
}

Point2 MissionFrame::toLocal(const GeoPoint& point, const std::string& what) const {
  return std::visit([&](const auto& frame) { return frame.toLocal(point, what); }, frame_);
}

GeoPoint MissionFrame::toGeographic(const Point2& local) const {
  return std::visit([&](const auto& frame) { return frame.toGeographic(local); }, frame_);
}

double MissionFrame::northDirection(const Point2& local) const {
  const GeoPoint here = toGeographic(local);
  const double step =
      here.latitude + kNorthStepDegrees <= 90.0 ? kNorthStepDegrees : -kNorthStepDegrees;
  const GeoPoint moved{here.latitude + step, here.longitude};
  const Point2 north = std::copysign(1.0, step) * (toLocal(moved, "a point north of it") - local);
  return std::atan2(north.y(), north.x());
}

}  // namespace kinematic_coverage::core
