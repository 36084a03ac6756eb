#include "trajectory_generation_tools/simulation/driven_path_clearance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace kinematic_coverage::core {
namespace {

/// A 10 m square with a 2 m square obstacle at (4..6, 4..6).
PolygonWithHoles squareWithObstacle() {
  PolygonWithHoles area;
  area.hull = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  area.holes = {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}};
  return area;
}

/// Steps 0.1 s apart through `points`.
std::vector<SimulationStep> stepsThrough(const std::vector<Point2>& points) {
  std::vector<SimulationStep> steps;
  for (std::size_t i = 0; i < points.size(); ++i) {
    SimulationStep step;
    step.t = 0.1 * static_cast<double>(i);
    step.pose = {points[i].x(), points[i].y(), 0.0};
    steps.push_back(step);
  }
  return steps;
}

TEST(DrivenPathClearanceTest, IsTheNearestApproachOfAPathThatStaysInside) {
  const DrivenPathClearance clearance = measureDrivenPathClearance(
      stepsThrough({{1, 1}, {2, 2}, {3.5, 5}, {5, 8.5}, {9.2, 9}}), squareWithObstacle(), 0.1);
  EXPECT_FALSE(clearance.contact());
  EXPECT_NEAR(clearance.min_clearance_m, 0.5, 1e-12);  // (3.5, 5) to the obstacle
  EXPECT_EQ(clearance.obstacle_time_s, 0.0);
  EXPECT_EQ(clearance.outside_hull_time_s, 0.0);
}

TEST(DrivenPathClearanceTest, ReportsTheFirstPoseInsideAnObstacle) {
  const DrivenPathClearance clearance = measureDrivenPathClearance(
      stepsThrough({{2, 5}, {3.8, 5}, {4.2, 5}, {4.5, 5}, {3, 5}}), squareWithObstacle(), 0.1);
  ASSERT_TRUE(clearance.contact());
  EXPECT_NEAR(clearance.first_contact_t, 0.2, 1e-12);
  EXPECT_EQ(clearance.first_contact, Point2(4.2, 5));
  EXPECT_NEAR(clearance.obstacle_time_s, 0.2, 1e-12);
  EXPECT_EQ(clearance.min_clearance_m, 0.0);
}

TEST(DrivenPathClearanceTest, AStartOutsideTheHullIsNoContactButLeavingItIs) {
  // Put in the water outside the hull (from a boat), the robot drives in: no contact.
  const DrivenPathClearance from_a_boat = measureDrivenPathClearance(
      stepsThrough({{-2, 5}, {-0.5, 5}, {1, 5}, {2, 5}}), squareWithObstacle(), 0.1);
  EXPECT_FALSE(from_a_boat.contact());
  EXPECT_EQ(from_a_boat.outside_hull_time_s, 0.0);
  EXPECT_NEAR(from_a_boat.min_clearance_m, 1.0, 1e-12);
  // Once inside, leaving through the hull is a contact (a wall, where the hull is a shore).
  const DrivenPathClearance through_the_wall = measureDrivenPathClearance(
      stepsThrough({{9, 5}, {9.9, 5}, {10.1, 5}, {10.3, 5}}), squareWithObstacle(), 0.1);
  ASSERT_TRUE(through_the_wall.contact());
  EXPECT_EQ(through_the_wall.first_contact, Point2(10.1, 5));
  EXPECT_NEAR(through_the_wall.outside_hull_time_s, 0.2, 1e-12);
  EXPECT_EQ(through_the_wall.min_clearance_m, 0.0);
}

TEST(DrivenPathClearanceTest, NoPoseInsideLeavesTheClearanceInfinite) {
  const DrivenPathClearance clearance =
      measureDrivenPathClearance(stepsThrough({{-1, -1}, {-2, -2}}), squareWithObstacle(), 0.1);
  EXPECT_FALSE(clearance.contact());
  EXPECT_TRUE(std::isinf(clearance.min_clearance_m));
}

}  // namespace
}  // namespace kinematic_coverage::core
