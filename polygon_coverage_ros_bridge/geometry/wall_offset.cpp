#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

#include <algorithm>
#include <clipper.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The largest integer coordinate of the map's frame: 2^45, so that Clipper's products of
/// coordinates stay exact in its 128-bit arithmetic and a 300 m map is resolved to 1e-11 m
/// (a 30 km one to 1e-9 m), as fine as the doubles that the stages compute in.
constexpr double kLargestIntegerCoordinate = 35184372088832.0;

/// Integer coordinates of one free area for Clipper, whose Boolean operations and offsets
/// are exact on integers (a robust alternative to exact-kernel arithmetic that costs
/// milliseconds where the straight skeleton and exact overlays cost seconds).
class IntegerFrame {
 public:
  explicit IntegerFrame(const PolygonWithHoles& area) {
    double largest = 1.0;
    for (const Point2& p : area.hull) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    scale_ = std::exp2(std::floor(std::log2(kLargestIntegerCoordinate / largest)));
    extent_ = 2.0 * largest;
  }
  /// A length beyond which every offset of the area is empty (the hull's extent).
  double extent() const { return extent_; }
  /// The ring counter-clockwise (a hole too: it is offset on its own, outward).
  ClipperLib::Path toPath(const Ring& ring) const {
    ClipperLib::Path path;
    path.reserve(ring.size());
    for (const Point2& p : ring) {
      path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p.x() * scale_)),
                        static_cast<ClipperLib::cInt>(std::llround(p.y() * scale_)));
    }
    if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
    return path;
  }
  Ring toRing(const ClipperLib::Path& path, bool counter_clockwise) const {
    Ring ring;
    ring.reserve(path.size());
    for (const ClipperLib::IntPoint& p : path) {
      ring.emplace_back(static_cast<double>(p.X) / scale_, static_cast<double>(p.Y) / scale_);
    }
    if ((signedArea(ring) > 0.0) != counter_clockwise) std::reverse(ring.begin(), ring.end());
    return ring;
  }
  double toInteger(double length) const { return length * scale_; }

 private:
  double scale_ = 1.0;
  double extent_ = 0.0;
};

/// The outer contours of a PolyTree's top level: an offset ring's outline, with the pockets
/// that it encloses filled (they are out of reach of the robot outside).
ClipperLib::Paths outlines(const ClipperLib::PolyTree& tree) {
  ClipperLib::Paths result;
  for (const ClipperLib::PolyNode* node : tree.Childs) result.push_back(node->Contour);
  return result;
}

/// The factor by which a chord of Clipper's round joins may sag more than its arc
/// tolerance: a join's last step spans up to 1.5 steps, and the sag grows with its square.
constexpr double kLastStepSag = 2.25;

/// The offset of one counter-clockwise ring by `delta` integer units, its corners mitred or
/// round (chords sagging at most `sag` units inside their arcs, vertices on them; mitres
/// squared off beyond `miter_limit` times |delta|): a negative delta shrinks it (the hull),
/// a positive one grows it (a hole).
ClipperLib::Paths clipperOffset(const ClipperLib::Path& ring, double delta, bool round, double sag,
                                double miter_limit) {
  ClipperLib::ClipperOffset offset(miter_limit, sag / kLastStepSag);
  offset.AddPath(ring, round ? ClipperLib::jtRound : ClipperLib::jtMiter,
                 ClipperLib::etClosedPolygon);
  ClipperLib::PolyTree tree;
  offset.Execute(tree, delta);
  return outlines(tree);
}

/// The share of the distance by which a tangent cap reaches past the mitred offset's edges.
constexpr double kTangentCapMargin = 0.05;

/// Where the offset by `delta` units (signed as in clipperOffset) needs a join at a corner
/// of the counter-clockwise `ring` sharper than kTangentStep, the region between its mitre
/// and the polygon of tangents to the arc of radius |delta| around the corner, kTangentStep
/// or less apart: every point of it at least |delta| from the corner and its two edges.
ClipperLib::Paths tangentCaps(const ClipperLib::Path& ring, double delta, double miter_limit) {
  const double side = delta < 0.0 ? -1.0 : 1.0;
  const double distance = std::abs(delta);
  const auto at = [&](std::size_t i) {
    const ClipperLib::IntPoint& p = ring[i % ring.size()];
    return Point2(static_cast<double>(p.X), static_cast<double>(p.Y));
  };
  const auto toIntPoint = [](const Point2& p) {
    return ClipperLib::IntPoint(static_cast<ClipperLib::cInt>(std::llround(p.x())),
                                static_cast<ClipperLib::cInt>(std::llround(p.y())));
  };
  ClipperLib::Paths caps;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 vertex = at(i);
    const Point2 in = vertex - at(i + n - 1);
    const Point2 out = at(i + 1) - vertex;
    if (in.norm() == 0.0 || out.norm() == 0.0) continue;
    const double turn_cross = in.x() * out.y() - in.y() * out.x();
    if (side * turn_cross <= 0.0) continue;  // the offset edges meet: no join
    const double turn = std::atan2(std::abs(turn_cross), in.dot(out));
    const int tangents = static_cast<int>(std::ceil(turn / kTangentStep - 1e-9));
    if (tangents < 2) continue;
    // Offset side normals of the two edges (outward of a counter-clockwise ring when growing).
    const Point2 first = side * Point2(in.y(), -in.x()).normalized();
    const double start = std::atan2(first.y(), first.x());
    const double rotation = (turn_cross > 0.0 ? 1.0 : -1.0) * turn;
    const double half_step = 0.5 * turn / tangents;
    const double radius = distance / std::cos(half_step);
    std::vector<Point2> corners;  // between successive tangents, from the first edge's line
    for (int k = 0; k < tangents; ++k) {
      const double angle = start + rotation * (k + 0.5) / tangents;
      corners.push_back(vertex + radius * Point2(std::cos(angle), std::sin(angle)));
    }
    // Out to the mitre along lines a margin beyond the edges' offset lines (at most
    // `miter_limit` distances out): the cap reaches past the mitred offset's edges instead of
    // sharing them, which Clipper's operations resolve less reliably.
    const double margin = kTangentCapMargin * distance;
    const Point2 second = side * Point2(out.y(), -out.x()).normalized();
    const double mitre_reach =
        std::min((distance + margin) * std::tan(0.5 * turn) - distance * std::tan(half_step),
                 miter_limit * distance);
    const Point2 first_out = corners.front() + margin * first;
    const Point2 last_out = corners.back() + margin * second;
    ClipperLib::Path cap = {toIntPoint(corners.front()), toIntPoint(first_out),
                            toIntPoint(first_out + mitre_reach * in.normalized()),
                            toIntPoint(last_out - mitre_reach * out.normalized()),
                            toIntPoint(last_out)};
    for (auto it = corners.rbegin(); it != corners.rend() - 1; ++it) {
      cap.push_back(toIntPoint(*it));
    }
    if (!ClipperLib::Orientation(cap)) ClipperLib::ReversePath(cap);
    caps.push_back(std::move(cap));
  }
  return caps;
}

/// One Boolean operation of Clipper on two sets of rings, the outlines of its result.
ClipperLib::Paths combine(const ClipperLib::Paths& subject, const ClipperLib::Paths& clip,
                          ClipperLib::ClipType operation) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(subject, ClipperLib::ptSubject, true);
  clipper.AddPaths(clip, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(operation, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return outlines(tree);
}

/// The offset of one counter-clockwise ring by `delta` integer units with `corners`
/// (`unit` integer units to the metre, mitres up to `miter_limit` times |delta|): the
/// region kept (a shrunk hull, delta < 0) or taken away (a grown hole, delta > 0).
ClipperLib::Paths offsetRing(const ClipperLib::Path& ring, double delta, OffsetCorners corners,
                             double unit, double miter_limit) {
  const double tolerance = kClearanceTolerance * unit;
  if (corners == OffsetCorners::kRound) {
    return clipperOffset(ring, delta, true, kExactOffsetArcTolerance * unit, miter_limit);
  }
  if (corners == OffsetCorners::kRoundClear) {
    // Arcs of the distance plus the sag, so that their chords keep the distance.
    const double sag = kRoundClearArcTolerance * unit;
    return clipperOffset(ring, delta < 0.0 ? delta - sag : delta + sag, true, sag, miter_limit);
  }
  const ClipperLib::Paths mitred = clipperOffset(ring, delta, false, tolerance, miter_limit);
  if (corners == OffsetCorners::kMitred || std::abs(delta) <= tolerance) return mitred;
  const ClipperLib::Paths caps = tangentCaps(ring, delta, miter_limit);
  if (caps.empty()) return mitred;
  // The caps are clear of their corner and its edges, not always of the ring's other edges:
  // a round offset half a tolerance short of the distance (its chords sagging at most the
  // other half) takes back what the caps would give that lies nearer the ring than that.
  const double short_delta = delta < 0.0 ? delta + 0.5 * tolerance : delta - 0.5 * tolerance;
  const ClipperLib::Paths round =
      clipperOffset(ring, short_delta, true, 0.5 * tolerance, miter_limit);
  if (delta < 0.0) {
    return combine(mitred, combine(caps, round, ClipperLib::ctIntersection), ClipperLib::ctUnion);
  }
  return combine(combine(mitred, caps, ClipperLib::ctDifference), round, ClipperLib::ctUnion);
}

/// The polygons of a PolyTree of Boolean results (counter-clockwise hulls, clockwise holes),
/// those of positive area.
std::vector<PolygonWithHoles> polygonsOf(const ClipperLib::PolyTree& tree,
                                         const IntegerFrame& frame) {
  std::vector<PolygonWithHoles> parts;
  for (const ClipperLib::PolyNode* node = tree.GetFirst(); node != nullptr;
       node = node->GetNext()) {
    if (node->IsHole()) continue;
    PolygonWithHoles part;
    part.hull = frame.toRing(node->Contour, true);
    for (const ClipperLib::PolyNode* hole : node->Childs) {
      part.holes.push_back(frame.toRing(hole->Contour, false));
    }
    if (area(part) > 0.0) parts.push_back(std::move(part));
  }
  return parts;
}

/// The parts of the offset free area in `tree`, largest first; throws when it is empty.
OffsetFreeArea offsetParts(const ClipperLib::PolyTree& tree, const IntegerFrame& frame,
                           double wall_distance) {
  std::vector<PolygonWithHoles> parts = polygonsOf(tree, frame);
  if (parts.empty()) {
    std::ostringstream message;
    message << "the offset free area is empty: wall_distance " << wall_distance
            << " m leaves no point far enough from the hull and the holes";
    throw InvalidInputError(message.str());
  }
  std::stable_sort(
      parts.begin(), parts.end(),
      [](const PolygonWithHoles& a, const PolygonWithHoles& b) { return area(a) > area(b); });
  OffsetFreeArea result;
  result.parts = std::move(parts);
  return result;
}

/// The part of `ring` within the box [low, high] (Sutherland-Hodgman, side by side): a closed
/// path whose winding number at every point strictly inside the box is the ring's (it may run
/// back and forth along the box's sides, which Clipper's non-zero rule resolves). Empty when
/// no part of the ring is in the box.
Ring clippedToBox(const Ring& ring, const Point2& low, const Point2& high) {
  Ring current = ring;
  for (int side = 0; side < 4 && !current.empty(); ++side) {
    const int axis = side % 2;
    const bool lower = side < 2;
    const double bound = lower ? low[axis] : high[axis];
    auto inside = [&](const Point2& p) { return lower ? p[axis] >= bound : p[axis] <= bound; };
    Ring next;
    for (std::size_t i = 0, n = current.size(); i < n; ++i) {
      const Point2& from = current[(i + n - 1) % n];
      const Point2& to = current[i];
      if (inside(to) != inside(from)) {
        const double t = (bound - from[axis]) / (to[axis] - from[axis]);
        Point2 crossing = from + t * (to - from);
        crossing[axis] = bound;
        next.push_back(crossing);
      }
      if (inside(to)) next.push_back(to);
    }
    current = std::move(next);
  }
  return current;
}

/// The share of a clipping box's larger side by which clippedToBox's box exceeds it, so that
/// the paths' runs along its sides lie outside the box Clipper clips to.
constexpr double kPreClipMarginShare = 0.01;

}  // namespace

/// The free area's rings in integer coordinates, converted once for every distance.
struct WallOffset::Rings {
  IntegerFrame frame;
  ClipperLib::Path hull;    ///< counter-clockwise
  ClipperLib::Paths holes;  ///< each counter-clockwise: offset outward by a positive delta
};

WallOffset::WallOffset(const PolygonWithHoles& free_area, double miter_limit)
    : rings_(std::make_unique<Rings>(Rings{IntegerFrame(free_area), {}, {}})),
      miter_limit_(miter_limit) {
  if (!(miter_limit >= kMinMiterLimit && miter_limit <= kMaxMiterLimit)) {
    throw InternalError("offset", "a mitre limit outside [2, 1000] wall distances was asked for");
  }
  rings_->hull = rings_->frame.toPath(free_area.hull);
  for (const Ring& hole : free_area.holes) rings_->holes.push_back(rings_->frame.toPath(hole));
}

WallOffset::~WallOffset() = default;

OffsetFreeArea WallOffset::at(double distance, OffsetCorners corners) const {
  if (!(distance >= 0.0 && std::isfinite(distance))) {
    throw InternalError("offset", "a negative or non-finite offset distance was asked for");
  }
  ClipperLib::PolyTree tree;
  // Beyond the hull's extent nothing is left (and the integer coordinates keep their range).
  if (distance <= rings_->frame.extent()) {
    const double delta = rings_->frame.toInteger(distance);
    const double unit = rings_->frame.toInteger(1.0);
    try {
      ClipperLib::Clipper clipper;
      clipper.StrictlySimple(true);
      if (distance > 0.0) {
        clipper.AddPaths(offsetRing(rings_->hull, -delta, corners, unit, miter_limit_),
                         ClipperLib::ptSubject, true);
        for (const ClipperLib::Path& hole : rings_->holes) {
          clipper.AddPaths(offsetRing(hole, delta, corners, unit, miter_limit_), ClipperLib::ptClip,
                           true);
        }
      } else {
        clipper.AddPath(rings_->hull, ClipperLib::ptSubject, true);
        clipper.AddPaths(rings_->holes, ClipperLib::ptClip, true);
      }
      clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero,
                      ClipperLib::pftNonZero);
    } catch (const ClipperLib::clipperException& error) {
      throw InternalError("offset", std::string("Clipper: ") + error.what());
    }
  }
  return offsetParts(tree, rings_->frame, distance);
}

std::vector<PolygonWithHoles> clipToBox(const PolygonWithHoles& area, const Point2& low,
                                        const Point2& high) {
  const IntegerFrame frame(area);
  // Both corners within the frame's range: the box beyond the hull adds nothing.
  const Eigen::AlignedBox2d hull_box = boundingBox(area.hull);
  const Point2 from = low.cwiseMax(hull_box.min());
  const Point2 to = high.cwiseMin(hull_box.max());
  if ((from.array() >= to.array()).any()) return {};
  // The rings cut down to a slightly larger box first: Clipper's sweep then meets only the
  // edges near the box, not every edge of a long shore.
  const Point2 margin = Point2::Constant(kPreClipMarginShare * (to - from).maxCoeff());
  auto nearBox = [&](const Ring& ring) { return clippedToBox(ring, from - margin, to + margin); };
  ClipperLib::PolyTree tree;
  try {
    ClipperLib::Clipper clipper;
    clipper.StrictlySimple(true);
    const Ring hull = nearBox(area.hull);
    if (hull.size() < 3) return {};
    clipper.AddPath(frame.toPath(hull), ClipperLib::ptSubject, true);
    for (const Ring& hole : area.holes) {
      const Ring near = nearBox(hole);
      if (near.size() < 3) continue;
      // Counter-clockwise as the hull, then turned round: taken away (non-zero rule).
      ClipperLib::Path path = frame.toPath(near);
      ClipperLib::ReversePath(path);
      clipper.AddPath(path, ClipperLib::ptSubject, true);
    }
    clipper.AddPath(frame.toPath({from, {to.x(), from.y()}, to, {from.x(), to.y()}}),
                    ClipperLib::ptClip, true);
    clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
  } catch (const ClipperLib::clipperException& error) {
    throw InternalError("offset", std::string("Clipper: ") + error.what());
  }
  return polygonsOf(tree, frame);
}

OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance,
                                     double miter_limit) {
  return WallOffset(free_area, miter_limit).at(wall_distance);
}

std::vector<PolygonWithHoles> exactOffsetParts(const PolygonWithHoles& free_area,
                                               double wall_distance,
                                               const std::vector<PolygonWithHoles>& offset_parts) {
  if (wall_distance == 0.0 || offset_parts.empty()) return offset_parts;
  return roundPartsHolding(WallOffset(free_area).at(wall_distance, OffsetCorners::kRound).parts,
                           offset_parts);
}

std::vector<PolygonWithHoles> roundPartsHolding(std::vector<PolygonWithHoles> round,
                                                const std::vector<PolygonWithHoles>& offset_parts) {
  // A mitred part's vertices lie inside or on its round part; a vertex where two round parts
  // touch lies on both, so each mitred part goes to the round part holding most of them.
  std::vector<bool> holds(round.size(), false);
  std::vector<PolygonWithHoles> exact;
  for (const PolygonWithHoles& part : offset_parts) {
    std::size_t best = round.size();
    std::size_t best_count = 0;
    for (std::size_t k = 0; k < round.size(); ++k) {
      std::size_t count = 0;
      const std::size_t step = std::max<std::size_t>(1, part.hull.size() / 8);
      for (std::size_t i = 0; i < part.hull.size(); i += step) {
        count += contains(round[k], part.hull[i], kRoundOffsetReach) ? 1 : 0;
      }
      if (count > best_count) {
        best_count = count;
        best = k;
      }
    }
    if (best < round.size()) {
      holds[best] = true;
    } else {
      exact.push_back(part);  // a sliver that rounding left out of every round part
    }
  }
  for (std::size_t k = 0; k < round.size(); ++k) {
    if (holds[k]) exact.push_back(std::move(round[k]));
  }
  return exact;
}

}  // namespace kinematic_coverage::core
