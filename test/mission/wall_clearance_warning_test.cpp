#include "coverage_system/mission/wall_clearance_warning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace kinematic_coverage::core {
namespace {

bool mentions(const std::optional<std::string>& warning, const std::string& text) {
  return warning.has_value() && warning->find(text) != std::string::npos;
}

TEST(WallClearanceWarning, NoneWhenTheTrajectoryKeepsTheWallDistanceWithinOneMillimetre) {
  PlannerParameters parameters;
  parameters.smoothing_clearance = 0.0;
  parameters.gap_clearance = 0.5;
  EXPECT_FALSE(wallClearanceWarning(1.0, parameters).has_value());
  EXPECT_FALSE(wallClearanceWarning(0.9995, parameters).has_value());
  EXPECT_FALSE(wallClearanceWarning(INFINITY, parameters).has_value());
}

TEST(WallClearanceWarning, NamesWhatLetTheTrajectoryIntoTheWallBand) {
  PlannerParameters parameters;
  // The defaults allow nothing nearer: only the waypoints can be.
  const std::optional<std::string> waypoints = wallClearanceWarning(0.5, parameters);
  EXPECT_TRUE(mentions(waypoints,
                       "the trajectory passes 0.5 m from a wall or obstacle, nearer "
                       "than wall_distance 1 m: its waypoints come that near"))
      << waypoints.value_or("none");

  parameters.smoothing_clearance = 0.2;
  const std::optional<std::string> turns = wallClearanceWarning(0.25, parameters);
  EXPECT_TRUE(mentions(turns, "smoothing_clearance 0.2 m lets its turns into the wall band"));
  EXPECT_FALSE(mentions(turns, "gap_clearance"));

  parameters.gap_clearance = 0.6;
  const std::optional<std::string> both = wallClearanceWarning(0.25, parameters);
  EXPECT_TRUE(mentions(both, "smoothing_clearance 0.2 m lets its turns into the wall band"));
  EXPECT_TRUE(mentions(both, "; gap_clearance 0.6 m lets its transits through narrower gaps"));

  // Unsmoothed, only the gaps can.
  parameters.smoothing = false;
  const std::optional<std::string> gaps = wallClearanceWarning(0.6, parameters);
  EXPECT_TRUE(mentions(gaps, ": gap_clearance 0.6 m lets its transits through narrower gaps"));
  EXPECT_FALSE(mentions(gaps, "smoothing_clearance"));
}

}  // namespace
}  // namespace kinematic_coverage::core
