// Its own executable, so that no other test's freed memory hides or inflates the growth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "coverage_system/parameters/stage_options.h"
#include "trajectory_generation_tools/replanning/visited_history.h"

namespace kinematic_coverage::core {
namespace {

/// This process's resident memory in kB (VmRSS of /proc/self/status), or -1.
long residentKilobytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

/// Pose `i` of a robot reporting at 10 Hz while it drives 0.5 m/s lawnmower lanes 7 m apart
/// over the 30 m lake, again and again: 100 000 poses are 2.8 hours.
Pose2 lawnmowerPose(long i) {
  constexpr double kStep = 0.05;
  constexpr double kLane = 28.0;
  constexpr double kSpacing = 7.0;
  constexpr int kLanes = 4;
  const double cycle = kLanes * (kLane + kSpacing);
  const double s = std::fmod(i * kStep, cycle);
  const int lane = static_cast<int>(s / (kLane + kSpacing));
  const double along = s - lane * (kLane + kSpacing);
  const bool forward = lane % 2 == 0;
  const double y = 1.0 + lane * kSpacing;
  if (along < kLane) {
    return {forward ? 1.0 + along : 29.0 - along, y, forward ? 0.0 : M_PI};
  }
  return {forward ? 29.0 : 1.0, y + (along - kLane), M_PI / 2};
}

/// The history keeps what every replanning method needs, whichever is asked for later.
TEST(VisitedHistoryMemory, HundredThousandPosesKeepResidentMemoryFlat) {
  VisitedHistory history{sensorOf(PlannerParameters())};
  long at_1000 = 0;
  for (long i = 0; i < 100000; ++i) {
    history.add(lawnmowerPose(i));
    if (i + 1 == 1000) at_1000 = residentKilobytes();
  }
  const long at_100000 = residentKilobytes();
  std::printf(
      "VmRSS %ld kB at pose 1 000, %ld kB at pose 100 000 (%+ld kB); %zu tiles, "
      "%zu hull vertices, %zu thinned corners\n",
      at_1000, at_100000, at_100000 - at_1000, history.tileCount(), history.foldedHull().size(),
      history.foldedCorners().size());
  ASSERT_GT(at_1000, 0);
  EXPECT_LT(at_100000 - at_1000, 5 * 1024);
  EXPECT_EQ(history.count(), 100000u);
  EXPECT_LE(history.recent().size(), VisitedHistory::kRecentPoses);
}

}  // namespace
}  // namespace kinematic_coverage::core
