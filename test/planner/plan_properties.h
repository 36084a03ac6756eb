#pragma once

#include <gtest/gtest.h>

#include "coverage_system/planner/coverage_planner.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

/// Legs may leave the offset free area by this much (rounding).
constexpr double kLegTolerance = 1e-6;

/// The properties every plan must have: it starts at the start and ends at the goal,
/// every leg between first_inside and last_inside lies in the route area (the offset free
/// area's planned parts joined through their gaps), yaws are
/// the headings of the legs, the metrics add up, and the legs' swept footprints cover at
/// least 99 % of the reachable area.
void expectValidPlan(const PolygonWithHoles& free_area, const CoveragePlan& plan,
                     const PlannerParameters& parameters, const Point2& start, const Point2& goal);

}  // namespace kinematic_coverage::core
