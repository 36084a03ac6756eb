#include "coverage_system/mission/local_east_north_frame.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// Height above the ellipsoid (m) at which toGeographic's iteration stops, and its bound.
constexpr double kHeightTolerance = 1e-9;
constexpr int kMaxIterations = 10;

}  // namespace

struct LocalEastNorthFrame::Projection {
  GeographicLib::LocalCartesian cartesian;
};

LocalEastNorthFrame::LocalEastNorthFrame(const GeoPoint& datum)
    : datum_(datum), projection_(std::make_unique<Projection>()) {
  checkRange(datum, "the datum");
  projection_->cartesian.Reset(datum.latitude, datum.longitude, 0.0);
}

LocalEastNorthFrame::~LocalEastNorthFrame() = default;

LocalEastNorthFrame::LocalEastNorthFrame(const LocalEastNorthFrame& other)
    : datum_(other.datum_), projection_(std::make_unique<Projection>(*other.projection_)) {}

LocalEastNorthFrame& LocalEastNorthFrame::operator=(const LocalEastNorthFrame& other) {
  datum_ = other.datum_;
  projection_ = std::make_unique<Projection>(*other.projection_);
  return *this;
}

void LocalEastNorthFrame::checkRange(const GeoPoint& point, const std::string& what) {
  if (!std::isfinite(point.latitude) || !std::isfinite(point.longitude) ||
      std::abs(point.latitude) > 90.0 || std::abs(point.longitude) > 180.0) {
    throw InvalidInputError(what + " (longitude " + formatNumber(point.longitude) + ", latitude " +
                            formatNumber(point.latitude) +
                            ") lies outside [-180, 180] x [-90, 90]: GeoJSON coordinates are "
                            "[longitude, latitude] in WGS84 degrees");
  }
}

Point2 LocalEastNorthFrame::toLocal(const GeoPoint& point, const std::string& what) const {
  checkRange(point, what);
  double east = 0.0, north = 0.0, up = 0.0;
  projection_->cartesian.Forward(point.latitude, point.longitude, 0.0, east, north, up);
  const Point2 local(east, north);
  if (!(local.norm() <= kMaxRadius)) {
    throw InvalidInputError(
        what + " lies " + formatNumber(std::round(local.norm())) +
        " m from the datum, more than the " + formatNumber(kMaxRadius) +
        " m a local frame is made for: the area is too large for projection local "
        "(set projection: utm)");
  }
  return local;
}

GeoPoint LocalEastNorthFrame::toGeographic(const Point2& local) const {
  // The ellipsoid point whose east and north are `local`: its up coordinate (below the
  // frame's plane) is found by fixed-point iteration, each step taking the frame point
  // (east, north, up) back to geographic coordinates and dropping it onto the ellipsoid;
  // the height above it shrinks by orders of magnitude per step.
  GeoPoint point;
  double up = 0.0;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    double height = 0.0;
    projection_->cartesian.Reverse(local.x(), local.y(), up, point.latitude, point.longitude,
                                   height);
    if (std::abs(height) <= kHeightTolerance) break;
    double east = 0.0, north = 0.0;
    projection_->cartesian.Forward(point.latitude, point.longitude, 0.0, east, north, up);
  }
  return point;
}

}  // namespace kinematic_coverage::core
