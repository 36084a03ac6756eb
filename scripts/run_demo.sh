#!/usr/bin/env bash
# The demo mission end to end: installs what is missing, builds in Release and plans
# config/missions/lake_30x30.yaml with coverage_tool. Outputs go to ./demo_output.
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
mission=${1:-$root/config/missions/lake_30x30.yaml}
out=${OUT_DIR:-$root/demo_output/$(basename "$mission" .yaml)}
"$root/scripts/install_dependencies.sh"
echo "== build (Release)"
BUILD_DIR=$build_dir "$root/scripts/build.sh" --target kinematic_coverage_coverage_tool >/dev/null
echo "== plan $mission"
mkdir -p "$out"
"$build_dir/devel/lib/kinematic_coverage/coverage_tool" plan "$mission" --out "$out"
echo "Outputs are in $out:"
ls -1 "$out" | sed 's/^/  /'
