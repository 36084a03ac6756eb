#include "polygon_coverage_ros_bridge/gtsp/gtsplib_reader.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

GtsplibProblem parseText(const std::string& text) {
  std::istringstream in(text);
  return GtsplibReader::parse(in, "test");
}

/// Expects text to be rejected with a message containing fragment.
void expectRejected(const std::string& text, const std::string& fragment) {
  try {
    parseText(text);
    ADD_FAILURE() << "accepted; expected: " << fragment;
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

const char kSets[] =
    "GTSP_SET_SECTION\n"
    "1 1 -1\n"
    "2 2 3 -1\n"
    "EOF\n";

std::string explicitHeader(const std::string& format) {
  return "NAME : t\nTYPE : GTSP\nDIMENSION : 3\nGTSP_SETS : 2\nEDGE_WEIGHT_TYPE : EXPLICIT\n"
         "EDGE_WEIGHT_FORMAT : " +
         format + "\nEDGE_WEIGHT_SECTION\n";
}

TEST(GtsplibReader, EuclideanUsesTsplibRounding) {
  const GtsplibProblem problem = parseText(
      "NAME : e\nTYPE : GTSP\nDIMENSION : 3\nGTSP_SETS : 2\nEDGE_WEIGHT_TYPE : EUC_2D\n"
      "NODE_COORD_SECTION\n1 0 0\n2 2.5 0\n3 0 1.49\n" +
      std::string(kSets));
  const GtspInstance& instance = problem.instance;
  EXPECT_EQ(problem.name, "e");
  EXPECT_EQ(problem.type, "GTSP");
  ASSERT_EQ(instance.node_count, 3);
  EXPECT_EQ(instance.cost(0, 1), 3.0);  // nint(2.5) = 3
  EXPECT_EQ(instance.cost(0, 2), 1.0);  // nint(1.49) = 1
  EXPECT_EQ(instance.cost(1, 2), 3.0);  // nint(2.9086) = 3
  EXPECT_EQ(instance.cost(2, 0), 1.0);
  EXPECT_EQ(instance.clusters, (std::vector<std::vector<int>>{{0}, {1, 2}}));
  EXPECT_FALSE(instance.isPath());
}

TEST(GtsplibReader, FullMatrixWrappedOverLinesIsAsymmetric) {
  const GtsplibProblem problem =
      parseText(explicitHeader("FULL_MATRIX") + "9999 1 2\n3\n 9999 4 5 6\n9999\n" + kSets);
  const GtspInstance& instance = problem.instance;
  EXPECT_EQ(instance.cost(0, 1), 1.0);
  EXPECT_EQ(instance.cost(1, 0), 3.0);
  EXPECT_EQ(instance.cost(1, 2), 4.0);
  EXPECT_EQ(instance.cost(2, 1), 6.0);
  EXPECT_EQ(instance.cost(2, 2), 9999.0);
}

TEST(GtsplibReader, TriangularFormatsGiveTheSameSymmetricMatrix) {
  // d(1,2) = 4, d(1,3) = 7, d(2,3) = 9, diagonal 0.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"UPPER_ROW", "4 7\n9\n"},
      {"LOWER_ROW", "4\n7 9\n"},
      {"UPPER_DIAG_ROW", "0 4 7\n0 9\n0\n"},
      {"LOWER_DIAG_ROW", "0\n4 0\n7 9 0\n"},
      {"FULL_MATRIX", "0 4 7 4 0 9 7 9 0\n"}};
  for (const auto& [format, data] : cases) {
    const GtspInstance instance = parseText(explicitHeader(format) + data + kSets).instance;
    EXPECT_EQ(instance.costs, (std::vector<double>{0, 4, 7, 4, 0, 9, 7, 9, 0})) << format;
  }
}

TEST(GtsplibReader, ToleratesTheBenchmarkFilesTraps) {
  // Keyword without colon, trailing blanks, no blank around the colon, CRLF, no EOF.
  const GtsplibProblem problem = parseText(
      "NAME:trap \r\nTYPE  AGTSP\r\nCOMMENT : a: b\r\nDIMENSION : 3 \r\nGTSP_SETS : 2   \r\n"
      "EDGE_WEIGHT_TYPE: EXPLICIT\r\nEDGE_WEIGHT_FORMAT : FULL_MATRIX \r\nEDGE_WEIGHT_SECTION\r\n"
      "0 1\r\n2 3 0 4 5\r\n6 0 \r\nGTSP_SET_SECTION\r\n1 1 -1\r\n2 2\r\n3 -1\r\n");
  EXPECT_EQ(problem.name, "trap");
  EXPECT_EQ(problem.type, "AGTSP");
  EXPECT_EQ(problem.instance.cost(2, 1), 6.0);
  EXPECT_EQ(problem.instance.clusters[1], (std::vector<int>{1, 2}));
}

TEST(GtsplibReader, RejectsMalformedFiles) {
  const std::string euclidean =
      "TYPE : GTSP\nDIMENSION : 3\nGTSP_SETS : 2\nEDGE_WEIGHT_TYPE : EUC_2D\n"
      "NODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0 1\n";
  expectRejected("TYPE : GTSP\nGTSP_SETS : 2\nEDGE_WEIGHT_TYPE : EUC_2D\n", "DIMENSION missing");
  expectRejected("DIMENSION : three\n", "test:1: DIMENSION 'three' is not a positive integer");
  expectRejected("DIMENSION : 0\n", "not a positive integer");
  // Before the dense matrix of 8 n^2 bytes is allocated.
  expectRejected("DIMENSION : 6001\n",
                 "test:1: DIMENSION 6001 exceeds the limit of 6000 nodes (the cost matrix would "
                 "take 274 MiB)");
  // The size in the message is not computed in integers, which the largest one overflows.
  expectRejected("DIMENSION : 9223372036854775807\n",
                 "test:1: DIMENSION 9223372036854775807 exceeds the limit of 6000 nodes");
  expectRejected("TYPE : TSP\n", "test:1: TYPE 'TSP' is not GTSP or AGTSP");
  expectRejected("EDGE_WEIGHT_TYPE : GEO\n", "EDGE_WEIGHT_TYPE 'GEO' is not supported");
  expectRejected("DIMENSION : 3\nGTSP_SETS : 2\nEDGE_WEIGHT_TYPE : EUC_2D\n" + std::string(kSets),
                 "NODE_COORD_SECTION missing");
  expectRejected(euclidean, "GTSP_SET_SECTION missing");
  expectRejected(explicitHeader("FUNCTION") + "1\n" + kSets,
                 "test:7: EDGE_WEIGHT_FORMAT 'FUNCTION' is not supported");
  expectRejected(explicitHeader("FULL_MATRIX") + "0 1 2\n3 0 4\n5 6\n" + kSets,
                 "test:7: EDGE_WEIGHT_SECTION has 8 numbers, expected 9");
  expectRejected(explicitHeader("FULL_MATRIX") + "0 1 2\n3 x 4\n5 6 0\n" + kSets,
                 "test:9: 'x' is not a number");
  expectRejected(explicitHeader("UPPER_ROW") + "1 -2\n3\n" + kSets,
                 "test:8: negative edge weight -2");
  expectRejected(explicitHeader("UPPER_ROW") + "1 nan\n3\n" + kSets, "'nan' is not a number");
  expectRejected("DIMENSION : 3\nGTSP_SETS : 2\nEDGE_WEIGHT_TYPE : EUC_2D\nEDGE_WEIGHT_SECTION\n",
                 "test:4: EDGE_WEIGHT_SECTION needs EDGE_WEIGHT_TYPE EXPLICIT");
  expectRejected(
      "EDGE_WEIGHT_TYPE : EXPLICIT\nEDGE_WEIGHT_FORMAT : FULL_MATRIX\n"
      "EDGE_WEIGHT_SECTION\n0\n",
      "test:3: EDGE_WEIGHT_SECTION before DIMENSION");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 -1\n2 2 3\n", "test:11: set 2 not ended by -1");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 2 -1\n2 2 3 -1\n",
                 "test:11: node 2 is in set 1 and set 2");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 -1\n2 2 4 -1\n",
                 "test:11: node 4 of set 2 outside 1..3");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 -1\n2 2 -1\n", "node 3 is in no set");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 2 3 -1\n", "set 2 missing");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 -1\n3 2 3 -1\n",
                 "test:11: set id 3 outside 1..2");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 2 3 -1\n2 -1\n", "test:11: set 2 is empty");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1 -1\n1 2 3 -1\n", "test:11: set 1 listed twice");
  expectRejected(euclidean + "GTSP_SET_SECTION\n1 1.5 -1\n", "test:10: node 1.5 is not an integer");
  // Found by gtsplib_fuzzer: a huge GTSP_SETS made the reader allocate tens of gigabytes.
  expectRejected(
      "DIMENSION : 3\nGTSP_SETS : 2999999999\nEDGE_WEIGHT_TYPE : EUC_2D\n"
      "NODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0 1\nGTSP_SET_SECTION\n1 1 -1\n",
      "test:8: GTSP_SETS 2999999999 exceeds DIMENSION 3 (every set needs a node)");
  expectRejected(
      "DIMENSION : 3\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0\n",
      "test:3: NODE_COORD_SECTION has 8 numbers");
  expectRejected("DIMENSION : 2\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\n1 1 0\n",
                 "test:5: node 1 listed twice");
  expectRejected("DIMENSION : 2\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\n3 1 0\n",
                 "test:5: node id 3 outside 1..2");
  expectRejected("DIMENSION : 3\nFOO_SECTION\n", "test:2: unknown keyword 'FOO_SECTION'");
  expectRejected("DIMENSION : 3\n1 2 3\n", "test:2: data '1 2 3' outside a section");
  expectRejected("", "DIMENSION missing");
}

TEST(GtsplibReader, MissingFileIsInvalidInput) {
  EXPECT_THROW(GtsplibReader::readFile("/nonexistent/x.gtsp"), InvalidInputError);
}

TEST(GtsplibReader, ReadsTheBenchmarkInstances) {
  const std::string dir = std::string(KC_BENCH_DATA_DIR) + "/gtsplib/instances/";
  const GtsplibProblem ftv = GtsplibReader::readFile(dir + "asymmetric/35ftv170.gtsp");
  EXPECT_EQ(ftv.type, "AGTSP");
  EXPECT_EQ(ftv.instance.node_count, 171);
  EXPECT_EQ(ftv.instance.clusters.size(), 35u);
  const GtsplibProblem eil = GtsplibReader::readFile(dir + "symmetric/11eil51.gtsp");
  EXPECT_EQ(eil.instance.node_count, 51);
  EXPECT_EQ(eil.instance.clusters.size(), 11u);
}

}  // namespace
}  // namespace kinematic_coverage::core
