#!/usr/bin/env bash
# catkin_lint -W2 (Debian's catkin-lint) finds nothing in the package: no error, warning or
# notice, but those its CMake files ignore with a reason. catkin_lint wants the package in a
# directory named after it, so the checkout is linked under that name. Exit 77 (skipped)
# when catkin_lint is not installed (scripts/install_dependencies.sh installs it).
set -euo pipefail
source_dir=$(cd "$1" && pwd)
if ! command -v catkin_lint >/dev/null; then
  echo "catkin_lint is not installed: apt-get install catkin-lint"
  exit 77
fi
workspace=$(mktemp -d)
trap 'rm -rf "$workspace"' EXIT
ln -s "$source_dir" "$workspace/kinematic_coverage"
catkin_lint -W2 --strict "$workspace/kinematic_coverage"
