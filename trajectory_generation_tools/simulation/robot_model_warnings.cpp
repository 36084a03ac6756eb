#include "trajectory_generation_tools/simulation/robot_model_warnings.h"

#include <sstream>

namespace kinematic_coverage::core {

std::vector<std::string> robotModelWarnings(const RobotModel& model) {
  std::vector<std::string> warnings;
  const double sigma = model.disturbance.navigation_sigma;
  // Relative slack, so that a tolerance of exactly three sigmas (0.3 against 3 x 0.1 in
  // doubles) does not warn.
  constexpr double kRelativeSlack = 1e-9;
  if (sigma > 0.0 &&
      model.position_tolerance < kToleranceNavigationSigmas * sigma * (1.0 - kRelativeSlack)) {
    std::ostringstream text;
    text << "position_tolerance = " << model.position_tolerance << " m is less than "
         << kToleranceNavigationSigmas
         << " x navigation_sigma = " << kToleranceNavigationSigmas * sigma
         << " m: the robot's estimate wanders beyond the tolerance, so it "
         << (model.controller == TrackingController::kSetpoint
                 ? "slows and hunts near every pose it is handed"
                 : "hunts at the last pose before it counts as arrived");
    warnings.push_back(text.str());
  }
  return warnings;
}

}  // namespace kinematic_coverage::core
