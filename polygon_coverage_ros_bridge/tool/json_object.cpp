#include "polygon_coverage_ros_bridge/tool/json_object.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"

namespace kinematic_coverage::core {
namespace {

std::string quoted(const std::string& text) {
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

}  // namespace

JsonObject::Entry& JsonObject::entry(const std::string& key) {
  for (Entry& existing : entries_) {
    if (existing.key == key) return existing;
  }
  entries_.push_back(Entry{key, 0.0, nullptr});
  return entries_.back();
}

JsonObject& JsonObject::set(const std::string& key, double value) {
  if (!std::isfinite(value)) {
    throw std::domain_error("JSON value of '" + key + "' is not finite");
  }
  Entry& target = entry(key);
  target.number = value;
  target.object.reset();
  return *this;
}

JsonObject& JsonObject::set(const std::string& key, const JsonObject& value) {
  entry(key).object = std::make_shared<const JsonObject>(value);
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
    out += quoted(e.key) + ": " + (e.object ? e.object->toString() : formatRoundTrip(e.number));
  }
  return out + "}";
}

void JsonObject::write(const std::string& path) const { writeTextFile(path, toString() + "\n"); }

}  // namespace kinematic_coverage::core
