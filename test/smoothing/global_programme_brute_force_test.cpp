// The global smoothing strategy's dynamic programme (GlobalSmoothingProgramme::plan) against
// brute force: on seeded random paths of one to three corners, short legs so that
// neighbouring corners' smoothings compete for the same leg, several radii per corner and,
// in some, a hull and a hole close to a corner, every choice of one candidate per corner
// (or none, for the first corner of a reverse curve) is evaluated piece by piece
// (GlobalSmoothingProgramme::evaluate, with Alg. 1's feasibility rules), and the
// programme's time must equal the least time of the feasible choices.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "test/smoothing/smoothing_oracle.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"

namespace kinematic_coverage::core {
namespace {

constexpr double kRelativeTolerance = 1e-9;

/// A random path with its free area and velocity model.
struct Case {
  std::vector<Point2> waypoints;
  PolygonWithHoles area;
  GlobalSmoothingOptions options;
};

/// A heading change (signed, rad): any turn, a near-reversal, a near-collinear turn or a
/// turn near a right angle.
double randomTurn(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double exponent = -4.0 + 3.0 * unit(rng);  // 1e-4 to 1e-1
  double turn = 0.0;
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0:
      turn = 0.05 + (M_PI - 0.1) * unit(rng);
      break;
    case 1:
      turn = M_PI - std::pow(10.0, exponent);
      break;
    case 2:
      turn = std::pow(10.0, exponent);
      break;
    default:
      turn = M_PI / 4 + M_PI / 2 * unit(rng);
      break;
  }
  return unit(rng) < 0.5 ? turn : -turn;
}

/// A path of `corners` corners with legs of 0.2 r to 6 r; with `obstacles`, in a
/// rectangular hull a little larger than the path, with a small square hole near one corner
/// that no leg touches (when one such is found); with `sensor`, coverage-preserving.
Case randomCase(std::mt19937& rng, int corners, bool obstacles, bool sensor) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Case result;
  const double r = 0.5 + 1.5 * unit(rng);
  result.options.vehicle.turning_radius = r;
  result.options.min_turning_radius = (0.25 + 0.55 * unit(rng)) * r;
  // Slow and fast robots: the arcs' speed limit yaw_rate_max * radius is below v_max at
  // some radii and above it at others.
  result.options.vehicle.v_max = 0.3 + 1.2 * unit(rng);
  result.options.vehicle.a_max = 0.1 + 0.9 * unit(rng);
  result.options.vehicle.yaw_rate_max = 0.2 + 1.3 * unit(rng);
  if (sensor) {
    const double width = r * (1.0 + 5.0 * unit(rng));
    result.options.preserved_sensor = FrustumSensor(width, (0.3 + 0.7 * unit(rng)) * width, 0.0);
  }

  double heading = M_PI * (2.0 * unit(rng) - 1.0);
  Point2 point(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0);
  result.waypoints.push_back(point);
  double turn = 0.0;
  for (int leg = 0; leg <= corners; ++leg) {
    point += r * (0.2 + 5.8 * unit(rng)) * Point2(std::cos(heading), std::sin(heading));
    result.waypoints.push_back(point);
    // Now and then a jog (a turn back by about the last turn), where a reverse curve fits.
    turn = leg > 0 && unit(rng) < 0.3 ? -turn * (0.8 + 0.4 * unit(rng)) : randomTurn(rng);
    heading += turn;
  }
  if (!obstacles) return result;

  Point2 low = result.waypoints.front();
  Point2 high = low;
  for (const Point2& p : result.waypoints) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double margin = r * (0.3 + 2.2 * unit(rng));
  low -= Point2(margin, margin);
  high += Point2(margin, margin);
  result.area.hull = {low, {high.x(), low.y()}, high, {low.x(), high.y()}};
  for (int attempt = 0; attempt < 20; ++attempt) {
    const Point2& b = result.waypoints[1 + std::uniform_int_distribution<int>(0, corners - 1)(rng)];
    const double angle = M_PI * (2.0 * unit(rng) - 1.0);
    const Point2 centre =
        b + r * (0.2 + 1.8 * unit(rng)) * Point2(std::cos(angle), std::sin(angle));
    const double half = r * (0.05 + 0.35 * unit(rng));
    PolygonWithHoles area = result.area;
    area.holes.push_back(
        testing::rectangleHole(centre - Point2(half, half), centre + Point2(half, half)));
    const BoundaryEdgeIndex index(area);
    bool clear = true;
    for (std::size_t k = 0; k + 1 < result.waypoints.size(); ++k) {
      clear = clear && index.inside(result.waypoints[k]) &&
              index.segmentClear(result.waypoints[k], result.waypoints[k + 1]);
    }
    if (clear) {
      result.area = area;
      break;
    }
  }
  return result;
}

std::string describe(const Case& c) {
  std::ostringstream out;
  out.precision(17);
  out << "r = " << c.options.vehicle.turning_radius << ", min r = " << c.options.min_turning_radius
      << ", v_max = " << c.options.vehicle.v_max << ", a_max = " << c.options.vehicle.a_max
      << ", yaw_rate_max = " << c.options.vehicle.yaw_rate_max << ", holes " << c.area.holes.size()
      << ", waypoints";
  for (const Point2& p : c.waypoints) out << " (" << p.x() << ", " << p.y() << ")";
  return out.str();
}

std::string describe(const GlobalSmoothingChoice& choice) {
  std::string text;
  for (const int j : choice) text += " " + std::to_string(j);
  return text;
}

/// What brute force found for one path.
struct Enumeration {
  long combinations = 0;  ///< every choice tried
  long feasible = 0;      ///< those feasible
  /// Choices of a one-corner candidate at every corner, and those feasible: the others
  /// have smoothings that overlap on a leg or a blocked leg piece between them (or, with a
  /// preserved sensor, a smoothing that loses coverage).
  long own = 0;
  long own_feasible = 0;
  double least = std::numeric_limits<double>::infinity();
  GlobalSmoothingChoice fastest;
};

/// Every choice of one candidate or none per corner, evaluated.
Enumeration enumerate(GlobalSmoothingProgramme& programme) {
  const std::size_t corners = programme.corners();
  const std::vector<std::vector<GlobalSmoothingCandidate>>& candidates = programme.candidates();
  Enumeration result;
  GlobalSmoothingChoice choice(corners, GlobalSmoothingProgramme::kNoCandidate);
  while (true) {
    ++result.combinations;
    const GlobalSmoothingEvaluation evaluation = programme.evaluate(choice);
    bool own = true;
    for (std::size_t i = 0; i < corners && own; ++i) {
      own = choice[i] >= 0 && candidates[i][static_cast<std::size_t>(choice[i])].corners() == 1;
    }
    if (own) {
      ++result.own;
      if (evaluation.feasible) ++result.own_feasible;
    }
    if (evaluation.feasible) {
      ++result.feasible;
      if (evaluation.time < result.least) {
        result.least = evaluation.time;
        result.fastest = choice;
      }
    }
    // The next choice, counting from kNoCandidate to the last candidate per corner.
    std::size_t i = 0;
    while (i < corners && ++choice[i] == static_cast<int>(candidates[i].size())) {
      choice[i] = GlobalSmoothingProgramme::kNoCandidate;
      ++i;
    }
    if (i == corners) return result;
  }
}

/// Counters over all cases, for the test's non-triviality.
struct Tally {
  int cases = 0;
  int with_hole = 0;
  int several_feasible = 0;  ///< cases with more than one feasible choice
  int smoothed = 0;          ///< cases whose fastest choice smooths some corner
  int reverse_curve = 0;     ///< cases whose fastest choice has a reverse curve
  int conflicts = 0;         ///< cases where a choice of one-corner candidates is infeasible
  int obstructed = 0;        ///< cases whose hull or hole excludes some candidate
  int coverage_bound = 0;    ///< cases slower for coverage than without it
  long combinations = 0;
  long feasible = 0;
};

/// Checks the programme of `c` against brute force and counts into `tally`.
void check(const Case& c, Tally* tally) {
  SCOPED_TRACE(describe(c));
  const GlobalPathSmoother smoother(c.area, c.options);
  GlobalSmoothingProgramme programme = smoother.programme(c.waypoints);
  const std::size_t corners = programme.corners();
  ASSERT_GE(corners, 1u);

  const Enumeration brute = enumerate(programme);
  // The all-sharp choice is always feasible.
  ASSERT_GE(brute.feasible, 1);
  EXPECT_TRUE(programme.evaluate(GlobalSmoothingChoice(corners, 0)).feasible);

  const GlobalSmoothingPlan plan = programme.plan();
  ASSERT_EQ(plan.choice.size(), corners);
  const GlobalSmoothingEvaluation chosen = programme.evaluate(plan.choice);
  EXPECT_TRUE(chosen.feasible) << "choice" << describe(plan.choice);
  EXPECT_NEAR(plan.time, brute.least, kRelativeTolerance * brute.least)
      << "programme's choice" << describe(plan.choice) << ", fastest enumerated"
      << describe(brute.fastest);
  EXPECT_NEAR(chosen.time, plan.time, kRelativeTolerance * plan.time);

  ++tally->cases;
  if (!c.area.holes.empty()) ++tally->with_hole;
  if (brute.feasible > 1) ++tally->several_feasible;
  tally->combinations += brute.combinations;
  tally->feasible += brute.feasible;
  bool smoothed = false;
  bool reverse = false;
  for (std::size_t i = 0; i < corners; ++i) {
    if (plan.choice[i] < 0) continue;
    const GlobalSmoothingCandidate& candidate =
        programme.candidates()[i][static_cast<std::size_t>(plan.choice[i])];
    smoothed = smoothed || candidate.smoothing.has_value();
    reverse = reverse || candidate.corners() == 2;
  }
  if (smoothed) ++tally->smoothed;
  if (reverse) ++tally->reverse_curve;
  if (brute.own_feasible < brute.own) ++tally->conflicts;

  GlobalSmoothingOptions unconstrained = c.options;
  unconstrained.preserved_sensor.reset();
  if (!c.area.hull.empty()) {
    const GlobalPathSmoother plane_smoother({}, unconstrained);
    const GlobalSmoothingProgramme plane = plane_smoother.programme(c.waypoints);
    for (std::size_t i = 0; i < corners; ++i) {
      if (plane.candidates()[i].size() > programme.candidates()[i].size()) {
        ++tally->obstructed;
        break;
      }
    }
  }
  if (c.options.preserved_sensor &&
      plan.time > GlobalPathSmoother(c.area, unconstrained).programme(c.waypoints).plan().time) {
    ++tally->coverage_bound;
  }
}

/// `trials` seeded random cases, of one to three corners, every other triple with
/// obstacles.
Tally runCases(unsigned seed, int trials, bool sensor) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937 rng(seed);
  Tally tally;
  for (int trial = 0; trial < trials; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const int corners = 1 + trial % 3;
    const bool obstacles = (trial / 3) % 2 == 1;
    check(randomCase(rng, corners, obstacles, sensor), &tally);
    if (::testing::Test::HasFatalFailure()) break;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[   INFO   ] " << tally.cases << " cases (" << tally.with_hole << " with a hole, "
            << tally.obstructed << " with candidates excluded by the hull or hole), "
            << tally.combinations << " choices enumerated, " << tally.feasible << " feasible; "
            << tally.several_feasible << " cases with several feasible choices, " << tally.smoothed
            << " smoothed, " << tally.reverse_curve << " with a reverse curve, " << tally.conflicts
            << " with conflicting candidates, " << tally.coverage_bound << " slower for coverage; "
            << seconds << " s\n";
  return tally;
}

TEST(GlobalProgrammeBruteForce, PlanIsTheFastestFeasibleChoice) {
  const int trials = 1200;
  const Tally tally = runCases(20240611, trials, false);
  ASSERT_EQ(tally.cases, trials);
  // Not trivial: nearly every case has a real choice, most plans smooth, some with a
  // reverse curve, the hull or hole often excludes candidates, and neighbouring corners
  // often exclude each other's.
  EXPECT_GT(tally.several_feasible, trials * 9 / 10);
  EXPECT_GT(tally.smoothed, trials * 3 / 4);
  EXPECT_GT(tally.reverse_curve, trials / 100);
  EXPECT_GT(tally.obstructed, trials / 10);
  EXPECT_GT(tally.conflicts, trials / 5);
}

TEST(GlobalProgrammeBruteForce, CoveragePreservingPlanIsTheFastestPreservingChoice) {
  // evaluate counts a choice with a smoothing that loses coverage as infeasible; the
  // programme, which checks only what it chooses, still finds the fastest of the rest.
  const int trials = 90;  // each coverage check rasterizes the corner
  const Tally tally = runCases(7, trials, true);
  ASSERT_EQ(tally.cases, trials);
  EXPECT_GT(tally.several_feasible, trials / 2);
  EXPECT_GT(tally.coverage_bound, trials / 10);
}

}  // namespace
}  // namespace kinematic_coverage::core
