// Writes HardMapGenerator's maps (test/support/hard_map_generator.h) as mission files for
// `coverage_tool plan`, DIR/FAMILY_SEED.yaml (DIR is created if missing; seeds 0:19 and
// every family unless told), or, with --fuzz-corpus, as inputs of
// planner_fuzzer (fuzz/planner_fuzzer.cpp): the fuzz-sized map moved and scaled into the
// fuzzer's box, encoded in the order the fuzzer consumes its bytes, DIR/FAMILY_SEED.bin.
// --small writes the fuzz-sized maps, moved and scaled the same way, as mission files.
//
// Usage: hard_map_writer --out DIR [--families comb,spiral,...] [--seeds FIRST:LAST]
//                        [--small | --fuzz-corpus]

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "test/support/hard_map_generator.h"
#include "test/support/hard_map_yaml.h"

namespace kinematic_coverage::core::testing {
namespace {

/// planner_fuzzer's box of coordinates (m) and its parameter ranges.
constexpr double kBoxLow = -5.0;
constexpr double kBoxHigh = 35.0;

/// The bytes that make FuzzedDataProvider return given values: it takes integers from the
/// end of the input, most significant byte first, as many bytes as the range needs, and a
/// floating-point value in [low, high] as low + (high - low) * (a 64-bit integer / 2^64 - 1).
class FuzzInputEncoder {
 public:
  void integer(std::uint64_t value, std::uint64_t low, std::uint64_t high) {
    const std::uint64_t range = high - low;
    int bytes = 0;
    while (bytes < 8 && (range >> (8 * bytes)) > 0) ++bytes;
    for (int k = bytes - 1; k >= 0; --k) {
      consumed_.push_back(static_cast<std::uint8_t>(((value - low) >> (8 * k)) & 0xff));
    }
  }
  void boolean(bool value) { integer(value ? 1 : 0, 0, 255); }
  void real(double value, double low, double high) {
    const double p = std::clamp((value - low) / (high - low), 0.0, 1.0);
    const double scale = static_cast<double>(std::numeric_limits<std::uint64_t>::max());
    const std::uint64_t v = p >= 1.0 ? std::numeric_limits<std::uint64_t>::max()
                                     : static_cast<std::uint64_t>(p * scale);
    integer(v, 0, std::numeric_limits<std::uint64_t>::max());
  }
  /// The input: the consumed bytes, last consumed first.
  std::string bytes() const { return std::string(consumed_.rbegin(), consumed_.rend()); }

 private:
  std::vector<std::uint8_t> consumed_;
};

/// The map moved and scaled (with wall distance, turning radius and sensor height) so that
/// it fits planner_fuzzer's box with a margin.
HardMap intoFuzzBox(HardMap map) {
  Mission& m = map.mission;
  Point2 low = m.polygon.hull.front();
  Point2 high = low;
  for (const Point2& p : m.polygon.hull) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double extent = std::max((high - low).maxCoeff(), 1e-9);
  const double scale = std::min(1.0, 36.0 / extent);
  const Point2 centre = 0.5 * (low + high);
  const Point2 middle(0.5 * (kBoxLow + kBoxHigh), 0.5 * (kBoxLow + kBoxHigh));
  const auto move = [&](Point2& p) { p = middle + scale * (p - centre); };
  for (Point2& p : m.polygon.hull) move(p);
  for (Ring& hole : m.polygon.holes) {
    for (Point2& p : hole) move(p);
  }
  move(m.start);
  move(m.goal);
  m.parameters.wall_distance *= scale;
  m.parameters.turning_radius *= scale;
  m.parameters.sensor_distance *= scale;
  map.footprint_width_m *= scale;
  map.footprint_length_m *= scale;
  return map;
}

/// planner_fuzzer's input for the map (already in its box): its parameters (time cost,
/// frustum sensor, default speeds), raw rings without snapping, start and goal. Values
/// outside the fuzzer's ranges are clamped to them.
std::string fuzzInput(const HardMap& map) {
  const Mission& m = map.mission;
  const PlannerParameters& p = m.parameters;
  FuzzInputEncoder input;
  input.boolean(p.decomposition_type == "boustrophedon");
  input.integer(1, 0, 2);  // cost function "time"
  input.boolean(true);     // frustum sensor
  input.real(p.wall_distance, 0.0, 3.0);
  input.real(p.lateral_footprint, 1.0, 12.0);
  input.real(p.sensor_distance, 0.3, 6.0);
  input.real(p.lateral_fov, 0.5, 3.0);
  input.real(p.onward_fov, 0.1, 3.0);
  input.real(p.lateral_overlap, 0.0, 0.9);
  input.real(p.turning_radius, 0.1, 5.0);
  input.real(p.v_max, 0.1, 3.0);
  input.real(p.a_max, 0.05, 2.0);
  input.real(p.yaw_rate_max, 0.1, 2.0);
  input.integer(1, 0, 15);  // every parameter in range
  input.boolean(false);     // no snapping
  input.integer(0, 0, 7);   // raw rings
  const auto ring = [&](const Ring& r) {
    for (const Point2& v : r) {
      input.real(v.x(), kBoxLow, kBoxHigh);
      input.real(v.y(), kBoxLow, kBoxHigh);
    }
  };
  input.integer(m.polygon.hull.size(), 3, 12);
  ring(m.polygon.hull);
  input.integer(m.polygon.holes.size(), 0, 2);
  for (const Ring& hole : m.polygon.holes) {
    input.real(15.0, 0.0, 30.0);  // centre and radius, unused by raw rings
    input.real(15.0, 0.0, 30.0);
    input.real(1.0, 0.5, 6.0);
    input.integer(hole.size(), 3, 6);
    ring(hole);
  }
  input.real(m.start.x(), kBoxLow, kBoxHigh);
  input.real(m.start.y(), kBoxLow, kBoxHigh);
  input.real(m.goal.x(), kBoxLow, kBoxHigh);
  input.real(m.goal.y(), kBoxLow, kBoxHigh);
  return input.bytes();
}

[[noreturn]] void usage() {
  std::cerr << "usage: hard_map_writer --out DIR [--families comb,spiral,rooms,shoreline,"
               "touching_holes,star] [--seeds FIRST:LAST] [--small | --fuzz-corpus]\n";
  std::exit(2);
}

}  // namespace
}  // namespace kinematic_coverage::core::testing

int main(int argc, char** argv) {
  using namespace kinematic_coverage::core::testing;
  std::string out;
  std::vector<MapFamily> families = HardMapGenerator::families();
  std::uint64_t first = 0;
  std::uint64_t last = 19;
  bool small = false;
  bool fuzz = false;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--small" || flag == "--fuzz-corpus") {
      (flag == "--small" ? small : fuzz) = true;
      continue;
    }
    if (i + 1 >= argc) usage();
    const std::string value = argv[++i];
    if (flag == "--out") {
      out = value;
    } else if (flag == "--families") {
      const auto named = HardMapGenerator::fromNames(value);
      if (!named) usage();
      families = *named;
    } else if (flag == "--seeds") {
      const std::size_t colon = value.find(':');
      if (colon == std::string::npos) usage();
      first = std::stoull(value.substr(0, colon));
      last = std::stoull(value.substr(colon + 1));
      if (first > last) usage();
    } else {
      usage();
    }
  }
  if (out.empty() || (small && fuzz)) usage();
  std::filesystem::create_directories(out);
  for (MapFamily family : families) {
    if ((small || fuzz) && family == MapFamily::kStar) continue;
    const HardMapGenerator generator(family, small || fuzz ? MapSize::kFuzz : MapSize::kFull);
    for (std::uint64_t seed = first;; ++seed) {
      HardMap map = generator.generate(seed);
      if (small || fuzz) map = intoFuzzBox(map);
      char name[64];
      std::snprintf(name, sizeof(name), "%s_%04llu.%s", HardMapGenerator::name(family).c_str(),
                    static_cast<unsigned long long>(seed), fuzz ? "bin" : "yaml");
      const std::string path = out + "/" + name;
      std::ofstream file(path, std::ios::binary);
      file << (fuzz ? fuzzInput(map) : hardMapYaml(map));
      if (!file) {
        std::cerr << "hard_map_writer: cannot write " << path << "\n";
        return 2;
      }
      std::cout << path << "\n";
      if (seed == last) break;
    }
  }
  return 0;
}
