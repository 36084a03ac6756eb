#!/usr/bin/env bash
# Runs every test: installs what is missing, builds every target in Release (a target that
# does not compile fails the run), runs ctest (under a virtual display, for the GUI tests;
# it includes a smoke run of every benchmark and the check of the figures in docs/ against
# their commands, scripts/doc_figures.py check --ci), then a fuzz smoke:
# every libFuzzer target for 5 s under the sanitizers (scripts/run_fuzzers.sh, with its own
# clang build; KC_FUZZ_SMOKE=0 leaves it out). All of it took 14 min 46 s on a clean clone
# on 2 cores (2026-11-25; the packages installed already, ccache warm), about 2 min 15 s of
# it the figure check.
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
"$root/scripts/install_dependencies.sh"
echo "== build (every target: core, coverage_tool, nodes, rviz plugins, benchmarks, tests)"
mkdir -p "$build_dir"
build_log=$build_dir/build.log
if ! BUILD_DIR=$build_dir "$root/scripts/build.sh" --target all tests >"$build_log" 2>&1; then
  grep -E 'error:|Error [0-9]|undefined reference' "$build_log" | head -60
  echo "BUILD FAILED: a target does not compile or link (whole log: $build_log)"
  exit 1
fi
grep -E 'warning:' "$build_log" || true
# catkin records the devel space's Python path only once devel/lib/python3 exists, i.e.
# after the first build: configure again, or the rostests cannot import the messages.
BUILD_DIR=$build_dir "$root/scripts/build.sh" --target tests >/dev/null
echo "== test"
export ROS_HOSTNAME=localhost ROS_HOME="$build_dir/ros_home" ROSCONSOLE_STDOUT_LINE_BUFFERED=1
mkdir -p "$ROS_HOME"
cd "$build_dir"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j"${JOBS:-2}"
fuzz_smoke_seconds=5
if [ "${KC_FUZZ_SMOKE:-1}" != 0 ]; then
  echo "== fuzz smoke"
  BUILD_DIR="$build_dir-fuzz" "$root/scripts/run_fuzzers.sh" --seconds "$fuzz_smoke_seconds"
fi
