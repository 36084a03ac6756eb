#!/usr/bin/env bash
# Install-space test: installs the package from a configured and built build
# directory into a temporary directory, sources that prefix's setup.bash only, runs
# `roslaunch kinematic_coverage mission.launch` (which starts its own master on a free
# port) and waits for a `trajectory` message. Exit status 0 when one arrives, non-zero
# with a message naming the failure otherwise.
#
# Usage: install_space_test.sh BUILD_DIR
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
if [[ $# -ne 1 || ! -d $1 ]]; then
  echo "usage: $0 BUILD_DIR (a configured and built build directory)" >&2
  exit 2
fi
build_dir=$(cd "$1" && pwd)
timeout_s=${KC_INSTALL_TEST_TIMEOUT_S:-60}

work=$(mktemp -d "${TMPDIR:-/tmp}/kc_install_space.XXXXXX")
launch_pid=
# Stops roslaunch with SIGINT (it then stops its nodes and master); if it has not exited
# after 30 s, kills it and the processes it started.
cleanup() {
  if [[ -n $launch_pid ]] && kill -0 "$launch_pid" 2>/dev/null; then
    local children
    children=$(pgrep -P "$launch_pid" || true)
    kill -INT "$launch_pid" 2>/dev/null || true
    for _ in $(seq 1 60); do
      kill -0 "$launch_pid" 2>/dev/null || break
      sleep 0.5
    done
    if kill -0 "$launch_pid" 2>/dev/null; then
      echo "install_space_test: roslaunch ignored SIGINT for 30 s, killing it" >&2
      # shellcheck disable=SC2086
      kill -KILL "$launch_pid" $children 2>/dev/null || true
    fi
  fi
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "install_space_test: FAILED: $*" >&2
  if [[ -f $work/roslaunch.log ]]; then
    echo "---- roslaunch output (last 40 lines)" >&2
    tail -n 40 "$work/roslaunch.log" >&2
  fi
  exit 1
}

# catkin installs its setup files to the configured CMAKE_INSTALL_PREFIX as an absolute
# path, which `cmake --install --prefix` does not redirect: stage the whole install under
# DESTDIR instead, so nothing is written outside the temporary directory. The setup files
# find their own location, so the staged install space works where it is.
install_prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build_dir/CMakeCache.txt")
[[ -n $install_prefix ]] || fail "$build_dir/CMakeCache.txt has no CMAKE_INSTALL_PREFIX"
prefix=$work/root$install_prefix
echo "== DESTDIR=$work/root cmake --install $build_dir"
DESTDIR=$work/root cmake --install "$build_dir" >"$work/install.log" 2>&1 ||
  { cat "$work/install.log" >&2; fail "cmake --install failed"; }
[[ -f $prefix/setup.bash ]] || fail "the install space has no setup.bash"

# Only the install space: the devel space of the build must not leak in (ctest's
# environment script puts it on the paths).
unset ROS_PACKAGE_PATH CMAKE_PREFIX_PATH PYTHONPATH LD_LIBRARY_PATH PKG_CONFIG_PATH \
  ROS_MASTER_URI ROSLISP_PACKAGE_DIRECTORIES
export ROS_HOSTNAME=localhost ROS_HOME=$work/ros_home ROSCONSOLE_STDOUT_LINE_BUFFERED=1
mkdir -p "$ROS_HOME"
set +u
# shellcheck source=/dev/null
source "$prefix/setup.bash"
set -u

share=$(rospack find kinematic_coverage 2>/dev/null) ||
  fail "rospack does not find kinematic_coverage in the install space"
[[ $share == "$prefix"/* ]] || fail "kinematic_coverage found at $share, not in $prefix"
for file in launch/mission.launch launch/pipeline.launch config/default.yaml \
  config/missions/lake_30x30.yaml config/rviz/pipeline.rviz; do
  [[ -f $share/$file ]] || fail "$file is not installed in $share"
done
for node in coverage_planner smooth_trajectory_generator mission_publisher; do
  [[ -x $prefix/lib/kinematic_coverage/$node ]] || fail "node $node is not installed"
done

port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://localhost:$port
echo "== roslaunch kinematic_coverage mission.launch -p $port"
# Job control on: a background job of a script would otherwise ignore SIGINT.
set -m
roslaunch -p "$port" kinematic_coverage mission.launch >"$work/roslaunch.log" 2>&1 &
launch_pid=$!
set +m

echo "== waiting up to $timeout_s s for a trajectory"
deadline=$((SECONDS + timeout_s))
until rostopic list >/dev/null 2>&1; do
  kill -0 "$launch_pid" 2>/dev/null || fail "roslaunch exited early"
  ((SECONDS < deadline)) || fail "no ROS master on port $port within $timeout_s s"
  sleep 0.5
done
remaining=$((deadline - SECONDS))
((remaining > 0)) || remaining=1
if ! timeout "$remaining" rostopic echo -n 1 /trajectory >"$work/trajectory.txt" 2>&1; then
  fail "no message on /trajectory within $timeout_s s"
fi
grep -q 'frame_id: "map"' "$work/trajectory.txt" ||
  fail "the trajectory is not in the mission's frame map"
poses=$(grep -c 'position:' "$work/trajectory.txt" || true)
((poses >= 2)) || fail "the trajectory has $poses poses"
grep -q 'process has died' "$work/roslaunch.log" && fail "a node died"
echo "install_space_test: OK: mission.launch ran from $prefix and published a trajectory of $poses poses"
