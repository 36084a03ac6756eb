#!/usr/bin/env bash
# Installs the Debian 12 packages that building, testing and running kinematic_coverage
# need. Idempotent and quiet when everything is installed already.
# --clang adds clang with libFuzzer and the sanitizer runtimes (scripts/run_fuzzers.sh,
# scripts/run_sanitizer_tests.sh).
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH

packages=(
  g++ make cmake catkin ccache
  libroscpp-dev librostest-dev python3-rostest python3-roslaunch rosout python3-rostopic
  ros-message-generation ros-message-runtime
  libstd-msgs-dev ros-std-msgs python3-std-msgs libstd-srvs-dev ros-std-srvs python3-std-srvs
  libgeometry-msgs-dev ros-geometry-msgs python3-geometry-msgs
  libnav-msgs-dev ros-nav-msgs python3-nav-msgs
  libvisualization-msgs-dev ros-visualization-msgs python3-visualization-msgs python3-rosservice
  libtf2-ros-dev libtf2-geometry-msgs-dev tf2-tools rosbash
  python3-rosnode python3-roswtf python3-rosbag
  libcgal-dev libeigen3-dev libyaml-cpp-dev libgeographiclib-dev libgtest-dev libbenchmark-dev libcairo2-dev
  libpolyclipping-dev
  librviz-dev rviz pluginlib-dev qtbase5-dev
  xvfb xauth xdotool x11-utils imagemagick clang-tidy catkin-lint
)
if [ "${1:-}" = --clang ]; then packages+=(clang libfuzzer-14-dev libclang-rt-14-dev); fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg -s "$package" >/dev/null 2>&1; then missing+=("$package"); fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "Installing ${#missing[@]} missing packages: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
  "${missing[@]}" >/dev/null
echo "Packages installed."
