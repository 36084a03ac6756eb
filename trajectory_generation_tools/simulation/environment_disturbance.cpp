#include "trajectory_generation_tools/simulation/environment_disturbance.h"

namespace kinematic_coverage::core {

EnvironmentDisturbance::EnvironmentDisturbance(const DisturbanceParameters& parameters,
                                               double mean_x, double mean_y)
    : parameters_(parameters),
      normal_(parameters.seed),
      mean_current_(mean_x, mean_y),
      current_x_(parameters.current_sigma, parameters.current_time_constant, normal_),
      current_y_(parameters.current_sigma, parameters.current_time_constant, normal_),
      navigation_x_(parameters.navigation_sigma, parameters.navigation_time_constant, normal_),
      navigation_y_(parameters.navigation_sigma, parameters.navigation_time_constant, normal_) {}

void EnvironmentDisturbance::advance(double duration) {
  current_x_.advance(duration, normal_);
  current_y_.advance(duration, normal_);
  navigation_x_.advance(duration, normal_);
  navigation_y_.advance(duration, normal_);
}

Point2 EnvironmentDisturbance::current() const {
  return mean_current_ + Point2(current_x_.value(), current_y_.value());
}

Point2 EnvironmentDisturbance::navigationError() const {
  return {navigation_x_.value(), navigation_y_.value()};
}

bool EnvironmentDisturbance::isLakeOf(const DisturbanceParameters& parameters, double mean_x,
                                      double mean_y) const {
  return parameters.current_sigma == parameters_.current_sigma &&
         parameters.current_time_constant == parameters_.current_time_constant &&
         parameters.navigation_sigma == parameters_.navigation_sigma &&
         parameters.navigation_time_constant == parameters_.navigation_time_constant &&
         parameters.seed == parameters_.seed && mean_x == mean_current_.x() &&
         mean_y == mean_current_.y();
}

}  // namespace kinematic_coverage::core
