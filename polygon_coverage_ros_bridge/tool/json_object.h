#pragma once

#include <memory>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// A JSON object of numbers and nested objects, for `metrics.json` (docs/REFERENCE.md, Metrics),
/// written without an external library. Keys keep their insertion order and are escaped
/// as JSON requires; numbers are written in shortest round-trip form.
class JsonObject {
 public:
  /// Sets `key` to a number, replacing an earlier value. Throws std::domain_error for a
  /// non-finite value: JSON has none, and a metric that is not finite is a bug upstream.
  JsonObject& set(const std::string& key, double value);

  /// Sets `key` to a nested object (e.g. percentiles), replacing an earlier value.
  JsonObject& set(const std::string& key, const JsonObject& value);

  /// True when `key` has a value.
  bool has(const std::string& key) const;

  /// The object as one line of JSON, e.g. {"cells": 7, "planning_time_s": 0.25}.
  std::string toString() const;

  /// Writes toString() and a newline to `path`; InvalidInputError when it cannot.
  void write(const std::string& path) const;

 private:
  struct Entry {
    std::string key;
    double number = 0.0;
    std::shared_ptr<const JsonObject> object;  ///< set for a nested object
  };
  Entry& entry(const std::string& key);

  std::vector<Entry> entries_;
};

}  // namespace kinematic_coverage::core
