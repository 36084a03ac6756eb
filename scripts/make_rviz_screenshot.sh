#!/usr/bin/env bash
# Retakes the README's rviz picture, docs/images/rviz_pipeline.png: pipeline.launch (the lake
# mission, rviz with config/rviz/pipeline.rviz) on a 1200 x 900 virtual display, one
# `activate`, and a screenshot once the trajectory has arrived and rviz has drawn it. rviz's
# frame rate stands in the picture's lower right corner (32 fps on 2026-11-27, coverage
# heatmap drawn). Needs the catkin build (scripts/build.sh; BUILD_DIR as there), xvfb-run and
# ImageMagick's `import` (scripts/install_dependencies.sh installs both).
#   scripts/make_rviz_screenshot.sh [OUTPUT.png]
set -eo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
output=$(realpath -m "${1:-$root/docs/images/rviz_pipeline.png}")
[ -f "$build_dir/devel/setup.bash" ] || {
  echo "make_rviz_screenshot.sh: no $build_dir/devel/setup.bash: build first" >&2
  exit 2
}
if [ -z "${KC_SCREENSHOT_DISPLAY:-}" ]; then
  exec env KC_SCREENSHOT_DISPLAY=1 xvfb-run -a -s "-screen 0 1200x900x24" "$0" "$output"
fi
# shellcheck disable=SC1091
source "$build_dir/devel/setup.bash"
export ROS_HOSTNAME=localhost ROS_HOME=${ROS_HOME:-$(mktemp -d)}
log=$(mktemp)
roslaunch kinematic_coverage pipeline.launch >"$log" 2>&1 &
launch=$!
trap 'kill -INT $launch 2>/dev/null; wait $launch 2>/dev/null; rm -f "$log"' EXIT
# The planner is up once its service is; rviz needs a few seconds more to load its displays.
for _ in $(seq 60); do rosservice list 2>/dev/null | grep -q /coverage_planner/plan && break; sleep 1; done
sleep 10
rostopic pub -1 activate std_msgs/Empty '{}' >/dev/null
timeout 120 rostopic echo -n 1 trajectory >/dev/null
sleep 10  # the heatmap and the markers are drawn
import -window root "$output"
echo "make_rviz_screenshot.sh: wrote $output"
