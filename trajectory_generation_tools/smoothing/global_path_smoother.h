#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner_coverage_check.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"
#include "trajectory_generation_tools/smoothing/global_smoothing_options.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {

/// One way the global programme may take a corner, with what the dynamic programme needs of
/// it: a sharp turn (an in-place rotation), or a smoothing by Alg. 2 to 8 at one radius.
struct GlobalSmoothingCandidate {
  std::optional<CornerSmoothing> smoothing;  ///< nullopt: a sharp turn
  double radius = 0.0;                       ///< radius of its arcs (0: sharp)
  double entry = 0.0;  ///< distance from B back along the incoming leg where it starts
  double exit = 0.0;   ///< distance from B along the outgoing leg where it ends
  double speed = 0.0;  ///< speed on it (0: sharp, the robot stops)
  double time = 0.0;   ///< seconds to drive it (a sharp turn: its rotation)
  /// The sharp corners it replaces (a, b, c, or a, b1, b2, c), for the coverage check.
  std::vector<Point2> corner_path;

  /// Corners it takes: 1, or 2 for a reverse curve, which is a candidate of the later of
  /// its two corners and enters on the leg before the earlier one.
  std::size_t corners() const {
    return smoothing ? static_cast<std::size_t>(smoothing->corners) : 1;
  }
};

/// How to take every corner of a path: entry i is the index of corner i's candidate (see
/// GlobalSmoothingProgramme::candidates), or GlobalSmoothingProgramme::kNoCandidate where
/// corner i is the first corner of the reverse curve chosen at corner i + 1.
using GlobalSmoothingChoice = std::vector<int>;

/// A choice's objective and whether it can be driven at all.
struct GlobalSmoothingEvaluation {
  bool feasible = false;
  /// Traversal time (s) from rest at the first waypoint to rest at the last; infinity when
  /// not feasible.
  double time = std::numeric_limits<double>::infinity();
};

/// What the dynamic programme chose for one path.
struct GlobalSmoothingPlan {
  /// The waypoints turned at (cornerWaypoints of the input); corner i is waypoint i + 1.
  std::vector<Point2> waypoints;
  /// The chosen candidate per corner (a feasible choice; empty without corners).
  GlobalSmoothingChoice choice;
  /// Its objective: the least traversal time over every feasible choice.
  double time = 0.0;
  /// Per corner, as SmoothedPathAssembler takes them: the chosen smoothing or nullopt for
  /// a sharp turn; a reverse curve is listed at the earlier of its two corners.
  std::vector<std::optional<CornerSmoothing>> smoothings;
  /// Corners left sharp because their fastest smoothing was refused for coverage.
  int kept_for_coverage = 0;
};

class GlobalPathSmoother;
class PathCoverageCheck;

/// The global strategy's optimisation problem for one path: the candidates of every corner,
/// the feasibility and objective of any choice among them (evaluate), and the dynamic
/// programme that finds the fastest feasible choice (plan). Made by
/// GlobalPathSmoother::programme; it refers to that smoother, which must outlive it.
///
/// Feasibility is Algorithm 1's (Alg. 1): a smoothing's arcs keep clear of the raw hull and
/// holes, start on the incoming leg and end on the outgoing one, and begin no sooner than
/// the previous corner's smoothing ends; the leg pieces between them are clear and in the
/// free area (a whole leg between two sharp turns or the path's ends always is, so the
/// all-sharp choice is always feasible). With a preserved sensor, every chosen smoothing
/// must also preserve coverage (CornerCoverageCheck). With a safe sensor, the chosen
/// smoothings together must see what the sharp path sees (PathCoverageCheck), up to its
/// tolerated loss: the corners whose smoothings lose the most reachable area are guarded
/// (their smoothings must then keep what the sharp path sees with only that corner
/// smoothed) until the rest lose no more than that, and a guarded corner's smoothing that
/// still loses area is refused.
///
/// The objective is the sum of the pieces' times under the velocity model: each arc chain
/// driven at its speed limit min(v_max, yaw_rate_max * radius), a sharp corner as stop,
/// rotate at yaw_rate_max, go, and each leg piece in the fastest time from the speed its
/// previous primitive ends with to the one its next begins with under a_max, from rest at
/// the first waypoint to rest at the last. Where a leg piece is too short for that speed
/// change the cost is approximate; TrajectoryGenerator compares the exact times with
/// Algorithm 1's result.
class GlobalSmoothingProgramme {
 public:
  /// A choice entry for a corner without a candidate of its own (GlobalSmoothingChoice).
  static constexpr int kNoCandidate = -1;

  /// Number of corners (interior waypoints).
  std::size_t corners() const { return candidates_.size(); }
  /// The waypoints turned at (cornerWaypoints of the input).
  const std::vector<Point2>& waypoints() const { return points_; }

  /// The candidates of every corner: [i][0] is corner i's sharp turn, then its smoothings
  /// whose arcs are clear and that start and end on their legs: inner (Alg. 2 and 3), outer
  /// at the bisector boundary (Alg. 4 and 5) and at the tangent intersection boundary
  /// (Alg. 6 to 8, also from each place a previous corner's smoothing ends), and reverse
  /// curves over corners i - 1 and i, each at every radius of the smoother.
  const std::vector<std::vector<GlobalSmoothingCandidate>>& candidates() const {
    return candidates_;
  }

  /// The feasibility and objective of `choice`, summed piece by piece along the path (no
  /// dynamic programme). A choice of the wrong size, with an index out of range, or whose
  /// kNoCandidate entries and reverse curves do not pair up, is not feasible. Checks the
  /// coverage of chosen smoothings not checked before when a sensor is preserved.
  GlobalSmoothingEvaluation evaluate(const GlobalSmoothingChoice& choice);

  /// The fastest feasible choice, by dynamic programme over the corner sequence; with a
  /// preserved sensor, checking the coverage of only the smoothings it chooses and choosing
  /// again without those refused, until every chosen smoothing preserves coverage; with a
  /// safe sensor, checking the whole path's coverage after each choice and guarding or
  /// refusing the smoothings that lose area, until none does.
  GlobalSmoothingPlan plan() const;

 private:
  friend class GlobalPathSmoother;

  /// A candidate's coverage check: not yet made, passed, or refused (the smoothing sees less
  /// than the sharp corners it replaces).
  enum class CoverageVerdict { kUnchecked, kPreserves, kRefused };

  GlobalSmoothingProgramme(const GlobalPathSmoother& smoother, const std::vector<Point2>& points);

  void addCandidates(std::size_t i, const std::vector<double>& radii);
  /// The runs along the middle leg (fractions of leg i, from corner i - 1) of the bulb
  /// turns tried over corners i - 1 and i with arcs of `radius`.
  std::vector<std::pair<double, double>> bulbRuns(std::size_t i, double radius) const;
  /// The time (s) of the piece of leg `leg` from the end of `previous` to the start of
  /// `next` (nullptr: the path's start or end, at rest), or nullopt when it cannot be
  /// driven (the two overlap, or the piece is not clear).
  std::optional<double> legPiece(std::size_t leg, const GlobalSmoothingCandidate* previous,
                                 const GlobalSmoothingCandidate* next) const;
  /// Whether candidate j of corner i preserves coverage (checked once, then remembered in
  /// `verdicts`): with `path_check` (coverage-safe smoothing), the reachable area the
  /// whole sharp path sees is kept with only this corner smoothed; without, the corner's
  /// own footprints keep what its sharp turn saw (CornerCoverageCheck).
  bool preservesCoverage(std::size_t i, std::size_t j,
                         std::vector<std::vector<CoverageVerdict>>& verdicts,
                         const PathCoverageCheck* path_check) const;
  /// Checks the chosen smoothings of the `guarded` corners not checked before; marks a
  /// corner whose choice is refused in `refused_at`. True when any was refused.
  bool refuseUnpreserved(const GlobalSmoothingChoice& choice, const std::vector<bool>& guarded,
                         std::vector<std::vector<CoverageVerdict>>& verdict,
                         std::vector<bool>& refused_at, const PathCoverageCheck* path_check) const;
  /// The fastest choice whose guarded corners' smoothings preserve coverage.
  GlobalSmoothingChoice solveGuarded(const std::vector<bool>& guarded,
                                     std::vector<std::vector<CoverageVerdict>>& verdict,
                                     std::vector<bool>& refused_at, double* least,
                                     const PathCoverageCheck* path_check) const;
  /// Coverage-safe smoothing's rounds after the first choice in `plan`: the whole-path
  /// check's largest losers are guarded (or, if guarded already, their choice refused)
  /// and the programme chooses again, until the rest lose no more than it tolerates.
  void keepCoverageSafe(GlobalSmoothingPlan& plan, PathCoverageCheck& check,
                        std::vector<bool>& guarded,
                        std::vector<std::vector<CoverageVerdict>>& verdict,
                        std::vector<bool>& refused_at) const;
  /// The stretch of the sharp path (a ReplacedStretch of PathCoverageCheck) that
  /// `candidate`, a smoothing of corner i, replaces.
  std::vector<Point2> replacedStretch(std::size_t i,
                                      const GlobalSmoothingCandidate& candidate) const;
  /// The smoothing per corner of `choice`, as SmoothedPathAssembler takes them.
  std::vector<std::optional<CornerSmoothing>> smoothingsOf(
      const GlobalSmoothingChoice& choice) const;
  /// The dynamic programme over the candidates not refused in `verdict`: the fastest
  /// feasible choice, and its time in `least`.
  GlobalSmoothingChoice solve(const std::vector<std::vector<CoverageVerdict>>& verdict,
                              double* least) const;

  const GlobalPathSmoother& smoother_;
  /// Coverage-preserving smoothing's test of each corner.
  std::optional<CornerCoverageCheck> coverage_;
  std::vector<Point2> points_;
  // Legs k = P_k -> P_k+1; a leg that is clear and starts in the free area holds every
  // piece of itself, otherwise each piece is checked.
  std::vector<double> leg_length_;
  std::vector<Point2> leg_direction_;
  std::vector<bool> leg_free_;
  std::vector<std::vector<GlobalSmoothingCandidate>> candidates_;
  /// evaluate's coverage verdicts, per candidate.
  std::vector<std::vector<CoverageVerdict>> verdict_;
};

/// The global smoothing strategy (the thesis's Chapter 5 names Algorithm 1's
/// corner-by-corner decisions as a limit): every corner's smoothing, among none (an
/// in-place rotation), inner, outer at the bisector boundary, outer at the tangent
/// intersection boundary (Alg. 2 to 8) and reverse curves, each at a few radii between
/// min_turning_radius and turning_radius (and at max_turning_radius where that is wider),
/// is chosen jointly by dynamic programming over the corner sequence (GlobalSmoothingProgramme),
/// minimising the traversal time under the velocity model of GlobalSmoothingOptions.
class GlobalPathSmoother {
 public:
  /// Radii tried per corner when min_turning_radius < turning_radius, evenly spaced
  /// from turning_radius down to min_turning_radius.
  static constexpr int kRadiusLevels = 4;

  /// Collisions are checked against the raw hull and holes of `free_area` (an empty hull:
  /// the unbounded plane). Throws InvalidInputError for radii that are not positive and
  /// finite with min_turning_radius <= turning_radius, a max_turning_radius that is negative
  /// or not finite, a velocity limit that is not positive and finite, or a non-finite
  /// coordinate.
  GlobalPathSmoother(const PolygonWithHoles& free_area, const GlobalSmoothingOptions& options);

  /// The smoothed path through `waypoints`, of the same form as PathSmoother's (duplicate
  /// and straight waypoints dropped, joining segments, arcs, rotations at sharp corners):
  /// programme(waypoints).plan(), assembled.
  /// Throws InvalidInputError for a non-finite coordinate.
  SmoothedPath smooth(const std::vector<Point2>& waypoints) const;
  /// The same from poses (their positions; headings follow from the legs).
  SmoothedPath smooth(const std::vector<Pose2>& waypoints) const;

  /// The optimisation problem of `waypoints` (after cornerWaypoints), which refers to this
  /// smoother. Throws InvalidInputError for a non-finite coordinate.
  GlobalSmoothingProgramme programme(const std::vector<Point2>& waypoints) const;

 private:
  friend class GlobalSmoothingProgramme;

  PolygonWithHoles free_area_;  ///< for the coverage-safe check's reachable area
  BoundaryEdgeIndex index_;
  GlobalSmoothingOptions options_;
  std::vector<double> radii_;
};

}  // namespace kinematic_coverage::core
