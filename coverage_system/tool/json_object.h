#pragma once

#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `text` as a JSON string: quoted, with the escapes JSON requires.
std::string jsonString(const std::string& text);

/// A JSON object for `metrics.json` (docs/REFERENCE.md, Metrics) and the GeoJSON outputs,
/// written without an external library. Keys keep their insertion order and are escaped
/// as JSON requires; numbers are written in shortest round-trip form.
class JsonObject {
 public:
  /// Sets `key` to a number, replacing an earlier value. Throws std::domain_error for a
  /// non-finite value: JSON has none, and a metric that is not finite is a bug upstream.
  JsonObject& set(const std::string& key, double value);

  /// Sets `key` to a nested object (e.g. percentiles), replacing an earlier value.
  JsonObject& set(const std::string& key, const JsonObject& value);

  /// Sets `key` to a string.
  JsonObject& set(const std::string& key, const std::string& text);

  /// Sets `key` to an array of numbers. Throws std::domain_error for a non-finite one.
  JsonObject& set(const std::string& key, const std::vector<double>& numbers);

  /// Sets `key` to `json`, a JSON value the caller has written (an array of arrays or of
  /// objects, say).
  JsonObject& setJson(const std::string& key, std::string json);

  /// True when `key` has a value.
  bool has(const std::string& key) const;

  /// The object as one line of JSON, e.g. {"cells": 7, "planning_time_s": 0.25}.
  std::string toString() const;

  /// Writes toString() and a newline to `path`; InvalidInputError when it cannot.
  void write(const std::string& path) const;

 private:
  struct Entry {
    std::string key;
    std::string json;  ///< the value as JSON text
  };
  Entry& entry(const std::string& key);

  std::vector<Entry> entries_;
};

}  // namespace kinematic_coverage::core
