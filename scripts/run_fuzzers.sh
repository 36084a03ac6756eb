#!/usr/bin/env bash
# The libFuzzer targets of fuzz/ (issue 11) under AddressSanitizer + UBSan.
#
#   scripts/run_fuzzers.sh [--seconds S | --runs N] [TARGET ...]
#
# Installs clang, builds the targets (KC_FUZZ=ON, KC_SANITIZE=ON) into ./build-fuzz (or
# $BUILD_DIR) and runs each, by default every one, for S seconds (default 5: the smoke that
# scripts/run_tests.sh runs) or N executions, over its committed seed corpus
# fuzz/corpus/TARGET (read only) and a working corpus BUILD_DIR/corpus/TARGET that grows
# from run to run. A crash, leak, undefined behaviour, violated property or an input
# slower than 60 s fails the run; the input is saved as BUILD_DIR/findings/TARGET-*.
# Several invocations may run at once on one build (one per core), each with its targets.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/scripts/sanitizer_env.sh"
build_dir=${BUILD_DIR:-$root/build-fuzz}
limit=(-max_total_time=5)
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) limit=("-max_total_time=$2"); shift 2 ;;
    --runs) limit=("-runs=$2"); shift 2 ;;
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
cmake --build "$build_dir" -j"${JOBS:-$(nproc)}" --target "${targets[@]}" >/dev/null
flock -u 9
failed=0
for target in "${targets[@]}"; do
  corpus=$build_dir/corpus/$target
  mkdir -p "$corpus" "$build_dir/findings"
  log=$build_dir/findings/$target.log
  start=$(date +%s)
  if "$build_dir/devel/lib/kinematic_coverage/$target" "${limit[@]}" -timeout=60 \
      -print_final_stats=1 -artifact_prefix="$build_dir/findings/$target-" \
      "$corpus" "$root/fuzz/corpus/$target" >"$log" 2>&1; then
    result=clean
  else
    result="FAILED (log: $log)"
    failed=1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  printf '%-24s %10s executions in %4d s: %s\n' "$target" "${runs:-?}" \
    $(($(date +%s) - start)) "$result"
  [ "$result" = clean ] || grep -E 'ERROR|runtime error|fuzz property|Test unit written' "$log" | head -n 5
done
exit $failed
