#!/usr/bin/env bash
# The outputs a refactoring must not change: coverage_tool's plan of every shipped mission
# (default, thesis preset, unsmoothed, trapezoidal cells with the line sensor and the
# distance cost), simulate and replan of the lake, and plans of rooms and shoreline hard
# maps, with their progress lines. Compare two snapshots with --compare: every file must
# be identical except the *_time_s keys of metrics.json and the durations of the progress
# lines.
#
#   scripts/behaviour_snapshot.sh OUT_DIR            # with ./build's coverage_tool
#   scripts/behaviour_snapshot.sh --compare A B      # exit 1 on a difference
#   BUILD_DIR=/path/to/build scripts/behaviour_snapshot.sh OUT_DIR
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${1:-}" = --compare ]; then
  exec /usr/bin/python3 - "$2" "$3" <<'PYTHON'
import filecmp, json, os, re, sys
a, b = sys.argv[1].rstrip('/'), sys.argv[2].rstrip('/')

def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if not k.endswith('_time_s')}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value

def log_lines(path, folder):
    text = open(path).read().replace(folder + '/', 'OUT/')
    text = re.sub(r'\(\d+\.\d+ s\)', '(T)', text)
    return re.sub(r'took \d+\.\d+ s', 'took T', text)

files = differences = 0
for directory, _, names in os.walk(a):
    for name in sorted(names):
        pa = os.path.join(directory, name)
        pb = os.path.join(b, os.path.relpath(pa, a))
        files += 1
        if not os.path.exists(pb):
            same = False
        elif name == 'metrics.json':
            same = without_times(json.load(open(pa))) == without_times(json.load(open(pb)))
        elif name.endswith('.log'):
            same = log_lines(pa, a) == log_lines(pb, b)
        else:
            same = filecmp.cmp(pa, pb, shallow=False)
        if not same:
            differences += 1
            print('differs:', os.path.relpath(pa, a))
print(f'behaviour_snapshot: {files} files, {differences} differences')
sys.exit(1 if differences else 0)
PYTHON
fi
out=${1:?usage: behaviour_snapshot.sh OUT_DIR | --compare A B}
build_dir=${BUILD_DIR:-$root/build}
tool=$build_dir/devel/lib/kinematic_coverage/coverage_tool
maps=$build_dir/devel/lib/kinematic_coverage/hard_map_writer
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
for mission in lake_30x30 lake_7_5 parallelogram_60; do
  file=$root/config/missions/$mission.yaml
  "$tool" plan "$file" --out "$out/$mission" >"$out/$mission.log" 2>&1
  "$tool" plan "$file" --out "$out/${mission}_thesis" --config "$root/config/thesis.yaml" \
    >"$out/${mission}_thesis.log" 2>&1
  "$tool" plan "$file" --out "$out/${mission}_unsmoothed" --set smoothing=false \
    >"$out/${mission}_unsmoothed.log" 2>&1
  "$tool" plan "$file" --out "$out/${mission}_trapezoidal" --set decomposition_type=trapezoidal \
    --set sensor_model=line --set cost_function=distance >"$out/${mission}_trapezoidal.log" 2>&1
done
lake=$root/config/missions/lake_30x30.yaml
"$tool" simulate "$lake" --trajectory "$out/lake_30x30/trajectory.csv" --out "$out/simulate" \
  >"$out/simulate.log" 2>&1
head -n 400 "$out/lake_30x30/trajectory.csv" >"$out/visited.csv"
cat >"$out/updated.yaml" <<'YAML'
polygon:
  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]
  holes:
    - [[10, 10], [14, 10], [14, 14], [10, 14]]
YAML
for method in footprint convex_hull; do
  "$tool" replan "$lake" --updated "$out/updated.yaml" --visited "$out/visited.csv" \
    --out "$out/replan_$method" --set replanning_method=$method >"$out/replan_$method.log" 2>&1
done
"$maps" --out "$out/maps" --families rooms,shoreline --seeds 5:7 >/dev/null
for map in "$out"/maps/*.yaml; do
  name=$(basename "$map" .yaml)
  "$tool" plan "$map" --out "$out/$name" >"$out/$name.log" 2>&1
done
echo "behaviour_snapshot: $(find "$out" -type f | wc -l) files in $out"
