#include "polygon_coverage_ros_bridge/gtsp/gtsplib_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// Largest DIMENSION accepted: a file's explicit cost matrix is read whole before anything is
/// solved, so its size is refused before it is allocated.
constexpr long long kMaxDimension = kMaxGtspNodes;

struct NumberToken {
  double value;
  int line;
};

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const auto end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

class Parser {
 public:
  Parser(std::istream& in, std::string source) : source_(std::move(source)) {
    std::string line;
    while (std::getline(in, line)) lines_.push_back(line);
  }

  GtsplibProblem run() {
    while (current_ < lines_.size()) {
      const std::string line = trim(lines_[current_]);
      const int line_number = static_cast<int>(current_) + 1;
      ++current_;
      if (line.empty()) continue;
      const auto [key, value] = keyAndValue(line);
      if (key == "EOF") break;
      if (!std::isalpha(static_cast<unsigned char>(key[0]))) {
        fail(line_number, "data '" + line + "' outside a section");
      }
      readKeyword(key, value, line_number);
    }
    return finish();
  }

 private:
  /// "KEY: value" or "KEY value", the key in upper case.
  static std::pair<std::string, std::string> keyAndValue(const std::string& line) {
    const auto colon = line.find(':');
    if (colon != std::string::npos) {
      return {upper(trim(line.substr(0, colon))), trim(line.substr(colon + 1))};
    }
    const auto blank = line.find_first_of(" \t");
    return {upper(line.substr(0, blank)),
            blank == std::string::npos ? "" : trim(line.substr(blank))};
  }

  /// One specification keyword, or a section read from the lines after it.
  void readKeyword(const std::string& key, const std::string& value, int line_number) {
    if (key == "NAME") {
      problem_.name = value;
    } else if (key == "COMMENT" || key == "NODE_COORD_TYPE" || key == "DISPLAY_DATA_TYPE") {
    } else if (key == "TYPE") {
      problem_.type = upper(value);
      if (problem_.type != "GTSP" && problem_.type != "AGTSP") {
        fail(line_number, "TYPE '" + value + "' is not GTSP or AGTSP");
      }
    } else if (key == "DIMENSION") {
      dimension_ = positiveInteger(value, line_number, "DIMENSION");
      if (dimension_ > kMaxDimension) {
        fail(line_number,
             "DIMENSION " + value + " exceeds the limit of " + std::to_string(kMaxDimension) +
                 " nodes (the cost matrix would take " +
                 formatNumber(std::floor(8.0 * static_cast<double>(dimension_) *
                                         static_cast<double>(dimension_) / 1048576.0)) +
                 " MiB)");
      }
    } else if (key == "GTSP_SETS") {
      set_count_ = positiveInteger(value, line_number, "GTSP_SETS");
    } else if (key == "EDGE_WEIGHT_TYPE") {
      weight_type_ = upper(value);
      if (weight_type_ != "EUC_2D" && weight_type_ != "EXPLICIT") {
        fail(line_number, "EDGE_WEIGHT_TYPE '" + value + "' is not supported (EUC_2D, EXPLICIT)");
      }
    } else if (key == "EDGE_WEIGHT_FORMAT") {
      weight_format_ = upper(value);
    } else if (key == "NODE_COORD_SECTION") {
      readCoordinates(line_number);
      have_coordinates_ = true;
    } else if (key == "EDGE_WEIGHT_SECTION") {
      readWeights(line_number);
      have_weights_ = true;
    } else if (key == "GTSP_SET_SECTION") {
      readSets(line_number);
      have_sets_ = true;
    } else if (key == "DISPLAY_DATA_SECTION") {
      requireDimension(line_number, key);
      const std::vector<NumberToken> numbers = readNumbers();
      if (numbers.size() != static_cast<std::size_t>(3 * dimension_)) {
        fail(line_number, "DISPLAY_DATA_SECTION has " + std::to_string(numbers.size()) +
                              " numbers, expected 3 per node");
      }
    } else {
      fail(line_number, "unknown keyword '" + key + "'");
    }
  }

  /// The problem once every line is read: what is missing, the costs, the instance checks.
  GtsplibProblem finish() {
    if (dimension_ < 0) fail(0, "DIMENSION missing");
    if (set_count_ < 0) fail(0, "GTSP_SETS missing");
    if (weight_type_.empty()) fail(0, "EDGE_WEIGHT_TYPE missing");
    if (!have_sets_) fail(0, "GTSP_SET_SECTION missing");
    if (weight_type_ == "EUC_2D" && !have_coordinates_) fail(0, "NODE_COORD_SECTION missing");
    if (weight_type_ == "EXPLICIT" && !have_weights_) fail(0, "EDGE_WEIGHT_SECTION missing");
    if (weight_type_ == "EUC_2D") computeEuclideanCosts();
    GtspInstance& instance = problem_.instance;
    instance.node_count = static_cast<int>(dimension_);
    try {
      validateGtspInstance(instance);
    } catch (const InvalidInputError& error) {
      fail(0, error.what());
    }
    return problem_;
  }

  [[noreturn]] void fail(int line, const std::string& message) const {
    std::ostringstream text;
    text << source_;
    if (line > 0) text << ":" << line;
    text << ": " << message;
    throw InvalidInputError(text.str());
  }

  long long positiveInteger(const std::string& value, int line, const std::string& key) const {
    char* end = nullptr;
    const long long parsed = std::strtoll(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || parsed <= 0) {
      fail(line, key + " '" + value + "' is not a positive integer");
    }
    return parsed;
  }

  void requireDimension(int line, const std::string& section) const {
    if (dimension_ < 0) fail(line, section + " before DIMENSION");
  }

  /// Numbers from the current line on, up to the next line starting with a keyword.
  std::vector<NumberToken> readNumbers() {
    std::vector<NumberToken> numbers;
    while (current_ < lines_.size()) {
      const std::string line = trim(lines_[current_]);
      if (!line.empty() && std::isalpha(static_cast<unsigned char>(line[0]))) break;
      const int line_number = static_cast<int>(current_) + 1;
      ++current_;
      std::istringstream words(line);
      std::string word;
      while (words >> word) {
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        if (*end != '\0' || !std::isfinite(value)) {
          fail(line_number, "'" + word + "' is not a number");
        }
        numbers.push_back({value, line_number});
      }
    }
    return numbers;
  }

  int integerAt(const NumberToken& token, const std::string& what) const {
    if (token.value != std::floor(token.value) || std::abs(token.value) > 1e9) {
      std::ostringstream text;
      text << what << " " << token.value << " is not an integer";
      fail(token.line, text.str());
    }
    return static_cast<int>(token.value);
  }

  void readCoordinates(int line) {
    requireDimension(line, "NODE_COORD_SECTION");
    const std::vector<NumberToken> numbers = readNumbers();
    if (numbers.size() != static_cast<std::size_t>(3 * dimension_)) {
      fail(line, "NODE_COORD_SECTION has " + std::to_string(numbers.size()) +
                     " numbers, expected 3 per node (id x y) for DIMENSION " +
                     std::to_string(dimension_));
    }
    x_.assign(dimension_, 0.0);
    y_.assign(dimension_, 0.0);
    std::vector<bool> seen(dimension_, false);
    for (std::size_t k = 0; k < numbers.size(); k += 3) {
      const int id = integerAt(numbers[k], "node id");
      if (id < 1 || id > dimension_) {
        fail(numbers[k].line,
             "node id " + std::to_string(id) + " outside 1.." + std::to_string(dimension_));
      }
      if (seen[id - 1]) fail(numbers[k].line, "node " + std::to_string(id) + " listed twice");
      seen[id - 1] = true;
      x_[id - 1] = numbers[k + 1].value;
      y_[id - 1] = numbers[k + 2].value;
    }
  }

  void readWeights(int line) {
    requireDimension(line, "EDGE_WEIGHT_SECTION");
    if (weight_type_ != "EXPLICIT")
      fail(line, "EDGE_WEIGHT_SECTION needs EDGE_WEIGHT_TYPE EXPLICIT");
    const long long n = dimension_;
    long long expected = 0;
    if (weight_format_ == "FULL_MATRIX") {
      expected = n * n;
    } else if (weight_format_ == "UPPER_ROW" || weight_format_ == "LOWER_ROW") {
      expected = n * (n - 1) / 2;
    } else if (weight_format_ == "UPPER_DIAG_ROW" || weight_format_ == "LOWER_DIAG_ROW") {
      expected = n * (n + 1) / 2;
    } else if (weight_format_.empty()) {
      fail(line, "EDGE_WEIGHT_FORMAT missing before EDGE_WEIGHT_SECTION");
    } else {
      fail(line, "EDGE_WEIGHT_FORMAT '" + weight_format_ +
                     "' is not supported (FULL_MATRIX, UPPER_ROW, LOWER_ROW, UPPER_DIAG_ROW, "
                     "LOWER_DIAG_ROW)");
    }
    const std::vector<NumberToken> numbers = readNumbers();
    if (static_cast<long long>(numbers.size()) != expected) {
      fail(line, "EDGE_WEIGHT_SECTION has " + std::to_string(numbers.size()) +
                     " numbers, expected " + std::to_string(expected) + " for " + weight_format_ +
                     " with DIMENSION " + std::to_string(n));
    }
    for (const NumberToken& token : numbers) {
      if (token.value < 0.0) {
        std::ostringstream text;
        text << "negative edge weight " << token.value;
        fail(token.line, text.str());
      }
    }
    std::vector<double>& costs = problem_.instance.costs;
    costs.assign(static_cast<std::size_t>(n * n), 0.0);
    auto set = [&](long long i, long long j, double value) {
      costs[static_cast<std::size_t>(i * n + j)] = value;
      costs[static_cast<std::size_t>(j * n + i)] = value;
    };
    std::size_t k = 0;
    if (weight_format_ == "FULL_MATRIX") {
      for (long long i = 0; i < n * n; ++i) costs[static_cast<std::size_t>(i)] = numbers[k++].value;
    } else if (weight_format_ == "UPPER_ROW") {
      for (long long i = 0; i < n; ++i) {
        for (long long j = i + 1; j < n; ++j) set(i, j, numbers[k++].value);
      }
    } else if (weight_format_ == "LOWER_ROW") {
      for (long long i = 0; i < n; ++i) {
        for (long long j = 0; j < i; ++j) set(i, j, numbers[k++].value);
      }
    } else if (weight_format_ == "UPPER_DIAG_ROW") {
      for (long long i = 0; i < n; ++i) {
        for (long long j = i; j < n; ++j) set(i, j, numbers[k++].value);
      }
    } else {
      for (long long i = 0; i < n; ++i) {
        for (long long j = 0; j <= i; ++j) set(i, j, numbers[k++].value);
      }
    }
  }

  void readSets(int line) {
    requireDimension(line, "GTSP_SET_SECTION");
    if (set_count_ < 0) fail(line, "GTSP_SET_SECTION before GTSP_SETS");
    // Every set holds a node of its own; checked before the per-set tables are allocated.
    if (set_count_ > dimension_) {
      fail(line, "GTSP_SETS " + std::to_string(set_count_) + " exceeds DIMENSION " +
                     std::to_string(dimension_) + " (every set needs a node)");
    }
    const std::vector<NumberToken> numbers = readNumbers();
    std::vector<std::vector<int>>& clusters = problem_.instance.clusters;
    clusters.assign(static_cast<std::size_t>(set_count_), {});
    std::vector<bool> seen_set(static_cast<std::size_t>(set_count_), false);
    std::vector<int> set_of_node(static_cast<std::size_t>(dimension_), 0);
    std::size_t k = 0;
    while (k < numbers.size()) {
      const int id = integerAt(numbers[k], "set id");
      if (id < 1 || id > set_count_) {
        fail(numbers[k].line,
             "set id " + std::to_string(id) + " outside 1.." + std::to_string(set_count_));
      }
      if (seen_set[id - 1]) fail(numbers[k].line, "set " + std::to_string(id) + " listed twice");
      seen_set[id - 1] = true;
      ++k;
      bool closed = false;
      while (k < numbers.size()) {
        const int node = integerAt(numbers[k], "node");
        const int node_line = numbers[k].line;
        ++k;
        if (node == -1) {
          closed = true;
          break;
        }
        if (node < 1 || node > dimension_) {
          fail(node_line, "node " + std::to_string(node) + " of set " + std::to_string(id) +
                              " outside 1.." + std::to_string(dimension_));
        }
        if (set_of_node[node - 1] != 0) {
          fail(node_line, "node " + std::to_string(node) + " is in set " +
                              std::to_string(set_of_node[node - 1]) + " and set " +
                              std::to_string(id));
        }
        set_of_node[node - 1] = id;
        clusters[id - 1].push_back(node - 1);
      }
      if (!closed) fail(numbers.back().line, "set " + std::to_string(id) + " not ended by -1");
      if (clusters[id - 1].empty())
        fail(numbers[k - 1].line, "set " + std::to_string(id) + " is empty");
    }
    for (long long s = 0; s < set_count_; ++s) {
      if (!seen_set[s])
        fail(line, "set " + std::to_string(s + 1) + " missing from GTSP_SET_SECTION");
    }
    for (long long node = 0; node < dimension_; ++node) {
      if (set_of_node[node] == 0) fail(line, "node " + std::to_string(node + 1) + " is in no set");
    }
  }

  void computeEuclideanCosts() {
    const long long n = dimension_;
    std::vector<double>& costs = problem_.instance.costs;
    costs.assign(static_cast<std::size_t>(n * n), 0.0);
    for (long long i = 0; i < n; ++i) {
      for (long long j = 0; j < n; ++j) {
        // TSPLIB nint: floor(d + 0.5); the GTSPLIB optima only reproduce with it.
        const double dx = x_[i] - x_[j];
        const double dy = y_[i] - y_[j];
        const double d = std::sqrt(dx * dx + dy * dy);
        costs[static_cast<std::size_t>(i * n + j)] = std::floor(d + 0.5);
      }
    }
  }

  std::string source_;
  std::vector<std::string> lines_;
  std::size_t current_ = 0;
  GtsplibProblem problem_;
  long long dimension_ = -1;
  long long set_count_ = -1;
  std::string weight_type_;
  std::string weight_format_;
  bool have_coordinates_ = false;
  bool have_weights_ = false;
  bool have_sets_ = false;
  std::vector<double> x_;
  std::vector<double> y_;
};

}  // namespace

GtsplibProblem GtsplibReader::parse(std::istream& in, const std::string& source) {
  return Parser(in, source).run();
}

GtsplibProblem GtsplibReader::readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidInputError(path + ": cannot open GTSPLIB file");
  return parse(in, path);
}

}  // namespace kinematic_coverage::core
