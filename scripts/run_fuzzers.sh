#!/usr/bin/env bash
# The libFuzzer targets of fuzz/ under AddressSanitizer + UBSan.
#
#   scripts/run_fuzzers.sh [--seconds S | --runs N] [TARGET ...]
#   scripts/run_fuzzers.sh --campaign     # the campaigns of docs/RELIABILITY.md (hours)
#
# Installs clang, builds the targets (KC_FUZZ=ON, KC_SANITIZE=ON) into ./build-fuzz (or
# $BUILD_DIR) and runs each, by default every one, for S seconds (default 5: the smoke that
# scripts/run_tests.sh runs) or N executions, over its committed seed corpus
# fuzz/corpus/TARGET (read only) and a working corpus BUILD_DIR/corpus/TARGET that grows
# from run to run. --campaign runs every target to its documented budget: 10^6 executions
# of the parsers and of corner smoothing, 10^5 of the planner, 30 minutes of
# coverage-preserving smoothing. A crash, leak, undefined behaviour, violated property or an
# input slower than 60 s fails the run; the input is saved as BUILD_DIR/findings/TARGET-*.
# Prints a Markdown table, a row per target. Several invocations may run at once on one
# build (one per core), each with its targets.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/scripts/sanitizer_env.sh"
build_dir=${BUILD_DIR:-$root/build-fuzz}
limit=-max_total_time=5
campaign=false
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) limit="-max_total_time=$2"; shift 2 ;;
    --runs) limit="-runs=$2"; shift 2 ;;
    --campaign) campaign=true; shift ;;
    -h|--help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) echo "run_fuzzers.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
if [ ${#targets[@]} -eq 0 ]; then
  targets=(mission_file_fuzzer gtsplib_fuzzer corner_smoothing_fuzzer coverage_preserving_fuzzer
           planner_fuzzer)
fi
"$root/scripts/install_dependencies.sh" --clang
echo "== build the fuzz targets (clang, libFuzzer, ASan + UBSan) in $build_dir"
mkdir -p "$build_dir"
# One configure and build at a time, so that campaigns can run side by side on one build.
exec 9>"$build_dir.lock"
flock 9
kc_configure_sanitized "$build_dir" -DKC_FUZZ=ON
cmake --build "$build_dir" -j"${JOBS:-$(nproc)}" --target "${targets[@]/#/kinematic_coverage_}" >/dev/null
flock -u 9
# The budget of one target's run: --campaign's, else the one asked for.
budget() {
  if ! $campaign; then echo "$limit"; return; fi
  case "$1" in
    planner_fuzzer) echo -runs=100000 ;;
    coverage_preserving_fuzzer) echo -max_total_time=1800 ;;
    *) echo -runs=1000000 ;;
  esac
}
failed=0
echo "| target | budget | executions | seconds (timing) | executions/s (timing) | peak RSS MB (at most 2048) | edges covered at the end (varies) | corpus at start → end, inputs (varies) | result |"
echo "|---|---|---:|---:|---:|---:|---:|---|---|"
for target in "${targets[@]}"; do
  corpus=$build_dir/corpus/$target
  mkdir -p "$corpus" "$build_dir/findings"
  log=$build_dir/findings/$target.log
  start=$(date +%s)
  run_budget=$(budget "$target")
  if "$build_dir/devel/lib/kinematic_coverage/$target" "$run_budget" -timeout=60 \
      -print_final_stats=1 -artifact_prefix="$build_dir/findings/$target-" \
      "$corpus" "$root/fuzz/corpus/$target" >"$log" 2>&1; then
    result=clean
  else
    result="FAILED (log: $log)"
    failed=1
  fi
  seconds=$(($(date +%s) - start))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log")
  edges=$(grep -oE 'cov: [0-9]+' "$log" | tail -n 1 | cut -d' ' -f2)
  corpus_start=$(grep -E 'INITED' "$log" | grep -oE 'corp: [0-9]+' | head -n 1 | cut -d' ' -f2)
  corpus_end=$(grep -oE 'corp: [0-9]+' "$log" | tail -n 1 | cut -d' ' -f2)
  rate=$(( ${runs:-0} / (seconds > 0 ? seconds : 1) ))
  printf '| `%s` | %s | %s | %d | %d | %s | %s | %s → %s | %s |\n' "$target" "${run_budget#-}" \
    "${runs:-?}" "$seconds" "$rate" "${rss:-?}" "${edges:-?}" "${corpus_start:-?}" \
    "${corpus_end:-?}" "$result"
  [ "$result" = clean ] || grep -E 'ERROR|runtime error|fuzz property|Test unit written' "$log" | head -n 5 >&2
done
exit $failed
