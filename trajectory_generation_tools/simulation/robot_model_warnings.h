#pragma once

#include <string>
#include <vector>

#include "trajectory_generation_tools/simulation/robot_model.h"

namespace kinematic_coverage::core {

/// How many navigation-error standard deviations `position_tolerance` should span, so
/// that the robot's estimate settles within the tolerance of a pose it has reached.
inline constexpr double kToleranceNavigationSigmas = 3.0;

/// Valid robot models that will not behave as a user likely expects, one sentence each:
/// a `position_tolerance` below kToleranceNavigationSigmas times `navigation_sigma` makes
/// the controller hunt near every pose (docs/EXPERIMENTS.md measures it). Empty when
/// nothing stands out.
std::vector<std::string> robotModelWarnings(const RobotModel& model);

}  // namespace kinematic_coverage::core
