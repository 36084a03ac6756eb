#!/usr/bin/env bash
# No function of the core (every stage folder of polygon_coverage_ros_bridge/,
# trajectory_generation_tools/ and coverage_system/ but the ROS adapters in ros/) longer
# than 80 lines: clang-tidy's readability-function-size over the build's compile_commands.json.
#   scripts/check_function_size.sh BUILD_DIR
# Exit status: 0 none over, 1 a function over (named on stderr), 77 clang-tidy missing.
set -euo pipefail
export PATH=/usr/bin:/bin:$PATH
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${1:?usage: scripts/check_function_size.sh BUILD_DIR}"
tidy="$(command -v clang-tidy || command -v clang-tidy-14 || true)"
if [ -z "$tidy" ]; then
  echo "check_function_size: clang-tidy not found (scripts/install_dependencies.sh installs it)" >&2
  exit 77
fi
config='{Checks: "-*,readability-function-size", CheckOptions: [{key: readability-function-size.LineThreshold, value: 80}]}'
cd "$root"
sources=$(find polygon_coverage_ros_bridge trajectory_generation_tools coverage_system -name '*.cpp' \
  -not -path '*/ros/*' | sort)
output="$(printf '%s\n' $sources | xargs -P "${JOBS:-2}" -n 4 \
  "$tidy" -p "$build_dir" --quiet --config="$config" 2>/dev/null || true)"
# A source clang-tidy cannot compile is checked for nothing: that fails too.
if errors="$(echo "$output" | grep 'error:')"; then
  echo "$errors" >&2
  echo "check_function_size: clang-tidy could not read every source" >&2
  exit 1
fi
report="$(echo "$output" | grep 'warning:' || true)"
if [ -n "$report" ]; then
  echo "$report" >&2
  echo "check_function_size: $(echo "$report" | wc -l) functions of the core over 80 lines" >&2
  exit 1
fi
echo "check_function_size: $(echo $sources | wc -w) sources, no function over 80 lines"
