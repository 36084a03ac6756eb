#include "coverage_system/tool/json_object.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"

namespace kinematic_coverage::core {
namespace {

/// `value` in shortest round-trip form; std::domain_error naming `key` when not finite.
std::string numberJson(const std::string& key, double value) {
  if (!std::isfinite(value)) {
    throw std::domain_error("JSON value of '" + key + "' is not finite");
  }
  return formatRoundTrip(value);
}

}  // namespace

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof(escape), "\\u%04x", static_cast<unsigned char>(c));
          out += escape;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

JsonObject::Entry& JsonObject::entry(const std::string& key) {
  for (Entry& existing : entries_) {
    if (existing.key == key) return existing;
  }
  entries_.push_back(Entry{key, "0"});
  return entries_.back();
}

JsonObject& JsonObject::set(const std::string& key, double value) {
  const std::string json = numberJson(key, value);
  entry(key).json = json;
  return *this;
}

JsonObject& JsonObject::set(const std::string& key, const JsonObject& value) {
  entry(key).json = value.toString();
  return *this;
}

JsonObject& JsonObject::set(const std::string& key, const std::string& text) {
  entry(key).json = jsonString(text);
  return *this;
}

JsonObject& JsonObject::set(const std::string& key, const std::vector<double>& numbers) {
  std::string json = "[";
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    json += (i > 0 ? ", " : "") + numberJson(key, numbers[i]);
  }
  entry(key).json = json + "]";
  return *this;
}

JsonObject& JsonObject::setJson(const std::string& key, std::string json) {
  entry(key).json = std::move(json);
  return *this;
}

bool JsonObject::has(const std::string& key) const {
  for (const Entry& existing : entries_) {
    if (existing.key == key) return true;
  }
  return false;
}

std::string JsonObject::toString() const {
  std::string out = "{";
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (i > 0) out += ", ";
    out += jsonString(e.key) + ": " + e.json;
  }
  return out + "}";
}

void JsonObject::write(const std::string& path) const { writeTextFile(path, toString() + "\n"); }

}  // namespace kinematic_coverage::core
