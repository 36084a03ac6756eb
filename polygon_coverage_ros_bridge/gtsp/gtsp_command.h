#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool gtsp INSTANCE.gtsp [--seed N] [--time-limit S]` (docs/REFERENCE.md,
/// coverage_tool): args are the words after `gtsp`. Solves the GTSPLIB instance (cycle
/// mode) and prints one JSON line {"cost": ..., "time_s": ..., "tour": [...]} with the cost
/// in the instance's integer metric and the tour as 1-based node ids. Returns 0 on success,
/// 2 for invalid input (one line on err naming it), 1 for an internal error.
int runGtspCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace kinematic_coverage::core
