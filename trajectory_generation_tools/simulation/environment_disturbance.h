#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/simulation/disturbance_parameters.h"
#include "trajectory_generation_tools/simulation/gauss_markov_process.h"
#include "trajectory_generation_tools/simulation/standard_normal_source.h"

namespace kinematic_coverage::core {

/// The disturbances a simulated robot meets in the lake, as time goes on: the water
/// current (a constant mean plus a fluctuation) and the error of its navigation solution,
/// each axis a GaussMarkovProcess drawn from one seeded source. With both standard
/// deviations 0 the current is the mean and the error 0 at every instant.
class EnvironmentDisturbance {
 public:
  /// Disturbances of `parameters` about the mean current (mean_x, mean_y) m/s.
  EnvironmentDisturbance(const DisturbanceParameters& parameters, double mean_x, double mean_y);

  /// Moves every process on by `duration` s.
  void advance(double duration);

  /// m/s: the water's velocity now.
  Point2 current() const;

  /// m: what the navigation solution adds to the true position now.
  Point2 navigationError() const;

  /// Whether this is the lake of `parameters` about the mean current (mean_x, mean_y):
  /// a robot handed a new trajectory in the same lake meets these disturbances on, not
  /// the seed's first draws again.
  bool isLakeOf(const DisturbanceParameters& parameters, double mean_x, double mean_y) const;

 private:
  DisturbanceParameters parameters_;
  StandardNormalSource normal_;
  Point2 mean_current_;
  GaussMarkovProcess current_x_;
  GaussMarkovProcess current_y_;
  GaussMarkovProcess navigation_x_;
  GaussMarkovProcess navigation_y_;
};

}  // namespace kinematic_coverage::core
