#include "trajectory_generation_tools/smoothing/global_path_smoother.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/smoothing/corner_coverage_check.h"
#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/corner_waypoints.h"
#include "trajectory_generation_tools/smoothing/inner_smoothing.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_bisector.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_tangent.h"
#include "trajectory_generation_tools/smoothing/reverse_curve_smoothing.h"
#include "trajectory_generation_tools/smoothing/smoothed_path_assembler.h"

namespace kinematic_coverage::core {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Two candidate entry points of a tangent smoothing closer than this (times the leg's
/// length) are the same.
constexpr double kSameEntryTolerance = 1e-9;

/// A tangent smoothing (Alg. 8) may leave and join the legs at most this many radii from
/// the corner. Alg. 8 starts at the shorter leg's far end; at a reversal after a long lane
/// that skips the lane's end and the way back, which Algorithm 1 only risks when no other
/// variant fits, but a time-minimising choice would take everywhere.
constexpr double kMaxTangentReachRadii = 4.0;

/// One way to take one corner, with what the dynamic programme needs of it.
struct Candidate {
  std::optional<CornerSmoothing> smoothing;  ///< nullopt: a sharp turn
  double entry = 0.0;  ///< distance from B back along the incoming leg where it starts
  double exit = 0.0;   ///< distance from B along the outgoing leg where it ends
  double speed = 0.0;  ///< speed on it (0: sharp, the robot stops)
  double time = 0.0;   ///< seconds to drive it (a sharp turn: its rotation)
  /// The sharp corners it replaces (a, b, c, or a, b1, b2, c), for the coverage check.
  std::vector<Point2> corner_path;
};

/// A candidate's coverage check: not yet made, passed, or refused (the smoothing sees less
/// than the sharp corners it replaces).
enum class CoverageVerdict { kUnchecked, kPreserves, kRefused };

/// Fastest time (s) over a straight piece of `length` from speed v0 to speed v1 under
/// v_max and a_max (the trapezoid of the velocity model). When the piece is too short to
/// change between the two speeds, the faster end is slowed to the reachable speed and
/// the time that costs on the neighbouring arc is approximated by the braking time.
double pieceTime(double length, double v0, double v1, double v_max, double a_max) {
  length = std::max(0.0, length);
  double penalty = 0.0;
  const double reachable_high =
      std::sqrt(std::min(v0, v1) * std::min(v0, v1) + 2.0 * a_max * length);
  if (std::max(v0, v1) > reachable_high) {
    penalty = (std::max(v0, v1) - reachable_high) / a_max;
    if (v0 > v1) {
      v0 = reachable_high;
    } else {
      v1 = reachable_high;
    }
  }
  const double peak = std::min(v_max, std::sqrt(a_max * length + 0.5 * (v0 * v0 + v1 * v1)));
  if (peak <= 0.0) return penalty;
  const double accelerating = std::max(0.0, (peak * peak - v0 * v0) / (2.0 * a_max));
  const double braking = std::max(0.0, (peak * peak - v1 * v1) / (2.0 * a_max));
  const double cruising = std::max(0.0, length - accelerating - braking);
  return penalty + (peak - v0) / a_max + (peak - v1) / a_max + cruising / peak;
}

double arcsLength(const CornerSmoothing& smoothing) {
  double length = 0.0;
  for (const PathPrimitive& arc : smoothing.arcs) length += arc.length();
  return length;
}

void requirePositive(const char* name, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInputError(std::string(name) + " must be a positive finite number, got " +
                            std::to_string(value));
  }
}

}  // namespace

GlobalPathSmoother::GlobalPathSmoother(const PolygonWithHoles& free_area,
                                       const GlobalSmoothingOptions& options)
    : index_(free_area), options_(options) {
  requirePositive("turning_radius", options.turning_radius);
  requirePositive("min_turning_radius", options.min_turning_radius);
  requirePositive("v_max", options.v_max);
  requirePositive("a_max", options.a_max);
  requirePositive("yaw_rate_max", options.yaw_rate_max);
  if (options.min_turning_radius > options.turning_radius) {
    throw InvalidInputError(
        "min_turning_radius = " + std::to_string(options.min_turning_radius) +
        " must not exceed turning_radius = " + std::to_string(options.turning_radius));
  }
  const double span = options.turning_radius - options.min_turning_radius;
  const int levels = span > 0.0 ? kRadiusLevels : 1;
  for (int level = 0; level < levels; ++level) {
    radii_.push_back(level + 1 == levels && levels > 1
                         ? options.min_turning_radius
                         : options.turning_radius - span * level / std::max(1, levels - 1));
  }
}

SmoothedPath GlobalPathSmoother::smooth(const std::vector<Pose2>& waypoints) const {
  std::vector<Point2> points;
  points.reserve(waypoints.size());
  for (const Pose2& pose : waypoints) points.push_back(pose.position());
  return smooth(points);
}

SmoothedPath GlobalPathSmoother::smooth(const std::vector<Point2>& waypoints) const {
  const std::vector<Point2> points = cornerWaypoints(waypoints);
  if (points.size() < 3) return SmoothedPathAssembler::assemble(points, {});
  const std::size_t corners = points.size() - 2;
  const double v_max = options_.v_max;
  const double a_max = options_.a_max;
  std::optional<CornerCoverageCheck> coverage;
  if (options_.preserved_sensor) coverage.emplace(index_, *options_.preserved_sensor);

  // Legs k = P_k -> P_k+1; a leg that is clear and starts in the free area holds every
  // piece of itself, otherwise each piece is checked.
  const std::size_t legs = points.size() - 1;
  std::vector<double> leg_length(legs);
  std::vector<Point2> leg_direction(legs);
  std::vector<bool> leg_free(legs);
  for (std::size_t k = 0; k < legs; ++k) {
    const Point2 d = points[k + 1] - points[k];
    leg_length[k] = d.norm();
    leg_direction[k] = d / leg_length[k];
    leg_free[k] = index_.inside(points[k]) && index_.segmentClear(points[k], points[k + 1]);
  }
  // Whether the piece of leg k from `from` (metres after P_k) to `to` (metres before
  // P_k+1) can be driven. The whole leg between two sharp turns (or the path's ends) is
  // the planner's own and always can, so that the all-sharp choice is always feasible.
  const auto piece_free = [&](std::size_t k, double from, double to, bool whole_leg) {
    const double tolerance = kLegTolerance * std::max(1.0, leg_length[k]);
    if (from + to > leg_length[k] + tolerance) return false;
    if (leg_free[k] || whole_leg) return true;
    const Point2 start = points[k] + from * leg_direction[k];
    const Point2 end = points[k + 1] - to * leg_direction[k];
    return index_.inside(start) && index_.segmentClear(start, end);
  };

  // Candidates per corner i (waypoint i + 1). A reverse curve over corners i - 1 and i is
  // a candidate of corner i that follows a candidate of corner i - 2.
  std::vector<std::vector<Candidate>> candidates(corners);
  for (std::size_t i = 0; i < corners; ++i) {
    const Point2& a = points[i];
    const Point2& b = points[i + 1];
    const Point2& c = points[i + 2];
    const Point2& incoming = leg_direction[i];
    const Point2& outgoing = leg_direction[i + 1];
    const double turn =
        std::atan2(std::abs(incoming.x() * outgoing.y() - incoming.y() * outgoing.x()),
                   incoming.dot(outgoing));
    std::vector<Candidate>& options = candidates[i];
    options.push_back({std::nullopt, 0.0, 0.0, 0.0, turn / options_.yaw_rate_max, {}});

    // `smoothing` replaces the corners `corner_path` turns at; it enters on leg `in_leg`.
    const auto consider = [&](std::optional<CornerSmoothing> smoothing, double radius,
                              std::size_t in_leg, const std::vector<Point2>& corner_path) {
      if (!smoothing || smoothing->arcs.empty()) return;
      const double entry = smoothing->entry_distance;
      const double exit = smoothing->exit_distance;
      const double in_tolerance = kLegTolerance * std::max(1.0, leg_length[in_leg]);
      const double out_tolerance = kLegTolerance * std::max(1.0, leg_length[i + 1]);
      if (!std::isfinite(entry) || !std::isfinite(exit) || entry < -in_tolerance ||
          exit < -out_tolerance || entry > leg_length[in_leg] + in_tolerance ||
          exit > leg_length[i + 1] + out_tolerance) {
        return;
      }
      for (const PathPrimitive& arc : smoothing->arcs) {
        if (!std::isfinite(arc.sweep()) || !arc.start().allFinite() || !arc.end().allFinite() ||
            !index_.arcClear(arc)) {
          return;
        }
      }
      const double speed = std::min(v_max, options_.yaw_rate_max * radius);
      const double time = arcsLength(*smoothing) / speed;
      options.push_back({std::move(smoothing), std::max(0.0, entry), std::max(0.0, exit), speed,
                         time, corner_path});
    };

    // The tangent variant depends on where the smoothing may start (Alg. 8 puts the first
    // circle at the shorter leg's far end), so it is also tried from each place the
    // previous corner's candidates end.
    std::vector<double> starts{0.0};
    if (i > 0) {
      for (const Candidate& previous : candidates[i - 1]) {
        if (!previous.smoothing) continue;
        const bool known = std::any_of(starts.begin(), starts.end(), [&](double s) {
          return std::abs(s - previous.exit) <= kSameEntryTolerance * leg_length[i];
        });
        if (!known && previous.exit < leg_length[i]) starts.push_back(previous.exit);
      }
    }
    for (const double radius : radii_) {
      const Corner corner{a, b, c, radius, incoming};
      consider(InnerSmoothing::compute(corner), radius, i, {a, b, c});
      consider(OuterSmoothingBisector::compute(corner), radius, i, {a, b, c});
      for (const double start : starts) {
        const Corner shortened{a + start * incoming, b, c, radius, incoming};
        if (start > 0.0 && (b - shortened.a).norm() >= leg_length[i + 1]) continue;
        std::optional<CornerSmoothing> tangent = OuterSmoothingTangent::compute(shortened);
        if (tangent && std::max(tangent->entry_distance, tangent->exit_distance) >
                           kMaxTangentReachRadii * radius) {
          continue;
        }
        consider(std::move(tangent), radius, i, {a, b, c});
      }
      if (i > 0) {
        const Point2& before = points[i - 1];
        std::optional<CornerSmoothing> curve =
            ReverseCurveSmoothing::compute(before, a, b, c, radius);
        consider(std::move(curve), radius, i - 1, {before, a, b, c});
      }
    }
  }

  // Dynamic programme over the candidates not refused for coverage: best[i][j] is the
  // least time from the start to the end of candidate j of corner i, over compatible
  // choices at the corners before it; from[i][j] is the candidate it follows at corner
  // i - corners (-1: the start). Returns the chosen candidates, (corner, candidate), from
  // the last corner back; a reverse curve is chosen at the later of its two corners.
  std::vector<std::vector<CoverageVerdict>> verdict(corners);
  for (std::size_t i = 0; i < corners; ++i) {
    verdict[i].assign(candidates[i].size(), CoverageVerdict::kUnchecked);
  }
  std::vector<std::vector<double>> best(corners);
  std::vector<std::vector<int>> from(corners);
  const auto choose = [&] {
    for (std::size_t i = 0; i < corners; ++i) {
      best[i].assign(candidates[i].size(), kInfinity);
      from[i].assign(candidates[i].size(), -1);
      for (std::size_t j = 0; j < candidates[i].size(); ++j) {
        if (verdict[i][j] == CoverageVerdict::kRefused) continue;
        const Candidate& current = candidates[i][j];
        const std::size_t spanned = current.smoothing ? current.smoothing->corners : 1;
        const std::size_t leg = i + 1 - spanned;  // the leg it enters on
        if (leg == 0) {
          if (piece_free(0, 0.0, current.entry, !current.smoothing)) {
            best[i][j] =
                pieceTime(leg_length[0] - current.entry, 0.0, current.speed, v_max, a_max) +
                current.time;
          }
          continue;
        }
        const std::size_t layer = leg - 1;  // the corner before it
        for (std::size_t p = 0; p < candidates[layer].size(); ++p) {
          if (best[layer][p] == kInfinity) continue;
          const Candidate& previous = candidates[layer][p];
          if (!piece_free(leg, previous.exit, current.entry,
                          !previous.smoothing && !current.smoothing)) {
            continue;
          }
          const double time = best[layer][p] +
                              pieceTime(leg_length[leg] - previous.exit - current.entry,
                                        previous.speed, current.speed, v_max, a_max) +
                              current.time;
          if (time < best[i][j]) {
            best[i][j] = time;
            from[i][j] = static_cast<int>(p);
          }
        }
      }
    }
    // The last leg to the final waypoint, at rest there. The all-sharp choice is always
    // feasible (and never refused), so some choice is finite.
    const std::size_t last = corners - 1;
    double least = kInfinity;
    int choice = 0;
    for (std::size_t j = 0; j < candidates[last].size(); ++j) {
      const Candidate& candidate = candidates[last][j];
      if (best[last][j] == kInfinity ||
          !piece_free(last + 1, candidate.exit, 0.0, !candidate.smoothing)) {
        continue;
      }
      const double time = best[last][j] + pieceTime(leg_length[last + 1] - candidate.exit,
                                                    candidate.speed, 0.0, v_max, a_max);
      if (time < least) {
        least = time;
        choice = static_cast<int>(j);
      }
    }
    std::vector<std::pair<std::size_t, std::size_t>> chosen;
    std::size_t i = corners;
    while (i-- > 0 && choice >= 0) {
      const Candidate& candidate = candidates[i][static_cast<std::size_t>(choice)];
      chosen.emplace_back(i, static_cast<std::size_t>(choice));
      const int previous = from[i][static_cast<std::size_t>(choice)];
      if (candidate.smoothing && candidate.smoothing->corners == 2) --i;
      choice = previous;
    }
    return chosen;
  };

  // Coverage-preserving smoothing checks only the smoothings the programme chooses (each
  // check rasterizes the corner): a refused one is dropped and the programme runs again,
  // until every chosen smoothing preserves coverage. Every round drops a candidate, and
  // the result is the fastest choice among the candidates that preserve coverage, as if
  // all had been checked first. A corner left sharp whose fastest choice was refused
  // counts as kept for coverage.
  std::vector<bool> coverage_refused(corners, false);
  std::vector<std::pair<std::size_t, std::size_t>> chosen = choose();
  while (coverage) {
    bool refused = false;
    for (const auto& [i, j] : chosen) {
      const Candidate& candidate = candidates[i][j];
      if (!candidate.smoothing || verdict[i][j] != CoverageVerdict::kUnchecked) continue;
      if (coverage->preserves(candidate.corner_path, *candidate.smoothing)) {
        verdict[i][j] = CoverageVerdict::kPreserves;
      } else {
        verdict[i][j] = CoverageVerdict::kRefused;
        coverage_refused[i] = true;
        if (candidate.smoothing->corners == 2) coverage_refused[i - 1] = true;
        refused = true;
      }
    }
    if (!refused) break;
    chosen = choose();
  }

  // A reverse curve chosen at corner i is assembled at corner i - 1.
  std::vector<std::optional<CornerSmoothing>> smoothings(corners);
  for (const auto& [i, j] : chosen) {
    const std::optional<CornerSmoothing>& smoothing = candidates[i][j].smoothing;
    if (smoothing && smoothing->corners == 2) {
      smoothings[i - 1] = smoothing;
    } else {
      smoothings[i] = smoothing;
    }
  }
  int kept_for_coverage = 0;
  for (std::size_t i = 0; i < corners; ++i) {
    if (!smoothings[i] && coverage_refused[i] &&
        !(i > 0 && smoothings[i - 1] && smoothings[i - 1]->corners == 2)) {
      ++kept_for_coverage;
    }
  }
  SmoothedPath path = SmoothedPathAssembler::assemble(points, smoothings);
  path.statistics.kept_for_coverage = kept_for_coverage;
  return path;
}

}  // namespace kinematic_coverage::core
