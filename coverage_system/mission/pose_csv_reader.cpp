#include "coverage_system/mission/pose_csv_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A kind is a name of lower-case letters, digits and underscores: segment, arc, rotation,
/// clothoid, or a kind added later, which a reader treats as a curve sampled densely enough.
bool isKindName(const std::string& kind) {
  return !kind.empty() && std::all_of(kind.begin(), kind.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const std::size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    fields.push_back(trim(line.substr(begin, comma - begin)));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return fields;
}

}  // namespace

PoseTable PoseCsvReader::read(const std::string& path) const {
  std::error_code code;
  if (!std::filesystem::is_regular_file(path, code)) {
    throw InvalidInputError(path + ": no such file");
  }
  const auto size = std::filesystem::file_size(path, code);
  if (!code && size > kMaxFileBytes) {
    throw InvalidInputError(path + ": " + std::to_string(size) + " bytes, more than the limit of " +
                            std::to_string(kMaxFileBytes));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InvalidInputError(path + ": cannot be read");
  return parse(text.str(), path);
}

std::vector<Pose2> PoseCsvReader::readPoses(const std::string& path) const {
  const PoseTable table = read(path);
  std::vector<Pose2> poses;
  poses.reserve(table.rows.size());
  for (const PoseRecord& row : table.rows) poses.push_back(row.pose);
  return poses;
}

PoseTable PoseCsvReader::parse(const std::string& text, const std::string& source_name) const {
  std::istringstream lines(text);
  std::string line;
  std::size_t line_number = 0;
  std::vector<std::string> header;
  std::map<std::string, std::size_t> column;
  PoseTable table;
  auto fail = [&](const std::string& problem) {
    throw InvalidInputError(source_name + ":" + std::to_string(line_number) + ": " + problem);
  };
  while (std::getline(lines, line)) {
    ++line_number;
    if (trim(line).empty()) continue;
    std::vector<std::string> fields = splitFields(line);
    if (header.empty()) {
      header = fields;
      for (std::size_t i = 0; i < header.size(); ++i) {
        if (header[i].empty()) fail("column " + std::to_string(i + 1) + " has no name");
        if (!column.emplace(header[i], i).second) {
          fail("the column '" + header[i] + "' appears twice");
        }
      }
      for (const char* required : {"x", "y", "yaw"}) {
        if (column.count(required) == 0) {
          fail(std::string("the header has no '") + required +
               "' column (x, y and yaw are required)");
        }
      }
      table.has_time = column.count("t") > 0;
      table.has_kind = column.count("kind") > 0;
      continue;
    }
    if (fields.size() != header.size()) {
      fail(std::to_string(fields.size()) + " fields, but the header has " +
           std::to_string(header.size()));
    }
    if (table.rows.size() >= kMaxRows) {
      fail("more than " + std::to_string(kMaxRows) + " rows, the limit");
    }
    auto number = [&](const char* name) {
      const std::string& field = fields[column.at(name)];
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(field.c_str(), &end);
      if (field.empty() || end != field.c_str() + field.size()) {
        fail("column " + std::string(name) + ": '" + field + "' is not a number");
      }
      if (!std::isfinite(value)) {
        fail("column " + std::string(name) + ": '" + field + "' is not finite");
      }
      return value;
    };
    PoseRecord record;
    record.pose.x = number("x");
    record.pose.y = number("y");
    record.pose.yaw = wrapAngle(number("yaw"));
    if (table.has_time) {
      record.t = number("t");
      if (!table.rows.empty() && record.t < table.rows.back().t) {
        fail("column t: " + fields[column.at("t")] + " is before the previous row's time");
      }
    }
    if (table.has_kind) {
      record.kind = fields[column.at("kind")];
      if (!isKindName(record.kind)) {
        fail("column kind: '" + record.kind +
             "' is not a kind name (segment, arc, rotation, clothoid, ...: lower-case letters, "
             "digits and underscores)");
      }
    }
    table.rows.push_back(std::move(record));
  }
  if (header.empty()) throw InvalidInputError(source_name + ": the file is empty (no header row)");
  if (table.rows.empty()) throw InvalidInputError(source_name + ": the file has no rows");
  return table;
}

}  // namespace kinematic_coverage::core
