#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {
namespace testing {

/// The shapes HardMapGenerator draws: real lakes and harbours that the star-shaped family
/// of random_polygons.h never makes.
enum class MapFamily {
  kComb,           ///< rectilinear comb, teeth (dead-end bays) narrower and wider than 2 w
  kSpiral,         ///< spiral corridor, a few wall distances to several footprints wide
  kRooms,          ///< two rooms joined by a corridor a little narrower or wider than 2 w
  kShoreline,      ///< noisy shore of 150 to 600 vertices with noisy islands, some close
  kTouchingHoles,  ///< holes that touch, overlap, nest or cross the hull (to be cleaned)
  kStar,           ///< today's star-shaped family (random_missions.h)
};

/// How large HardMapGenerator's maps are.
enum class MapSize {
  kFull,  ///< as each family promises (shorelines of 150 to 600 vertices, ...)
  kFuzz,  ///< within planner_fuzzer's caps: at most 12 hull vertices and 2 holes of at most 6
};

/// One generated map: a mission (raw polygon, start, goal, the parameters that vary) and
/// the figures a test checks against the family's promise.
struct HardMap {
  MapFamily family = MapFamily::kStar;
  std::uint64_t seed = 0;
  /// The polygon (hull counter-clockwise, holes clockwise), start, goal and parameters.
  Mission mission;
  double footprint_width_m = 0.0;   ///< W of the mission's sensor
  double footprint_length_m = 0.0;  ///< L of the mission's sensor
  /// kComb: every tooth's width; kRooms: the corridor's width; empty otherwise.
  std::vector<double> passage_widths_m;
  /// kShoreline: each island's distance to the nearest other ring (shore or island).
  std::vector<double> island_gaps_m;
};

/// Draws seeded hard maps of one family (std::mt19937 over the seed and the family), the
/// same map for the same seed. Every family varies the footprint (W in [1, 13] m, L in
/// [1, W] m through sensor_distance, lateral_fov and onward_fov), turning_radius in
/// [0.3, 2] m, wall_distance w in [0.3, 2] m, lateral_overlap in [0.1, 0.5] and the
/// decomposition type. Polygons pass PolygonValidator; only kTouchingHoles has holes that
/// touch, overlap or cross the hull, and PolygonCleaner cleans them without throwing. At
/// most kMaxVertices vertices in all; start and goal lie outside every hole. MapSize::kFuzz
/// draws the same shapes with fewer vertices (combs of 2 teeth, spirals of 4 or 5 legs,
/// shores of 12 vertices with up to 2 islands of 6, one group of touching holes); kStar has
/// no such size.
class HardMapGenerator {
 public:
  /// Most vertices of the hull and holes together in any generated map.
  static constexpr std::size_t kMaxVertices = 600;

  explicit HardMapGenerator(MapFamily family, MapSize size = MapSize::kFull)
      : family_(family), size_(size) {}

  /// The map of `seed`.
  HardMap generate(std::uint64_t seed) const;

  /// Across a lake chart (m).
  static constexpr double kLakeChartSize = 300.0;
  /// Fewest and most vertices of a lake chart's island.
  static constexpr std::pair<int, int> kLakeChartIslandVertices{12, 60};

  /// A lake as a chart or a GIS exports it, with default parameters: a shore of
  /// `shore_vertices` vertices about kLakeChartSize across, noisy at every scale (ten
  /// octaves of waves and a 0.2 m jitter) and warped into bays and headlands, with up to
  /// `islands` noisy islands of kLakeChartIslandVertices vertices, 2 to 8 m across, at least
  /// 1 m from the shore and from each other (a lake too crowded for them all gets fewer).
  /// Not bounded by kMaxVertices: the test bed of planning at chart scale.
  static HardMap lakeChart(std::uint64_t seed, int shore_vertices, int islands);

  /// Radius (m) of a rough shore's ring.
  static constexpr double kRoughShoreRadius = 130.0;
  /// Most that a rough shore's radius lies off kRoughShoreRadius at a vertex (m): white
  /// noise, so that the radius jumps by up to twice this from vertex to vertex.
  static constexpr double kRoughShoreNoise = 4.0;

  /// A shore rougher than lakeChart's, as a coarse survey of a rocky shore draws it: a ring of
  /// `shore_vertices` vertices kRoughShoreRadius about the origin whose radius is off by up
  /// to kRoughShoreNoise at every vertex, independently (noise that does not fall off with
  /// scale: 2 000 vertices lie 0.4 m apart, 10 000 vertices 0.08 m), with up to `islands`
  /// islands as lakeChart's. Default parameters; not bounded by kMaxVertices.
  static HardMap roughShore(std::uint64_t seed, int shore_vertices, int islands);

  /// Side (m) of an archipelago's square lake.
  static constexpr double kArchipelagoSize = 1000.0;
  /// Fewest and most vertices of an archipelago's island.
  static constexpr std::pair<int, int> kArchipelagoIslandVertices{5, 12};
  /// Smallest and largest radius (m) of an archipelago's island.
  static constexpr std::pair<double, double> kArchipelagoIslandRadius{1.5, 5.0};
  /// Least distance (m) between two islands' centres, and from a centre to the shore.
  static constexpr double kArchipelagoSpacing = 15.0;

  /// A square lake kArchipelagoSize across with up to `islands` star-shaped islands of
  /// kArchipelagoIslandVertices vertices whose radii lie in kArchipelagoIslandRadius, their
  /// centres at least kArchipelagoSpacing apart and from the shore (a lake too crowded for
  /// them all gets fewer). Default parameters: every island opens boustrophedon cells.
  static HardMap archipelago(std::uint64_t seed, int islands);

  /// Every family, in declaration order.
  static std::vector<MapFamily> families();
  /// The family's name: "comb", "spiral", "rooms", "shoreline", "touching_holes", "star".
  static std::string name(MapFamily family);
  /// The family of `name`, if any.
  static std::optional<MapFamily> fromName(const std::string& name);
  /// The families of a comma-separated list of names ("comb,spiral"), as the benchmark
  /// programs' --families option takes them; none if a name is unknown or the list empty.
  static std::optional<std::vector<MapFamily>> fromNames(const std::string& names);

 private:
  MapFamily family_;
  MapSize size_;
};

}  // namespace testing
}  // namespace kinematic_coverage::core
