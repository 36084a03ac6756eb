#!/usr/bin/env bash
# Regenerates docs/EXPERIMENTS.md and docs/images/experiments_*.png: the thesis's two
# experiments (Chapter 4, Tables 4.1 to 4.3) in simulation, plus a run in a current, and the
# same trajectories in calm water with exact navigation, for both vehicles; then both
# experiments as a sensitivity study of the controllers (controller_study). Each mission is planned four times
# with `coverage_tool plan`: smoothed by the thesis's Algorithm 1 (`smoothing_strategy:
# local`), smoothed with the default strategy, the same with continuous-curvature turns
# (`turn_curve: clothoid`), and unsmoothed; the same robot follows every trajectory with
# `coverage_tool simulate`.
#
#   scripts/run_experiments.sh            # builds coverage_tool into ./build, writes the doc
#   scripts/run_experiments.sh --print    # the doc on standard output, nothing written
#                                         # (coverage_tool must be built; no build step)
#   BUILD_DIR=/path/to/build JOBS=1 scripts/run_experiments.sh
#
# Raw outputs (trajectories, actual paths, metrics) go to $OUT_DIR (default
# $BUILD_DIR/experiments, or a temporary folder with --print). The `doc_figures` test runs
# `--print` and compares its tables with docs/EXPERIMENTS.md (scripts/doc_figures.py).
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
tool=$build_dir/devel/lib/kinematic_coverage/coverage_tool
study=$build_dir/devel/lib/kinematic_coverage/controller_study
missions=$root/config/missions
images=$root/docs/images
print_only=false
case "${1:-}" in
  --print) print_only=true ;;
  "") ;;
  *) echo "usage: run_experiments.sh [--print]" >&2; exit 2 ;;
esac

if $print_only; then
  for program in "$tool" "$study"; do
    [ -x "$program" ] || { echo "run_experiments.sh: no $program: build it first" >&2; exit 2; }
  done
  out=${OUT_DIR:-$(mktemp -d)}
  [ -n "${OUT_DIR:-}" ] || trap 'rm -rf "$out"' EXIT
else
  out=${OUT_DIR:-$build_dir/experiments}
  echo "== build coverage_tool and controller_study" >&2
  BUILD_DIR=$build_dir "$root/scripts/build.sh" --target kinematic_coverage_coverage_tool \
    kinematic_coverage_controller_study >/dev/null
fi

# The lake, as the thesis's runs met it: a current that fluctuates by 0.02 m/s per axis
# about no mean (correlation time 60 s) and a navigation error of 0.1 m per axis
# (correlation time 2 s), disturbance_seed 1. The values were set before these experiments
# first ran with them, from the sources config/default.yaml cites, and not changed after.
lake=(--set current_sigma=0.02 --set navigation_sigma=0.1)
# The robots, as --set overrides of config/default.yaml (the same for every trajectory of an
# experiment). Experiment 1 is the default robot; experiment 2 lowers the yaw gain and
# samples rotations more finely, as the thesis's second run did.
robot_high_gain=()
robot_low_gain=(--set yaw_gain=2 --set rotation_sampling_angle=0.1)
current=(--set current_x=0.2 --set current_y=0.1)
# The follower of these experiments: the setpoint follower, homing on each pose as the
# thesis's robot did (the default controller, timed, tracks the planned times instead).
follower=(--set controller=setpoint)
# The four trajectories of each run: Algorithm 1 (with the thesis's no-contact check), the
# default strategy, the default strategy with continuous-curvature (clothoid) turns,
# unsmoothed.
local_smoothing=(--set smoothing=true --set smoothing_strategy=local --set smoothing_clearance=0)
default_smoothing=(--set smoothing=true)
clothoid_smoothing=(--set smoothing=true --set turn_curve=clothoid)
no_smoothing=(--set smoothing=false)

# run NAME MISSION [--set ...]: plans and simulates into $out/NAME.
run() {
  local name=$1 mission=$2
  shift 2
  echo "== $name" >&2
  rm -rf "${out:?}/$name"
  mkdir -p "$out/$name"
  "$tool" plan "$missions/$mission.yaml" --out "$out/$name/plan" "$@" >"$out/$name/plan.log"
  "$tool" simulate "$missions/$mission.yaml" --trajectory "$out/$name/plan/trajectory.csv" \
    --out "$out/$name/simulate" "${follower[@]}" "$@" >"$out/$name/simulate.log"
  grep '^simulate: ' "$out/$name/simulate.log" >&2
}

# resimulate NAME FROM MISSION [--set ...]: the robot of --set follows the trajectory planned
# for run FROM, into $out/NAME.
resimulate() {
  local name=$1 from=$2 mission=$3
  shift 3
  echo "== $name" >&2
  rm -rf "${out:?}/$name"
  mkdir -p "$out/$name"
  "$tool" simulate "$missions/$mission.yaml" --trajectory "$out/$from/plan/trajectory.csv" \
    --out "$out/$name/simulate" "${follower[@]}" "$@" >"$out/$name/simulate.log"
  grep '^simulate: ' "$out/$name/simulate.log" >&2
}

for strategy in local default clothoid unsmoothed; do
  case $strategy in
    local) smoothing=("${local_smoothing[@]}") ;;
    default) smoothing=("${default_smoothing[@]}") ;;
    clothoid) smoothing=("${clothoid_smoothing[@]}") ;;
    unsmoothed) smoothing=("${no_smoothing[@]}") ;;
  esac
  run "lake_30x30_$strategy" lake_30x30 "${smoothing[@]}" "${robot_high_gain[@]}" "${lake[@]}"
  run "lake_7_5_$strategy" lake_7_5 "${smoothing[@]}" "${robot_low_gain[@]}" "${lake[@]}"
  run "lake_7_5_high_gain_$strategy" lake_7_5 "${smoothing[@]}" "${robot_high_gain[@]}" \
    "${lake[@]}"
done
run lake_30x30_current lake_30x30 "${default_smoothing[@]}" "${current[@]}" "${lake[@]}"
# The default strategy with the thesis's no-contact check instead of the wall distance.
run lake_30x30_no_contact lake_30x30 "${default_smoothing[@]}" --set smoothing_clearance=0 \
  "${robot_high_gain[@]}" "${lake[@]}"
# The same trajectories in calm water with exact navigation, with the dynamic vehicle and
# with the first, kinematic one, for comparison.
calm() {
  local strategy=$1 vehicle=$2
  resimulate "lake_30x30_${strategy}_calm_$vehicle" "lake_30x30_$strategy" lake_30x30 \
    --set vehicle_model="$vehicle" "${robot_high_gain[@]}"
  resimulate "lake_7_5_${strategy}_calm_$vehicle" "lake_7_5_$strategy" lake_7_5 \
    --set vehicle_model="$vehicle" "${robot_low_gain[@]}"
}
for strategy in local default clothoid unsmoothed; do calm "$strategy" dynamic; done
for strategy in local unsmoothed; do calm "$strategy" kinematic; done
# How the hunting near the poses depends on position_tolerance against the navigation
# error: experiment 1's robot in the lake with larger tolerances (a sensitivity study; the
# tables above keep the default 0.05 m).
for tolerance in 0.1 0.2 0.3; do
  for strategy in local unsmoothed; do
    resimulate "lake_30x30_${strategy}_tolerance_$tolerance" "lake_30x30_$strategy" lake_30x30 \
      "${robot_high_gain[@]}" "${lake[@]}" --set position_tolerance=$tolerance
  done
done
# The controllers as a sensitivity study: the trajectories of Algorithm 1 and unsmoothed of
# both experiments, driven by every controller, in calm water and in the lake with seeds 1
# to 5.
echo "== controller_study" >&2
study_lake=()
for setting in "${lake[@]}"; do [ "$setting" = --set ] || study_lake+=(--lake "$setting"); done
"$study" --seeds 5 "${study_lake[@]}" \
  --experiment 1 "$missions/lake_30x30.yaml" "$out/lake_30x30_local/plan/trajectory.csv" \
  "$out/lake_30x30_unsmoothed/plan/trajectory.csv" "${robot_high_gain[@]}" \
  --experiment 2 "$missions/lake_7_5.yaml" "$out/lake_7_5_local/plan/trajectory.csv" \
  "$out/lake_7_5_unsmoothed/plan/trajectory.csv" "${robot_low_gain[@]}" \
  >"$out/controller_study.md" 2>"$out/controller_study.log"

if $print_only; then
  /usr/bin/python3 "$root/scripts/experiments_report.py" "$out"
  exit 0
fi
mkdir -p "$images"
for name in lake_30x30_local lake_30x30_default lake_30x30_clothoid lake_30x30_unsmoothed \
  lake_7_5_local lake_7_5_default lake_7_5_clothoid lake_7_5_unsmoothed lake_30x30_current; do
  cp "$out/$name/simulate/plot.png" "$images/experiments_$name.png"
done
# The thesis's figures for Algorithm 1 against unsmoothed: the planned trajectories'
# heatmaps (Fig. 4.2), the driven poses (Fig. 4.3) and the error statistics (Fig. 4.5).
for name in lake_30x30_local lake_30x30_unsmoothed lake_7_5_local lake_7_5_unsmoothed; do
  cp "$out/$name/simulate/poses.png" "$images/experiments_${name}_poses.png"
  cp "$out/$name/simulate/errors.png" "$images/experiments_${name}_errors.png"
done
for name in lake_30x30_local lake_30x30_unsmoothed lake_7_5_local lake_7_5_unsmoothed; do
  cp "$out/$name/plan/plot.png" "$images/experiments_${name}_plan.png"
done
echo "== write docs/EXPERIMENTS.md" >&2
/usr/bin/python3 "$root/scripts/experiments_report.py" "$out" >"$root/docs/EXPERIMENTS.md"
