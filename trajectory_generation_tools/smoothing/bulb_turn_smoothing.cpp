#include "trajectory_generation_tools/smoothing/bulb_turn_smoothing.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Difference (rad) allowed between the turn's total turning and the corners'.
constexpr double kTurnTolerance = 1e-6;
/// Arcs onto and off the middle leg's line sweeping at most this much (rad): a turn that
/// loops further is slower than the sharp corners it replaces.
constexpr double kMaxMiddleSweep = 1.5 * M_PI;

/// Signed turn (rad) from direction `from` to direction `to`.
double turnBetween(const Point2& from, const Point2& to) {
  return std::atan2(from.x() * to.y() - from.y() * to.x(), from.dot(to));
}

/// The distances t >= 0 at which a circle of `radius` centred at `base + t * direction`
/// touches a circle of `radius` centred at `other` from outside: |base + t d - other| = 2r.
std::vector<double> touchingDistances(const Point2& base, const Point2& direction,
                                      const Point2& other, double radius) {
  const Point2 w = base - other;
  const double half_b = w.dot(direction);
  const double discriminant = half_b * half_b - w.squaredNorm() + 4.0 * radius * radius;
  std::vector<double> distances;
  if (discriminant < 0.0) return distances;
  for (const double sign : {-1.0, 1.0}) {
    const double t = -half_b + sign * std::sqrt(discriminant);
    if (t >= 0.0) distances.push_back(t);
  }
  return distances;
}

/// One end of a bulb turn: the arc between a leg and the arc onto (or off) the middle
/// leg's line, which touch at `touch`.
struct BulbEnd {
  double distance;      ///< from the corner along the leg to where the end arc meets it
  Point2 leg_point;     ///< that point
  Point2 centre;        ///< the end arc's centre
  Point2 touch;         ///< where the end arc and the middle arc touch
  double end_sweep;     ///< |sweep| of the end arc, turning against the corners
  double middle_sweep;  ///< |sweep| of the middle arc, turning with them
};

/// The feasible entries: the arc leaving the incoming leg (direction `d1`, corner `b1`)
/// against the corners' way `side`, touching the arc onto the middle line at `run_start`.
std::vector<BulbEnd> bulbEntries(const Point2& b1, const Point2& d1, const Point2& onto_centre,
                                 const Point2& run_start, double side, double r) {
  std::vector<BulbEnd> entries;
  for (const double entry :
       touchingDistances(b1 - side * r * leftNormal(d1), -d1, onto_centre, r)) {
    const Point2 entry_point = b1 - entry * d1;
    const Point2 entry_centre = entry_point - side * r * leftNormal(d1);
    const Point2 onto_touch = 0.5 * (entry_centre + onto_centre);
    const double entry_sweep = sweepBetween(polarAngle(entry_point - entry_centre),
                                            polarAngle(onto_touch - entry_centre), -side);
    const double onto_sweep = sweepBetween(polarAngle(onto_touch - onto_centre),
                                           polarAngle(run_start - onto_centre), side);
    if (entry_sweep >= M_PI || onto_sweep > kMaxMiddleSweep) continue;
    entries.push_back({entry, entry_point, entry_centre, onto_touch, entry_sweep, onto_sweep});
  }
  return entries;
}

/// The feasible exits: the arc off the middle line at `run_end`, touching the arc that
/// joins the outgoing leg (direction `d3`, corner `b2`) against the corners' way.
std::vector<BulbEnd> bulbExits(const Point2& b2, const Point2& d3, const Point2& off_centre,
                               const Point2& run_end, double side, double r) {
  std::vector<BulbEnd> exits;
  for (const double exit : touchingDistances(b2 - side * r * leftNormal(d3), d3, off_centre, r)) {
    const Point2 exit_point = b2 + exit * d3;
    const Point2 exit_centre = exit_point - side * r * leftNormal(d3);
    const Point2 off_touch = 0.5 * (exit_centre + off_centre);
    const double off_sweep =
        sweepBetween(polarAngle(run_end - off_centre), polarAngle(off_touch - off_centre), side);
    const double exit_sweep = sweepBetween(polarAngle(off_touch - exit_centre),
                                           polarAngle(exit_point - exit_centre), -side);
    if (exit_sweep >= M_PI || off_sweep > kMaxMiddleSweep) continue;
    exits.push_back({exit, exit_point, exit_centre, off_touch, exit_sweep, off_sweep});
  }
  return exits;
}

/// The turn's primitives: entry arc, arc onto the line, the run along it (when it has a
/// length), arc off it, exit arc; arcs of zero sweep left out.
CornerSmoothing bulbSmoothing(const BulbEnd& entry, const BulbEnd& exit, const Point2& onto_centre,
                              const Point2& off_centre, const Point2& run_start,
                              const Point2& run_end, bool has_run, double side, double r) {
  CornerSmoothing smoothing;
  smoothing.variant = SmoothingVariant::kBulb;
  smoothing.corners = 2;
  smoothing.entry_distance = entry.distance;
  smoothing.exit_distance = exit.distance;
  const std::array<PathPrimitive, 2> onto{
      PathPrimitive::arc(entry.centre, r, polarAngle(entry.leg_point - entry.centre),
                         -side * entry.end_sweep),
      PathPrimitive::arc(onto_centre, r, polarAngle(entry.touch - onto_centre),
                         side * entry.middle_sweep)};
  for (const PathPrimitive& arc : onto) {
    if (arc.sweep() != 0.0) smoothing.arcs.push_back(arc);
  }
  if (has_run) smoothing.arcs.push_back(PathPrimitive::segment(run_start, run_end));
  const std::array<PathPrimitive, 2> off{
      PathPrimitive::arc(off_centre, r, polarAngle(run_end - off_centre), side * exit.middle_sweep),
      PathPrimitive::arc(exit.centre, r, polarAngle(exit.touch - exit.centre),
                         -side * exit.end_sweep)};
  for (const PathPrimitive& arc : off) {
    if (arc.sweep() != 0.0) smoothing.arcs.push_back(arc);
  }
  for (PathPrimitive& primitive : smoothing.arcs) primitive.withVariant(SmoothingVariant::kBulb);
  return smoothing;
}

}  // namespace

std::optional<CornerSmoothing> BulbTurnSmoothing::compute(const Point2& a, const Point2& b1,
                                                          const Point2& b2, const Point2& c,
                                                          double radius, double run_from,
                                                          double run_to) {
  if (!(std::isfinite(radius) && radius > 0.0) || !a.allFinite() || !b1.allFinite() ||
      !b2.allFinite() || !c.allFinite() || !(run_from >= 0.0) || !(run_to <= 1.0) ||
      !(run_from <= run_to)) {
    return std::nullopt;
  }
  const double incoming_length = (b1 - a).norm();
  const double middle_length = (b2 - b1).norm();
  const double outgoing_length = (c - b2).norm();
  if (incoming_length <= 0.0 || middle_length <= 0.0 || outgoing_length <= 0.0) {
    return std::nullopt;
  }
  const Point2 d1 = (b1 - a) / incoming_length;
  const Point2 d2 = (b2 - b1) / middle_length;
  const Point2 d3 = (c - b2) / outgoing_length;
  const double first_turn = turnBetween(d1, d2);
  const double second_turn = turnBetween(d2, d3);
  if (first_turn == 0.0 || second_turn == 0.0 || (first_turn > 0.0) != (second_turn > 0.0)) {
    return std::nullopt;
  }
  const double side = first_turn > 0.0 ? 1.0 : -1.0;  // the corners' way, +1 to the left
  const double r = radius;

  // The arcs onto and off the middle leg's line turn with the corners and touch the line
  // where the run starts and ends; the arcs before and after them turn the other way,
  // touch them from outside and run tangent into the legs.
  const Point2 run_start = b1 + run_from * middle_length * d2;
  const Point2 run_end = b1 + run_to * middle_length * d2;
  const Point2 onto_centre = run_start + side * r * leftNormal(d2);
  const Point2 off_centre = run_end + side * r * leftNormal(d2);

  const std::vector<BulbEnd> exits = bulbExits(b2, d3, off_centre, run_end, side, r);
  std::optional<CornerSmoothing> best;
  double best_length = std::numeric_limits<double>::infinity();
  for (const BulbEnd& entry : bulbEntries(b1, d1, onto_centre, run_start, side, r)) {
    for (const BulbEnd& exit : exits) {
      const double turning =
          side * (entry.middle_sweep + exit.middle_sweep - entry.end_sweep - exit.end_sweep);
      if (std::abs(turning - (first_turn + second_turn)) > kTurnTolerance) continue;
      const double length =
          r * (entry.end_sweep + entry.middle_sweep + exit.middle_sweep + exit.end_sweep) +
          (run_to - run_from) * middle_length;
      if (length >= best_length) continue;
      best_length = length;
      best = bulbSmoothing(entry, exit, onto_centre, off_centre, run_start, run_end,
                           run_to > run_from, side, r);
    }
  }
  return best;
}

}  // namespace kinematic_coverage::core
