#include "coverage_system/tool/parameters_command.h"

#include "coverage_system/parameters/parameter_schema.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

void writeMarkdown(std::ostream& out) {
  out << "| name | unit | default | valid | stage | description |\n"
         "|---|---|---|---|---|---|\n";
  for (const ParameterDeclaration& d : parameterSchema()) {
    const std::string value = parameterValueText(d, d.default_value);
    const bool is_name = !d.choices.empty() || value == (d.word ? d.word : "");
    out << "| `" << d.name << "` | " << d.unit << " | " << (is_name ? "`" + value + "`" : value)
        << " | " << validValuesText(d) << " | " << stageName(d.stage) << " | " << d.description
        << " |\n";
  }
}

}  // namespace

std::string ParametersCommand::usage() {
  return "usage: coverage_tool parameters [--markdown]\n"
         "  every parameter with its default, unit, valid values and description: as\n"
         "  config/default.yaml, or with --markdown as a table\n";
}

void ParametersCommand::run(const std::vector<std::string>& args, std::ostream& out) const {
  if (args.empty()) {
    out << defaultParametersYaml();
  } else if (args.size() == 1 && args.front() == "--markdown") {
    writeMarkdown(out);
  } else if (args.size() == 1 && (args.front() == "--help" || args.front() == "-h")) {
    out << usage();
  } else {
    throw InvalidInputError("parameters: unknown option '" + args.front() + "'\n" + usage());
  }
}

}  // namespace kinematic_coverage::core
