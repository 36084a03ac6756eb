#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

#include <algorithm>
#include <clipper.hpp>
#include <cmath>
#include <sstream>
#include <string>

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

/// The mitred offset of one counter-clockwise ring by `delta` integer units: a negative one
/// shrinks it (the hull), a positive one grows it (a hole).
ClipperLib::Paths offsetRing(const ClipperLib::Path& ring, double delta) {
  ClipperLib::ClipperOffset offset(kMiterLimit);
  offset.AddPath(ring, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::PolyTree tree;
  offset.Execute(tree, delta);
  return outlines(tree);
}

/// The parts of the offset free area in `tree`, largest first; throws when it is empty.
OffsetFreeArea offsetParts(const ClipperLib::PolyTree& tree, const IntegerFrame& frame,
                           double wall_distance) {
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

}  // namespace

/// The free area's rings in integer coordinates, converted once for every distance.
struct WallOffset::Rings {
  IntegerFrame frame;
  ClipperLib::Path hull;    ///< counter-clockwise
  ClipperLib::Paths holes;  ///< each counter-clockwise: offset outward by a positive delta
};

WallOffset::WallOffset(const PolygonWithHoles& free_area)
    : rings_(std::make_unique<Rings>(Rings{IntegerFrame(free_area), {}, {}})) {
  rings_->hull = rings_->frame.toPath(free_area.hull);
  for (const Ring& hole : free_area.holes) rings_->holes.push_back(rings_->frame.toPath(hole));
}

WallOffset::~WallOffset() = default;

OffsetFreeArea WallOffset::at(double distance) const {
  if (!(distance >= 0.0 && std::isfinite(distance))) {
    throw InternalError("offset", "a negative or non-finite offset distance was asked for");
  }
  ClipperLib::PolyTree tree;
  // Beyond the hull's extent nothing is left (and the integer coordinates keep their range).
  if (distance <= rings_->frame.extent()) {
    const double delta = rings_->frame.toInteger(distance);
    try {
      ClipperLib::Clipper clipper;
      clipper.StrictlySimple(true);
      if (distance > 0.0) {
        clipper.AddPaths(offsetRing(rings_->hull, -delta), ClipperLib::ptSubject, true);
        for (const ClipperLib::Path& hole : rings_->holes) {
          clipper.AddPaths(offsetRing(hole, delta), ClipperLib::ptClip, true);
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

OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance) {
  return WallOffset(free_area).at(wall_distance);
}

}  // namespace kinematic_coverage::core
