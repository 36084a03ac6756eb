#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/smoothing/corner.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {
namespace testing {

/// Independent checks of smoothings, built on planar_geometry only (not on the module's
/// collision index): G1 continuity, curvature, legs, and clearance by dense sampling.
constexpr double kRelativeGap = 1e-9;  ///< position gap, times the corner's scale
constexpr double kHeadingGap = 1e-9;   ///< rad

/// The axis-aligned square of half side `half` around `centre`, counter-clockwise.
inline Ring squareHull(const Point2& centre, double half) {
  return {centre + Point2(-half, -half), centre + Point2(half, -half), centre + Point2(half, half),
          centre + Point2(-half, half)};
}

/// The axis-aligned rectangle from `low` to `high`, clockwise (a hole).
inline Ring rectangleHole(const Point2& low, const Point2& high) {
  return {low, {low.x(), high.y()}, high, {high.x(), low.y()}};
}

inline double cornerScale(const Corner& corner) {
  return std::max(
      {(corner.a - corner.b).norm(), (corner.c - corner.b).norm(), corner.radius, corner.b.norm()});
}

inline double headingGap(double a, double b) { return std::abs(wrapAngle(a - b)); }

inline bool allFinite(const CornerSmoothing& smoothing) {
  if (!std::isfinite(smoothing.entry_distance) || !std::isfinite(smoothing.exit_distance)) {
    return false;
  }
  for (const PathPrimitive& arc : smoothing.arcs) {
    const Pose2 start = arc.startPose();
    const Pose2 end = arc.endPose();
    if (!std::isfinite(arc.sweep()) || !std::isfinite(arc.startAngle()) ||
        !arc.centre().allFinite() || !std::isfinite(start.x + start.y + start.yaw) ||
        !std::isfinite(end.x + end.y + end.yaw)) {
      return false;
    }
  }
  return true;
}

/// Expects G1 continuity from the leg [A, B] through the arcs to the leg [B, C], arcs of
/// radius r only, starting and ending on the legs.
inline void expectG1OnLegs(const Corner& corner, const CornerSmoothing& smoothing) {
  ASSERT_FALSE(smoothing.arcs.empty());
  ASSERT_TRUE(allFinite(smoothing));
  const double gap = kRelativeGap * cornerScale(corner);
  const double heading_in = headingOf(corner.a, corner.b);
  const double heading_out = headingOf(corner.b, corner.c);
  const PathPrimitive& first = smoothing.arcs.front();
  const PathPrimitive& last = smoothing.arcs.back();
  EXPECT_LE(distanceToSegment(first.start(), corner.a, corner.b), gap);
  EXPECT_LE(headingGap(first.startPose().yaw, heading_in), kHeadingGap);
  EXPECT_LE(distanceToSegment(last.end(), corner.b, corner.c), gap);
  EXPECT_LE(headingGap(last.endPose().yaw, heading_out), kHeadingGap);
  for (std::size_t i = 0; i < smoothing.arcs.size(); ++i) {
    const PathPrimitive& arc = smoothing.arcs[i];
    EXPECT_EQ(arc.kind(), PrimitiveKind::kArc);
    EXPECT_EQ(arc.variant(), smoothing.variant);
    EXPECT_LE(arc.curvature(), (1.0 + 1e-12) / corner.radius);
    EXPECT_LT(std::abs(arc.sweep()), 2.0 * M_PI);
    if (i == 0) continue;
    const PathPrimitive& previous = smoothing.arcs[i - 1];
    EXPECT_LE((previous.end() - arc.start()).norm(), gap);
    EXPECT_LE(headingGap(previous.endPose().yaw, arc.startPose().yaw), kHeadingGap);
  }
}

/// Checks a smoothed path's continuity: every primitive starts where the previous one
/// ends, with the heading it ended with (rotations turn from the arriving heading to the
/// leaving one); the statistics match the primitives (a reverse curve: two arcs, two
/// corners).
inline void expectContinuousPath(const SmoothedPath& path, double scale) {
  const std::vector<PathPrimitive>& p = path.primitives;
  int rotations = 0;
  int arcs = 0;
  int bulb_pieces = 0;  // a bulb turn's arcs and straight run
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Pose2 start = p[i].startPose();
    const Pose2 end = p[i].endPose();
    ASSERT_TRUE(std::isfinite(start.x + start.y + start.yaw + end.x + end.y + end.yaw));
    if (p[i].kind() == PrimitiveKind::kRotation) ++rotations;
    if (p[i].variant() == SmoothingVariant::kBulb) {
      ++bulb_pieces;
    } else if (p[i].kind() == PrimitiveKind::kSegment) {
      EXPECT_EQ(p[i].variant(), SmoothingVariant::kNone);
    }
    if (p[i].kind() == PrimitiveKind::kArc && p[i].variant() != SmoothingVariant::kBulb) {
      EXPECT_NE(p[i].variant(), SmoothingVariant::kNone);
      ++arcs;
    }
    if (i == 0) continue;
    // Positions everywhere; headings too, since sharp corners turn by an explicit rotation.
    EXPECT_LE((p[i - 1].end() - p[i].start()).norm(), kRelativeGap * scale) << i;
    EXPECT_LE(headingGap(p[i - 1].endPose().yaw, start.yaw), kHeadingGap) << i;
  }
  const SmoothingStatistics& s = path.statistics;
  EXPECT_EQ(rotations, s.turns_total - s.turns_smoothed);
  EXPECT_EQ(s.turns_smoothed,
            s.inner + s.outer_bisector + s.outer_tangent + s.reverse_curve + s.bulb);
  EXPECT_EQ(s.reverse_curve % 2, 0);
  EXPECT_EQ(s.bulb % 2, 0);
  EXPECT_EQ(arcs, s.inner + 3 * (s.outer_bisector + s.outer_tangent) + s.reverse_curve);
  // Each bulb turn (two corners) has two to four arcs and at most one straight run.
  EXPECT_GE(bulb_pieces, s.bulb);
  EXPECT_LE(bulb_pieces, 5 * s.bulb / 2);
}

/// Distance between two closed segments (0 when they cross), in doubles.
inline double segmentDistance(const Point2& a, const Point2& b, const Point2& p, const Point2& q) {
  const double o1 = cross(a, b, p);
  const double o2 = cross(a, b, q);
  const double o3 = cross(p, q, a);
  const double o4 = cross(p, q, b);
  if (((o1 < 0 && o2 > 0) || (o1 > 0 && o2 < 0)) && ((o3 < 0 && o4 > 0) || (o3 > 0 && o4 < 0))) {
    return 0.0;
  }
  return std::min({distanceToSegment(a, p, q), distanceToSegment(b, p, q),
                   distanceToSegment(p, a, b), distanceToSegment(q, a, b)});
}

template <typename Visitor>
void forEachEdge(const PolygonWithHoles& area, Visitor visit) {
  auto ring_edges = [&visit](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) visit(ring[i], ring[(i + 1) % ring.size()]);
  };
  ring_edges(area.hull);
  for (const Ring& hole : area.holes) ring_edges(hole);
}

/// Smallest distance from the segment [a, b] to the boundary.
inline double segmentClearance(const PolygonWithHoles& area, const Point2& a, const Point2& b) {
  double best = std::numeric_limits<double>::infinity();
  forEachEdge(area, [&](const Point2& p, const Point2& q) {
    best = std::min(best, segmentDistance(a, b, p, q));
  });
  return best;
}

/// True when p is in the free area; an empty hull is the unbounded plane.
inline bool inFreeArea(const PolygonWithHoles& area, const Point2& p) {
  if (!area.hull.empty()) return contains(area, p);
  for (const Ring& hole : area.holes) {
    if (insideRing(p, hole)) return false;
  }
  return true;
}

/// The arc sampled every `spacing` metres (both ends included): the smallest distance of a
/// sample to the boundary, or -1 when a sample lies outside the free area. A true contact
/// puts some sample within spacing / 2 of the boundary.
inline double sampledArcClearance(const PolygonWithHoles& area, const PathPrimitive& arc,
                                  double spacing) {
  // Only edges that can come near the circle matter.
  std::vector<std::pair<Point2, Point2>> near;
  forEachEdge(area, [&](const Point2& p, const Point2& q) {
    if (distanceToSegment(arc.centre(), p, q) <= arc.radius() + spacing) near.push_back({p, q});
  });
  const int samples = std::max(2, static_cast<int>(std::ceil(arc.length() / spacing)) + 1);
  std::vector<Point2> points;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < samples; ++i) {
    points.push_back(arc.poseAt(static_cast<double>(i) / (samples - 1)).position());
    for (const auto& [e0, e1] : near)
      best = std::min(best, distanceToSegment(points.back(), e0, e1));
  }
  // Containment of every sample only where the arc comes near the boundary at all.
  const bool check_all = best <= spacing;
  for (const Point2& p : points) {
    if (!inFreeArea(area, p)) return -1.0;
    if (!check_all) break;
  }
  return best;
}

/// Independent verdict on a smoothing: definitely feasible (legs hold, sampled clearance
/// positive, segments clear, A inside), or with evidence of infeasibility (a tangent point
/// off its leg or a sampled contact).
enum class Verdict { kFree, kInfeasible, kUndecided };

inline Verdict judge(const PolygonWithHoles& area, const Corner& corner,
                     const std::optional<CornerSmoothing>& smoothing) {
  if (!smoothing) return Verdict::kInfeasible;
  const double r = corner.radius;
  const double spacing = 0.01 * r;
  const double slack = kRelativeGap * cornerScale(corner);
  const Point2 entry = smoothing->arcs.front().start();
  const Point2 exit = smoothing->arcs.back().end();
  const double along_in = (entry - corner.b).dot((corner.a - corner.b).normalized());
  const double along_out = (exit - corner.b).dot((corner.c - corner.b).normalized());
  const double length_in = (corner.a - corner.b).norm();
  const double length_out = (corner.c - corner.b).norm();
  if (along_in > length_in + slack || along_out > length_out + slack) return Verdict::kInfeasible;
  if (!inFreeArea(area, corner.a)) return Verdict::kInfeasible;
  double clearance =
      std::min(segmentClearance(area, corner.a, entry), segmentClearance(area, exit, corner.c));
  for (const PathPrimitive& arc : smoothing->arcs) {
    const double arc_clearance = sampledArcClearance(area, arc, spacing);
    if (arc_clearance < 0.0) return Verdict::kInfeasible;
    clearance = std::min(clearance, arc_clearance);
  }
  if (clearance <= 0.5 * spacing + 1e-9) {
    return clearance > 1e-9 ? Verdict::kUndecided : Verdict::kInfeasible;
  }
  return Verdict::kFree;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
