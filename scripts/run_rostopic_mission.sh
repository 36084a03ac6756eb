#!/usr/bin/env bash
# The lake mission (config/missions/lake_30x30.yaml) driven by hand with `rostopic pub`,
# as the thesis's users drove the planner: polygon, start and goal, then `activate`;
# prints the planner's `~status` and the smoother's `~status`.
#
# Needs a running pipeline without its own mission publisher, e.g.
#   roslaunch kinematic_coverage pipeline.launch publish_mission:=false rviz:=false
# Topic names are relative, so ROS_NAMESPACE selects a namespaced pipeline.
# Environment: KC_SETUP (default build/devel/setup.bash of this repository; an install
# space's setup.bash works too; when it is missing, an environment that already finds
# kinematic_coverage is used as it is), ROS_MASTER_URI (default http://localhost:11311),
# KC_STATUS_TIMEOUT_S (default 120).
set -euo pipefail
export PATH=/usr/bin:/bin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
setup=${KC_SETUP:-$root/build/devel/setup.bash}
if [[ -f $setup ]]; then
  # setup.bash reads unset variables.
  set +u
  # shellcheck source=/dev/null
  source "$setup"
  set -u
elif [[ -n ${KC_SETUP:-} ]] || ! rospack find kinematic_coverage >/dev/null 2>&1; then
  echo "run_rostopic_mission.sh: $setup not found: build the package or set KC_SETUP" >&2
  exit 1
fi
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}
timeout_s=${KC_STATUS_TIMEOUT_S:-120}
# The planner's private topics, relative to the caller's namespace.
planner_status=coverage_planner/status
smoother_status=smooth_trajectory_generator/status

if ! rostopic list >/dev/null 2>&1; then
  echo "run_rostopic_mission.sh: no ROS master at ${ROS_MASTER_URI:-http://localhost:11311}" >&2
  exit 1
fi

tmp=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$tmp"' EXIT

# Listen before publishing: ~status is not latched.
timeout "$timeout_s" rostopic echo -n 1 "$planner_status" >"$tmp/planner_status" &
planner_listener=$!
timeout "$timeout_s" rostopic echo -n 1 "$smoother_status" >"$tmp/smoother_status" &
smoother_listener=$!
sleep 2

echo "== polygon: 30 m x 30 m lake with two obstacles"
rostopic pub -1 polygon kinematic_coverage/PolygonWithHolesStamped '{header: {frame_id: map},
  polygon: {
    hull: {points: [{x: 0, y: 0}, {x: 30, y: 0}, {x: 30, y: 30}, {x: 0, y: 30}]},
    holes: [
      {points: [{x: 7, y: 9}, {x: 12, y: 9}, {x: 12, y: 15}, {x: 7, y: 15}]},
      {points: [{x: 18, y: 17}, {x: 23, y: 18}, {x: 24, y: 23}, {x: 19, y: 25}, {x: 16, y: 21}]}]}}'
echo "== start (1, 1), goal (29, 29)"
rostopic pub -1 -s start geometry_msgs/PointStamped '{header: {stamp: now, frame_id: map}, point: {x: 1, y: 1}}'
rostopic pub -1 -s goal geometry_msgs/PointStamped '{header: {stamp: now, frame_id: map}, point: {x: 29, y: 29}}'
echo "== activate"
rostopic pub -1 activate std_msgs/Empty '{}'

echo "== waiting for $planner_status"
if ! wait "$planner_listener"; then
  echo "run_rostopic_mission.sh: no $planner_status within $timeout_s s" >&2
  exit 1
fi
cat "$tmp/planner_status"
if ! grep -q '^success: True' "$tmp/planner_status"; then
  echo "run_rostopic_mission.sh: planning failed" >&2
  exit 1
fi
echo "== waiting for $smoother_status"
if ! wait "$smoother_listener"; then
  echo "run_rostopic_mission.sh: no $smoother_status within $timeout_s s" >&2
  exit 1
fi
cat "$tmp/smoother_status"
if ! grep -q '^success: True' "$tmp/smoother_status"; then
  echo "run_rostopic_mission.sh: smoothing failed" >&2
  exit 1
fi
echo "== done: waypoint_list, trajectory and trajectory_path are latched; see them with"
echo "   rostopic echo -n 1 trajectory_path"
