#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/smoothing/path_coverage_check.h"

namespace kinematic_coverage::core {

/// A smoothed path whose turns were made continuous in curvature where they could be.
struct ContinuousCurvaturePath {
  std::vector<PathPrimitive> primitives;
  int turns_clothoid = 0;      ///< arcs replaced by clothoid-arc-clothoid turns
  int kept_for_room = 0;       ///< arcs kept: a leg too short for the longer turn
  int kept_for_clearance = 0;  ///< arcs kept: the turn would come nearer an obstacle
  int kept_for_coverage = 0;   ///< arcs kept: the turn would see less than the arc
};

/// `turn_curve: clothoid` (docs/REFERENCE.md, Parameters): an arc joined to a straight
/// line has a curvature jump that no vehicle with finite yaw acceleration can follow, so
/// every arc between two straight legs becomes a ContinuousCurvatureTurn, its legs
/// shortened to make room, where that keeps the arc's guarantees: curvature at most the
/// arc's (by construction), no nearer any obstacle than what it replaces, and, with a
/// coverage check (the coverage-safe and coverage-preserving strategies), losing no more of
/// what the sharp path sees than the arc does. The other arcs (in chains of arcs: outer
/// smoothing, reverse curves, bulb turns) and every arc that fails a test are kept.
class ContinuousCurvatureTurns {
 public:
  /// Obstacles are the hull and holes of `free_area`; the clothoids change curvature by
  /// at most `curvature_rate_max` (1/m^2, > 0). Throws InvalidInputError for a rate that is
  /// not a finite number > 0.
  ContinuousCurvatureTurns(const PolygonWithHoles& free_area, double curvature_rate_max);

  /// `path` (consecutive primitives, as SmoothedPath holds them) with its turns replaced;
  /// `coverage` (may be null) guards what the sensor sees.
  ContinuousCurvaturePath apply(const std::vector<PathPrimitive>& path,
                                PathCoverageCheck* coverage) const;

 private:
  /// One arc that may become a continuous-curvature turn.
  struct Candidate;

  std::vector<Candidate> candidates(const std::vector<PathPrimitive>& path,
                                    ContinuousCurvaturePath& result) const;
  /// `path` with the turns of `candidates` that are `accepted` in place of their arcs.
  static std::vector<PathPrimitive> assembled(const std::vector<PathPrimitive>& path,
                                              const std::vector<Candidate>& candidates,
                                              const std::vector<bool>& accepted);
  /// Refuses, round by round, the turns whose stretch loses more cells than its arc's.
  void keepCoverage(const std::vector<PathPrimitive>& path,
                    const std::vector<Candidate>& candidates, std::vector<bool>& accepted,
                    PathCoverageCheck& coverage, ContinuousCurvaturePath& result) const;

  PolygonWithHoles free_area_;
  double curvature_rate_max_;
};

}  // namespace kinematic_coverage::core
