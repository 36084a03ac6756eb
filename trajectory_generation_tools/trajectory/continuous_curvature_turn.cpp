#include "trajectory_generation_tools/trajectory/continuous_curvature_turn.h"

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// m and rad: how closely the built turn must end where the geometry says it does.
constexpr double kEndTolerance = 1e-6;

}  // namespace

std::optional<ContinuousCurvatureTurnShape> ContinuousCurvatureTurn::replacing(
    const PathPrimitive& arc, double curvature_rate) {
  if (arc.kind() != PrimitiveKind::kArc || !(curvature_rate > 0.0)) return std::nullopt;
  const double turn = std::abs(arc.sweep());
  if (!(turn > kMinTurn && turn < M_PI - kMinTurn)) return std::nullopt;
  const double side = arc.sweep() > 0.0 ? 1.0 : -1.0;
  // The clothoids rise to the arc's curvature, each turning kappa^2 / (2 rate), or, where
  // the two of them would turn more than the arc, meet at the curvature that turns it all.
  double peak = 1.0 / arc.radius();
  double spiral_turn = peak * peak / (2.0 * curvature_rate);
  if (2.0 * spiral_turn >= turn) {
    peak = std::sqrt(turn * curvature_rate);
    spiral_turn = 0.5 * turn;
  }
  const double spiral_length = peak / curvature_rate;
  const double arc_turn = turn - 2.0 * spiral_turn;

  // In the frame of the first clothoid's start (heading +x, turning left): the turn is
  // symmetric about the bisector of the legs, so its tangent length (from its start to the
  // legs' crossing) follows from the first clothoid's end (x, y) and heading
  // spiral_turn: through the centre of the arc where there is one, through the clothoids'
  // meeting point on the bisector where there is not.
  const Point2 spiral_end =
      PathPrimitive::clothoid({0.0, 0.0, 0.0}, 0.0, curvature_rate, spiral_length).end();
  Point2 on_bisector = spiral_end;
  double distance_from_leg = spiral_end.y();
  if (arc_turn > 0.0) {
    const double radius = 1.0 / peak;
    on_bisector = spiral_end + radius * Point2(-std::sin(spiral_turn), std::cos(spiral_turn));
    distance_from_leg = on_bisector.y();
  }
  const double half_tangent = std::tan(0.5 * turn);
  const double tangent_length = on_bisector.x() + distance_from_leg * half_tangent;
  ContinuousCurvatureTurnShape shape;
  shape.extension = tangent_length - arc.radius() * half_tangent;
  if (!std::isfinite(shape.extension) || shape.extension < -kEndTolerance) return std::nullopt;
  shape.extension = std::max(shape.extension, 0.0);

  const Pose2 arc_start = arc.startPose();
  const Point2 in_direction(std::cos(arc_start.yaw), std::sin(arc_start.yaw));
  const Point2 start = arc.start() - shape.extension * in_direction;
  shape.primitives.push_back(PathPrimitive::clothoid({start.x(), start.y(), arc_start.yaw}, 0.0,
                                                     side * curvature_rate, spiral_length)
                                 .withVariant(arc.variant()));
  Pose2 at = shape.primitives.back().endPose();
  if (arc_turn > 0.0) {
    const double radius = 1.0 / peak;
    const Point2 centre =
        at.position() + side * radius * Point2(-std::sin(at.yaw), std::cos(at.yaw));
    const Point2 from_centre = at.position() - centre;
    shape.primitives.push_back(PathPrimitive::arc(centre, radius,
                                                  std::atan2(from_centre.y(), from_centre.x()),
                                                  side * arc_turn)
                                   .withVariant(arc.variant()));
    at = shape.primitives.back().endPose();
  }
  shape.primitives.push_back(
      PathPrimitive::clothoid(at, side * peak, -side * curvature_rate, spiral_length)
          .withVariant(arc.variant()));

  const Pose2 arc_end = arc.endPose();
  const Point2 end =
      arc.end() + shape.extension * Point2(std::cos(arc_end.yaw), std::sin(arc_end.yaw));
  const Pose2 built_end = shape.primitives.back().endPose();
  if (!((built_end.position() - end).norm() <= kEndTolerance) ||
      !(std::abs(wrapAngle(built_end.yaw - arc_end.yaw)) <= kEndTolerance)) {
    return std::nullopt;
  }
  return shape;
}

}  // namespace kinematic_coverage::core
