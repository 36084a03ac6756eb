#pragma once

#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "coverage_system/parameters/planner_parameters.h"

namespace kinematic_coverage::core {

/// The stage whose options a parameter fills (docs/ARCHITECTURE.md, Parameters).
enum class ParameterStage {
  kDecomposition,
  kRoute,
  kVehicle,
  kWallOffset,
  kSensor,
  kRepair,
  kSmoothing,
  kTrajectory,
  kReplanning,
  kSimulation,
};

/// The stage's name, as tables print it ("wall offset").
const char* stageName(ParameterStage stage);

/// The numbers a parameter may take: finite, between `lower` and `upper` (each end open
/// or closed), and bounded by other parameters where named.
struct NumberRange {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_open = false;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_open = false;
  bool integer = false;
  /// The value is at most this parameter's.
  const char* upper_parameter = nullptr;
  /// The value is at least this parameter's.
  const char* lower_parameter = nullptr;
  /// 0 is also valid, standing for what `zero_means` says.
  bool zero_allowed = false;
  /// The value times this parameter's is at most `product_max`.
  const char* product_parameter = nullptr;
  double product_max = 0.0;
  /// The value divided by this parameter's is at most `quotient_max`.
  const char* quotient_parameter = nullptr;
  double quotient_max = 0.0;
  /// The range is not checked while this parameter is 0.
  const char* unchecked_while_zero = nullptr;
};

/// Where PlannerParameters holds a parameter; its type follows.
using ParameterMember = std::variant<double PlannerParameters::*, bool PlannerParameters::*,
                                     std::string PlannerParameters::*>;

/// A parameter's value as a source gives it: a number, a flag or a name (a number may be
/// given as a declared word too, such as `wall_distance`).
using ParameterValue = std::variant<double, bool, std::string>;

/// One parameter, declared once: everything else (the readers of mission files, GeoJSON
/// properties, `--set` and the nodes' parameters, the range checks and their messages,
/// config/default.yaml, the parameter tables of the reference and the README) follows from
/// it.
struct ParameterDeclaration {
  const char* name;
  ParameterMember member;
  /// "" for none.
  const char* unit;
  ParameterValue default_value;
  /// Numbers only.
  NumberRange range;
  /// Names only: the values allowed.
  std::vector<std::string> choices;
  /// Numbers only: a word that may stand for a value (`wall_distance` for a clearance, held
  /// as kClearanceOfWallDistance); nullptr for none.
  const char* word = nullptr;
  /// One line: what it is.
  const char* description = "";
  /// Where the default comes from, where it comes from somewhere (a paper, a data sheet).
  const char* source = "";
  ParameterStage stage = ParameterStage::kDecomposition;
};

/// Where each parameter's value came from ("lake.yaml:7", "--set turning_radius=2", "the
/// node's parameter ~v_max"), by name; a parameter not named kept its default.
using ParameterOrigins = std::map<std::string, std::string>;

/// Every parameter, in the order of config/default.yaml.
const std::vector<ParameterDeclaration>& parameterSchema();

/// The declaration of `name`, or nullptr.
const ParameterDeclaration* findParameter(std::string_view name);

/// The values `declaration` allows, as the reference writes them ("> 0", "(0, pi)",
/// "`arc`, `clothoid`", "[0, `turning_radius`]"); `markdown` false drops the backticks.
std::string validValuesText(const ParameterDeclaration& declaration, bool markdown = true);

/// `value` as a mission file writes it: numbers in the shortest form that reads back exactly,
/// "true"/"false", names, the word of a word-valued number.
std::string parameterValueText(const ParameterDeclaration& declaration,
                               const ParameterValue& value);

/// The value of `declaration` in `parameters`.
ParameterValue parameterValue(const PlannerParameters& parameters,
                              const ParameterDeclaration& declaration);

/// Sets `declaration` in `parameters` to `value` after checking its type and its own range
/// (not the bounds by other parameters: checkParameters does those once every value is in).
/// Throws InvalidInputError starting with `origin`, naming the parameter, the value and what
/// it must be, e.g. "lake.yaml:7: lateral_overlap = 1 is out of range: it must be in [0, 1)".
void assignParameter(PlannerParameters& parameters, const ParameterDeclaration& declaration,
                     const ParameterValue& value, const std::string& origin);

/// Checks every parameter against its declaration, the bounds by other parameters included.
/// Throws InvalidInputError for the first one out of range, starting with its origin where
/// `origins` names one.
void checkParameters(const PlannerParameters& parameters, const ParameterOrigins& origins = {});

/// config/default.yaml: every parameter with its default, unit, range and description.
std::string defaultParametersYaml();

}  // namespace kinematic_coverage::core
