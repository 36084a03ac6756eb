#!/usr/bin/env bash
# Regenerates the README's pictures with the default parameters, each from coverage_tool:
#   docs/images/lake_30x30_plan.png            plan config/missions/lake_30x30.yaml
#   docs/images/parallelogram_60_smoothed.png  plan config/missions/parallelogram_60.yaml,
#                                              smoothing_strategy local with smoothing_clearance
#                                              0 (the thesis's)
#   docs/images/parallelogram_60_unsmoothed.png the same, smoothing false
#   docs/images/lake_30x30_replan.png          replan the lake after 40 % of its trajectory,
#                                              both obstacles moved by (2, 1) m
#   docs/images/lake_100km2_plan.png           plan the 100 km^2 lake of lake_survey_benchmark
#                                              from its GeoJSON
# With --print it writes no picture and prints the README's table of the parallelogram's
# three trajectories instead (the doc_figures test compares it with the README).
# coverage_tool must be built (scripts/build.sh --target kinematic_coverage_coverage_tool);
# BUILD_DIR as there.
set -euo pipefail
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
tool=$build_dir/devel/lib/kinematic_coverage/coverage_tool
[ -x "$tool" ] || { echo "make_readme_images.sh: no $tool: build it first" >&2; exit 2; }
missions=$root/config/missions
images=$root/docs/images
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

if [ "${1:-}" = --print ]; then
  "$tool" plan "$missions/parallelogram_60.yaml" --out "$out/local" \
    --set smoothing_strategy=local --set smoothing_clearance=0 >/dev/null 2>&1
  "$tool" plan "$missions/parallelogram_60.yaml" --out "$out/coverage_safe" >/dev/null 2>&1
  "$tool" plan "$missions/parallelogram_60.yaml" --out "$out/sharp" --set smoothing=false \
    >/dev/null 2>&1
  /usr/bin/python3 - "$out" <<'EOF'
import json
import sys

print('| parallelogram_60.yaml | free area unseen | reachable area seen '
      '| seen by the unsmoothed trajectory, unseen | traversal time | turns smoothed |')
print('|---|---|---|---|---|---|')
for label, run in (('smoothed, Algorithm 1 (`local`)', 'local'),
                   ('smoothed, default (`coverage_safe`)', 'coverage_safe'),
                   ('unsmoothed', 'sharp')):
    metrics = json.load(open(f'{sys.argv[1]}/{run}/metrics.json'))
    lost = metrics.get('smoothing_lost_area_m2', 0.0)
    print(f"| {label} | {metrics['coverage_loss_percent']:.2f} % "
          f"| {metrics['reachable_coverage_percent']:.3f} % | {lost:.3f} m^2 "
          f"| {metrics['traversal_time_s']:.1f} s "
          f"| {metrics['turns_smoothed']:.0f} of {metrics['turns_total']:.0f} |")
EOF
  exit 0
fi

"$tool" plan "$missions/lake_30x30.yaml" --out "$out/lake" >/dev/null
cp "$out/lake/plot.png" "$images/lake_30x30_plan.png"

"$build_dir/devel/lib/kinematic_coverage/lake_survey_benchmark" --areas 100 --out "$out/lakes" \
  --plots "$out/lake_plots" >/dev/null
cp "$out/lake_plots/lake_100km2.png" "$images/lake_100km2_plan.png"

"$tool" plan "$missions/parallelogram_60.yaml" --out "$out/local" \
  --set smoothing_strategy=local --set smoothing_clearance=0 >/dev/null
cp "$out/local/plot.png" "$images/parallelogram_60_smoothed.png"
"$tool" plan "$missions/parallelogram_60.yaml" --out "$out/sharp" --set smoothing=false >/dev/null
cp "$out/sharp/plot.png" "$images/parallelogram_60_unsmoothed.png"

# The first 40 % of the lake's trajectory as the visited poses, the obstacles moved.
lines=$(($(wc -l <"$out/lake/trajectory.csv") - 1))
head -n $((1 + lines * 2 / 5)) "$out/lake/trajectory.csv" >"$out/visited.csv"
/usr/bin/python3 - "$missions/lake_30x30.yaml" "$out/updated.yaml" <<'EOF'
import re
import sys

text = open(sys.argv[1]).read()
hull = re.search(r'hull: (.*)', text).group(1)
holes = re.findall(r'    - (.*)', text)
shift = (2.0, 1.0)
with open(sys.argv[2], 'w') as out:
    out.write('polygon:\n  hull: %s\n  holes:\n' % hull)
    for hole in holes:
        points = re.findall(r'\[([-\d.]+), ([-\d.]+)\]', hole)
        moved = ', '.join('[%g, %g]' % (float(x) + shift[0], float(y) + shift[1]) for x, y in points)
        out.write('    - [%s]\n' % moved)
EOF
"$tool" replan "$missions/lake_30x30.yaml" --updated "$out/updated.yaml" \
  --visited "$out/visited.csv" --out "$out/replan" >/dev/null
cp "$out/replan/plot.png" "$images/lake_30x30_replan.png"
echo "make_readme_images.sh: wrote the README's five pictures in $images" >&2
