#include "polygon_coverage_ros_bridge/gtsp/gtsp_command.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace kinematic_coverage::core {
namespace {

int run(const std::vector<std::string>& args, std::string* out, std::string* err) {
  std::ostringstream out_stream;
  std::ostringstream err_stream;
  const int status = runGtspCommand(args, out_stream, err_stream);
  *out = out_stream.str();
  *err = err_stream.str();
  return status;
}

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(GtspCommand, SolvesAGtsplibFileAndPrintsOneJsonLine) {
  const std::string file =
      std::string(KC_BENCH_DATA_DIR) + "/gtsplib/instances/symmetric/11eil51.gtsp";
  std::string out;
  std::string err;
  ASSERT_EQ(run({file, "--seed", "3", "--time-limit", "10"}, &out, &err), 0) << err;
  EXPECT_TRUE(err.empty());
  EXPECT_EQ(lineCount(out), 1u);
  EXPECT_EQ(out.rfind("{\"cost\": 174, \"time_s\": ", 0), 0u) << out;
  EXPECT_NE(out.find("\"time_capped\": false, "), std::string::npos) << out;
  const std::size_t tour = out.find("\"tour\": [");
  ASSERT_NE(tour, std::string::npos);
  const std::string ids = out.substr(tour + 9, out.find(']') - tour - 9);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), ','), 10);  // 11 clusters, 1-based ids
  EXPECT_EQ(ids.find(" 0,"), std::string::npos);
}

TEST(GtspCommand, InvalidInputExitsTwoWithOneLine) {
  const std::string malformed = ::testing::TempDir() + "/malformed.gtsp";
  std::ofstream(malformed) << "TYPE : GTSP\nDIMENSION : 2\nGTSP_SETS : 1\n"
                              "EDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 x 1\n";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "no instance file"},
      {{"/nonexistent.gtsp"}, "cannot open"},
      {{malformed}, "malformed.gtsp:7: 'x' is not a number"},
      {{malformed, "--seed", "-1"}, "--seed '-1'"},
      {{malformed, "--time-limit", "0"}, "--time-limit '0'"},
      {{malformed, "--time-limit"}, "needs a value"},
      {{malformed, "--bogus"}, "unknown option '--bogus'"},
      {{malformed, malformed}, "more than one instance file"}};
  for (const auto& [args, fragment] : cases) {
    std::string out;
    std::string err;
    EXPECT_EQ(run(args, &out, &err), 2) << fragment;
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(lineCount(err), 1u) << err;
    EXPECT_NE(err.find(fragment), std::string::npos) << err;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
