#include "trajectory_generation_tools/simulation/line_of_sight_guidance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

TEST(LineOfSightGuidanceTest, TheCrossTrackErrorIsPositiveToTheLeft) {
  const Point2 from(1.0, 1.0);
  const Point2 to(3.0, 3.0);
  EXPECT_NEAR(LineOfSightGuidance::crossTrackError(from, to, {1.0, 2.0}), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(LineOfSightGuidance::crossTrackError(from, to, {2.0, 1.0}), -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(LineOfSightGuidance::crossTrackError(from, to, {5.0, 5.0}), 0.0, 1e-15);
  EXPECT_EQ(LineOfSightGuidance::crossTrackError(from, from, {5.0, 2.0}), 0.0);
}

TEST(LineOfSightGuidanceTest, TheCourseIsThePiecesDirectionLessTheArctangentOfTheError) {
  // chi_d = pi_p - atan(y_e / Delta) (Fossen 2021, Sec. 12.4), for pieces in every
  // quadrant, on both sides and on the line.
  const LineOfSightGuidance guidance(2.0);
  for (const double direction : {0.0, 0.7, 2.0, -2.5, M_PI}) {
    const Point2 from(-1.0, 0.5);
    const Point2 along(std::cos(direction), std::sin(direction));
    const Point2 left(-along.y(), along.x());
    for (const double error : {-3.0, -0.1, 0.0, 0.4, 10.0}) {
      const Point2 position = from + 1.5 * along + error * left;
      const double expected = direction - std::atan(error / 2.0);
      EXPECT_NEAR(std::remainder(guidance.course(from, from + 4.0 * along, position) - expected,
                                 2.0 * M_PI),
                  0.0, 1e-12)
          << direction << " " << error;
    }
  }
}

TEST(LineOfSightGuidanceTest, APieceOfNoLengthGivesTheBearingToItsEnd) {
  const LineOfSightGuidance guidance(1.0);
  EXPECT_NEAR(guidance.course({2.0, 2.0}, {2.0, 2.0}, {2.0, 0.0}), M_PI / 2, 1e-15);
}

TEST(LineOfSightGuidanceTest, RejectsALookAheadThatIsNotPositive) {
  for (const double lookahead : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(LineOfSightGuidance{lookahead}, InvalidInputError) << lookahead;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
