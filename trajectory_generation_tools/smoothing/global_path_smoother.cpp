#include "trajectory_generation_tools/smoothing/global_path_smoother.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/base/trapezoidal_velocity_profile.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/smoothing/bulb_turn_smoothing.h"
#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/corner_waypoints.h"
#include "trajectory_generation_tools/smoothing/inner_smoothing.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_bisector.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_tangent.h"
#include "trajectory_generation_tools/smoothing/path_coverage_check.h"
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

/// A larger radius (GlobalSmoothingOptions::max_turning_radius) is tried only when it is
/// wider than turning_radius by more than this fraction.
constexpr double kWiderRadiusMargin = 0.01;

/// Coverage-safe smoothing: a guarded corner's smoothing that loses at most this many
/// cells of PathCoverageCheck's raster keeps coverage (the sharp path and the smoothing are
/// rasterized differently: swept rotation sectors against sampled arcs).
constexpr std::size_t kGuardedToleratedCells = 2;

/// The runs along the middle leg (fractions of it, from the first corner) of the bulb turns
/// tried at every pair of corners turning the same way: touching the middle leg's middle,
/// along its middle half, and along all of it (through both corners, whose footprints see
/// the strip beyond the lanes' ends there).
constexpr std::array<std::pair<double, double>, 3> kBulbRuns{
    {{0.5, 0.5}, {0.25, 0.75}, {0.0, 1.0}}};
/// rad: the largest corner turn whose inner arc's reach (r tan(turn / 2)) places a bulb's
/// one-sided run; sharper corners use it too, which keeps the tangent finite.
constexpr double kMaxFlushTurn = 0.9 * M_PI;

double arcsLength(const CornerSmoothing& smoothing) {
  double length = 0.0;
  for (const PathPrimitive& arc : smoothing.arcs) length += arc.length();
  return length;
}

/// The angle (rad, in [0, pi]) between unit directions `from` and `to`: a corner's turn.
double turnBetween(const Point2& from, const Point2& to) {
  return std::atan2(std::abs(from.x() * to.y() - from.y() * to.x()), from.dot(to));
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
    : free_area_(free_area), index_(free_area, options.clearance), options_(options) {
  requirePositive("the turning radius", options.vehicle.turning_radius);
  requirePositive("the smallest turning radius", options.min_turning_radius);
  requirePositive("the speed limit", options.vehicle.v_max);
  requirePositive("the acceleration limit", options.vehicle.a_max);
  requirePositive("the yaw rate limit", options.vehicle.yaw_rate_max);
  if (options.min_turning_radius > options.vehicle.turning_radius) {
    throw InvalidInputError(
        "the smallest turning radius " + std::to_string(options.min_turning_radius) +
        " must not exceed the turning radius " + std::to_string(options.vehicle.turning_radius));
  }
  if (!std::isfinite(options.max_turning_radius) || options.max_turning_radius < 0.0) {
    throw InvalidInputError("the largest turning radius must be a finite number >= 0, got " +
                            std::to_string(options.max_turning_radius));
  }
  const double span = options.vehicle.turning_radius - options.min_turning_radius;
  const int levels = span > 0.0 ? kRadiusLevels : 1;
  for (int level = 0; level < levels; ++level) {
    radii_.push_back(level + 1 == levels && levels > 1
                         ? options.min_turning_radius
                         : options.vehicle.turning_radius - span * level / std::max(1, levels - 1));
  }
  if (options.max_turning_radius > options.vehicle.turning_radius * (1.0 + kWiderRadiusMargin)) {
    radii_.insert(radii_.begin(), options.max_turning_radius);
  }
}

SmoothedPath GlobalPathSmoother::smooth(const std::vector<Pose2>& waypoints) const {
  std::vector<Point2> points;
  points.reserve(waypoints.size());
  for (const Pose2& pose : waypoints) points.push_back(pose.position());
  return smooth(points);
}

SmoothedPath GlobalPathSmoother::smooth(const std::vector<Point2>& waypoints) const {
  const GlobalSmoothingPlan plan = programme(waypoints).plan();
  SmoothedPath path = SmoothedPathAssembler::assemble(plan.waypoints, plan.smoothings);
  path.statistics.kept_for_coverage = plan.kept_for_coverage;
  return path;
}

GlobalSmoothingProgramme GlobalPathSmoother::programme(const std::vector<Point2>& waypoints) const {
  return GlobalSmoothingProgramme(*this, cornerWaypoints(waypoints));
}

GlobalSmoothingProgramme::GlobalSmoothingProgramme(const GlobalPathSmoother& smoother,
                                                   const std::vector<Point2>& points)
    : smoother_(smoother), points_(points) {
  if (smoother_.options_.preserved_sensor) {
    coverage_.emplace(smoother_.index_, *smoother_.options_.preserved_sensor);
  }
  const std::size_t legs = points_.size() < 2 ? 0 : points_.size() - 1;
  leg_length_.resize(legs);
  leg_direction_.resize(legs);
  leg_free_.resize(legs);
  for (std::size_t k = 0; k < legs; ++k) {
    const Point2 d = points_[k + 1] - points_[k];
    leg_length_[k] = d.norm();
    leg_direction_[k] = d / leg_length_[k];
    leg_free_[k] = smoother_.index_.inside(points_[k]) &&
                   smoother_.index_.segmentClear(points_[k], points_[k + 1]);
  }
  const std::size_t corners = points_.size() < 3 ? 0 : points_.size() - 2;
  candidates_.resize(corners);
  verdict_.resize(corners);
  for (std::size_t i = 0; i < corners; ++i) {
    addCandidates(i, smoother_.radii_);
    verdict_[i].assign(candidates_[i].size(), CoverageVerdict::kUnchecked);
  }
}

void GlobalSmoothingProgramme::addCandidates(std::size_t i, const std::vector<double>& radii) {
  // Corner i is waypoint i + 1. A reverse curve over corners i - 1 and i is a candidate of
  // corner i that follows a candidate of corner i - 2.
  const GlobalSmoothingOptions& options = smoother_.options_;
  const Point2& a = points_[i];
  const Point2& b = points_[i + 1];
  const Point2& c = points_[i + 2];
  const Point2& incoming = leg_direction_[i];
  const Point2& outgoing = leg_direction_[i + 1];
  const double turn = turnBetween(incoming, outgoing);
  std::vector<GlobalSmoothingCandidate>& list = candidates_[i];
  list.push_back({std::nullopt, 0.0, 0.0, 0.0, 0.0, turn / options.vehicle.yaw_rate_max, {}});

  // `smoothing` replaces the corners `corner_path` turns at; it enters on leg `in_leg`.
  // Kept when its arcs are clear and it starts and ends on its legs (Alg. 1).
  const auto consider = [&](std::optional<CornerSmoothing> smoothing, double radius,
                            std::size_t in_leg, const std::vector<Point2>& corner_path) {
    if (!smoothing || smoothing->arcs.empty()) return;
    const double entry = smoothing->entry_distance;
    const double exit = smoothing->exit_distance;
    const double in_tolerance = kLegTolerance * std::max(1.0, leg_length_[in_leg]);
    const double out_tolerance = kLegTolerance * std::max(1.0, leg_length_[i + 1]);
    if (!std::isfinite(entry) || !std::isfinite(exit) || entry < -in_tolerance ||
        exit < -out_tolerance || entry > leg_length_[in_leg] + in_tolerance ||
        exit > leg_length_[i + 1] + out_tolerance) {
      return;
    }
    for (const PathPrimitive& arc : smoothing->arcs) {
      if (!std::isfinite(arc.sweep()) || !arc.start().allFinite() || !arc.end().allFinite() ||
          !smoother_.index_.primitiveClear(arc)) {
        return;
      }
    }
    const double speed = options.vehicle.arcSpeed(radius);
    const double time = arcsLength(*smoothing) / speed;
    list.push_back({std::move(smoothing), radius, std::max(0.0, entry), std::max(0.0, exit), speed,
                    time, corner_path});
  };

  // The tangent variant depends on where the smoothing may start (Alg. 8 puts the first
  // circle at the shorter leg's far end), so it is also tried from each place the
  // previous corner's candidates end.
  std::vector<double> starts{0.0};
  if (i > 0) {
    for (const GlobalSmoothingCandidate& previous : candidates_[i - 1]) {
      if (!previous.smoothing) continue;
      const bool known = std::any_of(starts.begin(), starts.end(), [&](double s) {
        return std::abs(s - previous.exit) <= kSameEntryTolerance * leg_length_[i];
      });
      if (!known && previous.exit < leg_length_[i]) starts.push_back(previous.exit);
    }
  }
  for (const double radius : radii) {
    const Corner corner{a, b, c, radius, incoming};
    consider(InnerSmoothing::compute(corner), radius, i, {a, b, c});
    consider(OuterSmoothingBisector::compute(corner), radius, i, {a, b, c});
    for (const double start : starts) {
      const Corner shortened{a + start * incoming, b, c, radius, incoming};
      if (start > 0.0 && (b - shortened.a).norm() >= leg_length_[i + 1]) continue;
      std::optional<CornerSmoothing> tangent = OuterSmoothingTangent::compute(shortened);
      if (tangent && std::max(tangent->entry_distance, tangent->exit_distance) >
                         kMaxTangentReachRadii * radius) {
        continue;
      }
      consider(std::move(tangent), radius, i, {a, b, c});
    }
    if (i > 0) {
      const Point2& before = points_[i - 1];
      std::optional<CornerSmoothing> curve =
          ReverseCurveSmoothing::compute(before, a, b, c, radius);
      consider(std::move(curve), radius, i - 1, {before, a, b, c});
      if (options.bulb_turns) {
        for (const auto& [run_from, run_to] : bulbRuns(i, radius)) {
          consider(BulbTurnSmoothing::compute(before, a, b, c, radius, run_from, run_to), radius,
                   i - 1, {before, a, b, c});
        }
      }
    }
  }
}

std::vector<std::pair<double, double>> GlobalSmoothingProgramme::bulbRuns(std::size_t i,
                                                                          double radius) const {
  std::vector<std::pair<double, double>> runs(kBulbRuns.begin(), kBulbRuns.end());
  // The middle leg is leg i, between corners i - 1 and i. Where the lanes are closer than
  // two radii a bulb swings beyond one of them; these runs keep all of the swing on one
  // side, for a lane beside a wall: the arc onto the middle leg is the inner arc of the
  // first corner (it touches the leg r tan(turn / 2) after it), or the arc off it is the
  // inner arc of the second.
  const double middle = leg_length_[i];
  const auto inner_reach = [&](const Point2& from, const Point2& to) {
    return radius * std::tan(0.5 * std::min(turnBetween(from, to), kMaxFlushTurn)) / middle;
  };
  const double incoming = std::min(1.0, inner_reach(leg_direction_[i - 1], leg_direction_[i]));
  const double outgoing =
      std::max(0.0, 1.0 - inner_reach(leg_direction_[i], leg_direction_[i + 1]));
  runs.emplace_back(incoming, incoming);
  runs.emplace_back(outgoing, outgoing);
  return runs;
}

std::optional<double> GlobalSmoothingProgramme::legPiece(
    std::size_t leg, const GlobalSmoothingCandidate* previous,
    const GlobalSmoothingCandidate* next) const {
  // The piece runs from `from` metres after P_leg to `to` metres before P_leg+1. The whole
  // leg between two sharp turns (or the path's ends) is the planner's own and can always be
  // driven, so that the all-sharp choice is always feasible.
  const double from = previous ? previous->exit : 0.0;
  const double to = next ? next->entry : 0.0;
  const bool whole_leg = !(previous && previous->smoothing) && !(next && next->smoothing);
  const double length = leg_length_[leg];
  const double tolerance = kLegTolerance * std::max(1.0, length);
  // A smoothing begins no sooner than the previous one ends (Alg. 1).
  if (from + to > length + tolerance) return std::nullopt;
  if (!leg_free_[leg] && !whole_leg) {
    const Point2 start = points_[leg] + from * leg_direction_[leg];
    const Point2 end = points_[leg + 1] - to * leg_direction_[leg];
    if (!smoother_.index_.inside(start) || !smoother_.index_.segmentClear(start, end)) {
      return std::nullopt;
    }
  }
  const TrapezoidalVelocityProfile profile(smoother_.options_.vehicle);
  return profile.pieceTime(length - from - to, previous ? previous->speed : 0.0,
                           next ? next->speed : 0.0);
}

bool GlobalSmoothingProgramme::preservesCoverage(
    std::size_t i, std::size_t j, std::vector<std::vector<CoverageVerdict>>& verdicts,
    const PathCoverageCheck* path_check) const {
  const GlobalSmoothingCandidate& candidate = candidates_[i][j];
  if ((!coverage_ && !path_check) || !candidate.smoothing) return true;
  CoverageVerdict& verdict = verdicts[i][j];
  if (verdict == CoverageVerdict::kUnchecked) {
    bool preserves = false;
    if (path_check) {
      // The candidate in the sharp path: its legs driven from their starts through its
      // arcs to their ends, every other corner sharp.
      const std::size_t first_leg = i + 1 - candidate.corners();
      const std::size_t last_leg = i + 1;
      const std::vector<Point2> legs(points_.begin() + static_cast<std::ptrdiff_t>(first_leg),
                                     points_.begin() + static_cast<std::ptrdiff_t>(last_leg + 2));
      std::vector<std::optional<CornerSmoothing>> smoothing(legs.size() - 2);
      smoothing.front() = candidate.smoothing;
      const std::vector<PathPrimitive> replacement =
          SmoothedPathAssembler::assemble(legs, smoothing).primitives;
      preserves =
          path_check->lostCellsReplacing(first_leg, last_leg, replacement,
                                         replacedStretch(i, candidate)) <= kGuardedToleratedCells;
    } else {
      preserves = coverage_->preserves(candidate.corner_path, *candidate.smoothing);
    }
    verdict = preserves ? CoverageVerdict::kPreserves : CoverageVerdict::kRefused;
  }
  return verdict == CoverageVerdict::kPreserves;
}

GlobalSmoothingEvaluation GlobalSmoothingProgramme::evaluate(const GlobalSmoothingChoice& choice) {
  const GlobalSmoothingEvaluation infeasible{};
  const std::size_t n = corners();
  if (choice.size() != n) return infeasible;
  // Every corner is taken exactly once: a reverse curve chosen at corner i takes corner
  // i - 1, which has no candidate of its own.
  for (std::size_t i = 0; i < n; ++i) {
    if (choice[i] == kNoCandidate) {
      if (i + 1 >= n || choice[i + 1] < 0 ||
          static_cast<std::size_t>(choice[i + 1]) >= candidates_[i + 1].size() ||
          candidates_[i + 1][static_cast<std::size_t>(choice[i + 1])].corners() != 2) {
        return infeasible;
      }
    } else if (choice[i] < 0 || static_cast<std::size_t>(choice[i]) >= candidates_[i].size()) {
      return infeasible;
    } else if (candidates_[i][static_cast<std::size_t>(choice[i])].corners() == 2 &&
               (i == 0 || choice[i - 1] != kNoCandidate)) {
      return infeasible;
    }
  }
  if (leg_length_.empty()) return {true, 0.0};
  // Summed in the order the dynamic programme adds them, piece by piece along the path.
  double time = 0.0;
  const GlobalSmoothingCandidate* previous = nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    if (choice[i] == kNoCandidate) continue;
    const std::size_t j = static_cast<std::size_t>(choice[i]);
    const GlobalSmoothingCandidate& current = candidates_[i][j];
    if (smoother_.options_.preserved_sensor && !preservesCoverage(i, j, verdict_, nullptr)) {
      return infeasible;
    }
    const std::optional<double> piece = legPiece(i + 1 - current.corners(), previous, &current);
    if (!piece) return infeasible;
    time += *piece;
    time += current.time;
    previous = &current;
  }
  const std::optional<double> last = legPiece(n, previous, nullptr);
  if (!last) return infeasible;
  return {true, time + *last};
}

GlobalSmoothingChoice GlobalSmoothingProgramme::solve(
    const std::vector<std::vector<CoverageVerdict>>& verdict, double* least) const {
  // best[i][j] is the least time from the start to the end of candidate j of corner i,
  // over compatible choices at the corners before it; from[i][j] is the candidate it
  // follows at the corner before the leg it enters on (-1: the start).
  const std::size_t corners = this->corners();
  std::vector<std::vector<double>> best(corners);
  std::vector<std::vector<int>> from(corners);
  for (std::size_t i = 0; i < corners; ++i) {
    best[i].assign(candidates_[i].size(), kInfinity);
    from[i].assign(candidates_[i].size(), -1);
    for (std::size_t j = 0; j < candidates_[i].size(); ++j) {
      if (verdict[i][j] == CoverageVerdict::kRefused) continue;
      const GlobalSmoothingCandidate& current = candidates_[i][j];
      const std::size_t leg = i + 1 - current.corners();  // the leg it enters on
      if (leg == 0) {
        if (const std::optional<double> piece = legPiece(0, nullptr, &current)) {
          best[i][j] = *piece + current.time;
        }
        continue;
      }
      const std::size_t layer = leg - 1;  // the corner before it
      for (std::size_t p = 0; p < candidates_[layer].size(); ++p) {
        if (best[layer][p] == kInfinity) continue;
        const std::optional<double> piece = legPiece(leg, &candidates_[layer][p], &current);
        if (!piece) continue;
        const double time = best[layer][p] + *piece + current.time;
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
  *least = kInfinity;
  int choice = 0;
  for (std::size_t j = 0; j < candidates_[last].size(); ++j) {
    if (best[last][j] == kInfinity) continue;
    const std::optional<double> piece = legPiece(last + 1, &candidates_[last][j], nullptr);
    if (!piece) continue;
    const double time = best[last][j] + *piece;
    if (time < *least) {
      *least = time;
      choice = static_cast<int>(j);
    }
  }
  // Back from the last corner; a reverse curve, chosen at the later of its two corners,
  // leaves the earlier one without a candidate.
  GlobalSmoothingChoice chosen(corners, kNoCandidate);
  std::size_t i = corners;
  while (i-- > 0 && choice >= 0) {
    chosen[i] = choice;
    const int previous = from[i][static_cast<std::size_t>(choice)];
    if (candidates_[i][static_cast<std::size_t>(choice)].corners() == 2) --i;
    choice = previous;
  }
  return chosen;
}

bool GlobalSmoothingProgramme::refuseUnpreserved(const GlobalSmoothingChoice& choice,
                                                 const std::vector<bool>& guarded,
                                                 std::vector<std::vector<CoverageVerdict>>& verdict,
                                                 std::vector<bool>& refused_at,
                                                 const PathCoverageCheck* path_check) const {
  bool refused = false;
  for (std::size_t i = 0; i < choice.size(); ++i) {
    if (choice[i] == kNoCandidate || !guarded[i]) continue;
    const std::size_t j = static_cast<std::size_t>(choice[i]);
    const GlobalSmoothingCandidate& candidate = candidates_[i][j];
    if (!candidate.smoothing || verdict[i][j] != CoverageVerdict::kUnchecked) continue;
    if (!preservesCoverage(i, j, verdict, path_check)) {
      refused_at[i] = true;
      if (candidate.corners() == 2) refused_at[i - 1] = true;
      refused = true;
    }
  }
  return refused;
}

GlobalSmoothingChoice GlobalSmoothingProgramme::solveGuarded(
    const std::vector<bool>& guarded, std::vector<std::vector<CoverageVerdict>>& verdict,
    std::vector<bool>& refused_at, double* least, const PathCoverageCheck* path_check) const {
  // Only the smoothings the programme chooses are checked (each check rasterizes the
  // corner): a refused one is dropped and the programme runs again, until every chosen
  // smoothing of a guarded corner preserves coverage. Every round drops a candidate, and
  // the result is the fastest choice among the candidates that preserve coverage, as if
  // all had been checked first.
  GlobalSmoothingChoice choice = solve(verdict, least);
  while ((coverage_ || path_check) &&
         refuseUnpreserved(choice, guarded, verdict, refused_at, path_check)) {
    choice = solve(verdict, least);
  }
  return choice;
}

std::vector<std::optional<CornerSmoothing>> GlobalSmoothingProgramme::smoothingsOf(
    const GlobalSmoothingChoice& choice) const {
  // A reverse curve chosen at corner i is assembled at corner i - 1.
  std::vector<std::optional<CornerSmoothing>> smoothings(choice.size());
  for (std::size_t i = 0; i < choice.size(); ++i) {
    if (choice[i] == kNoCandidate) continue;
    const std::optional<CornerSmoothing>& smoothing =
        candidates_[i][static_cast<std::size_t>(choice[i])].smoothing;
    smoothings[smoothing && smoothing->corners == 2 ? i - 1 : i] = smoothing;
  }
  return smoothings;
}

std::vector<Point2> GlobalSmoothingProgramme::replacedStretch(
    std::size_t i, const GlobalSmoothingCandidate& candidate) const {
  // From where the first arc leaves its leg (measured from the first corner), through the
  // corners, to where the last arc joins leg i + 1 (measured from the last corner).
  const std::vector<Point2>& path = candidate.corner_path;
  const std::size_t first_leg = i + 1 - candidate.corners();
  std::vector<Point2> stretch{path[1] - candidate.entry * leg_direction_[first_leg]};
  stretch.insert(stretch.end(), path.begin() + 1, path.end() - 1);
  stretch.push_back(path[path.size() - 2] + candidate.exit * leg_direction_[i + 1]);
  return stretch;
}

void GlobalSmoothingProgramme::keepCoverageSafe(GlobalSmoothingPlan& plan, PathCoverageCheck& check,
                                                std::vector<bool>& guarded,
                                                std::vector<std::vector<CoverageVerdict>>& verdict,
                                                std::vector<bool>& refused_at) const {
  // Every round guards a corner or refuses a candidate, so the rounds end; the all-sharp
  // choice loses nothing.
  for (;;) {
    std::vector<ReplacedStretch> stretches;
    std::vector<std::size_t> stretch_corner;  // the corner whose candidate it is
    for (std::size_t i = 0; i < plan.choice.size(); ++i) {
      if (plan.choice[i] == kNoCandidate) continue;
      const GlobalSmoothingCandidate& candidate =
          candidates_[i][static_cast<std::size_t>(plan.choice[i])];
      if (!candidate.smoothing) continue;
      stretches.push_back(replacedStretch(i, candidate));
      stretch_corner.push_back(i);
    }
    if (stretches.empty()) return;
    const std::vector<std::size_t> lost = check.lostCells(
        SmoothedPathAssembler::assemble(points_, smoothingsOf(plan.choice)).primitives, stretches);
    // The largest losses first, until what the others lose together is tolerated.
    std::vector<std::size_t> order(stretches.size());
    for (std::size_t s = 0; s < order.size(); ++s) order[s] = s;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return lost[a] > lost[b]; });
    std::size_t remaining = 0;
    for (const std::size_t cells : lost) remaining += cells;
    bool changed = false;
    for (const std::size_t s : order) {
      if (remaining <= check.toleratedLostCells() || lost[s] == 0) break;
      remaining -= lost[s];
      const std::size_t i = stretch_corner[s];
      if (!guarded[i]) {
        guarded[i] = true;
      } else {
        verdict[i][static_cast<std::size_t>(plan.choice[i])] = CoverageVerdict::kRefused;
      }
      refused_at[i] = true;
      changed = true;
    }
    if (!changed) return;
    plan.choice = solveGuarded(guarded, verdict, refused_at, &plan.time, &check);
  }
}

GlobalSmoothingPlan GlobalSmoothingProgramme::plan() const {
  GlobalSmoothingPlan plan;
  plan.waypoints = points_;
  const std::size_t corners = this->corners();
  plan.smoothings.resize(corners);
  if (corners == 0) {
    plan.time =
        leg_length_.empty() ? 0.0 : *legPiece(0, nullptr, nullptr);  // one leg, from rest to rest
    return plan;
  }

  std::vector<std::vector<CoverageVerdict>> verdict(corners);
  for (std::size_t i = 0; i < corners; ++i) {
    verdict[i].assign(candidates_[i].size(), CoverageVerdict::kUnchecked);
  }
  // Coverage-preserving smoothing guards every corner; coverage-safe smoothing guards the
  // corners whose smoothing the whole-path check finds losing area.
  std::vector<bool> guarded(corners, smoother_.options_.preserved_sensor.has_value());
  std::vector<bool> coverage_refused(corners, false);
  plan.choice = solveGuarded(guarded, verdict, coverage_refused, &plan.time, nullptr);
  if (smoother_.options_.safe_sensor && !smoother_.options_.preserved_sensor) {
    PathCoverageCheck check(smoother_.free_area_, smoother_.options_.wall_distance,
                            smoother_.options_.exact_offset_parts, *smoother_.options_.safe_sensor,
                            points_, smoother_.options_.coverage_safe_area);
    keepCoverageSafe(plan, check, guarded, verdict, coverage_refused);
  }

  plan.smoothings = smoothingsOf(plan.choice);
  for (std::size_t i = 0; i < corners; ++i) {
    if (!plan.smoothings[i] && coverage_refused[i] &&
        !(i > 0 && plan.smoothings[i - 1] && plan.smoothings[i - 1]->corners == 2)) {
      ++plan.kept_for_coverage;
    }
  }
  return plan;
}

}  // namespace kinematic_coverage::core
