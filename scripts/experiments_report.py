#!/usr/bin/env python3
"""Writes docs/EXPERIMENTS.md (on standard output) from the runs of run_experiments.sh.

    experiments_report.py OUT_DIR

OUT_DIR holds one folder per run (NAME/plan/metrics.json, NAME/simulate/metrics.json). The
statements about the thesis's trends are computed from the figures, so the text says what the
tables show under each strategy. The settings the text states are read from their files
(config/default.yaml, the missions, the `--set` values of run_experiments.sh), each followed
by the marker by which scripts/prose_figures.py checks it there; no figure of the prose is
typed here.
"""
import json
import math
import os
import re
import sys
import textwrap

import prose_figures

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PERCENTILES = ['1', '5', '10', '25', '50', '75', '90', '95', '99']
STRATEGIES = [('local', 'smoothed, Alg. 1 (`local`)'), ('default', 'smoothed, default'),
              ('clothoid', 'smoothed, default, clothoid turns'), ('unsmoothed', 'unsmoothed')]
COMMAND = 'scripts/run_experiments.sh --print'
SCRIPT = 'scripts/run_experiments.sh'
DEFAULTS = 'config/default.yaml'
# position_tolerance of the sensitivity study beyond the default, metres (run_experiments.sh's
# loop; the runs' folders are named by them).
TOLERANCES = ['0.1', '0.2', '0.3']
# The thesis's traversal times (s) and tracking error sums (m), smoothed and unsmoothed
# (Tables 4.1 and 4.3).
THESIS = {'lake_30x30': {'time': (1529, 1241), 'error': (293.44, 452.20)},
          'lake_7_5': {'time': (531, 703), 'error': (283.98, 239.34)}}


def main():
    out = sys.argv[1]

    def load(name, part):
        with open(f'{out}/{name}/{part}/metrics.json') as stream:
            return json.load(stream)

    names = [f'{mission}_{strategy}' for mission in ('lake_30x30', 'lake_7_5', 'lake_7_5_high_gain')
             for strategy, _ in STRATEGIES] + ['lake_30x30_current', 'lake_30x30_no_contact'] + [
                 f'{mission}_{strategy}_calm_{vehicle}' for mission in ('lake_30x30', 'lake_7_5')
                 for strategy, vehicle in [(strategy, 'dynamic') for strategy, _ in STRATEGIES] +
                 [('local', 'kinematic'), ('unsmoothed', 'kinematic')]] + [
                 f'lake_30x30_{strategy}_tolerance_{tolerance}' for tolerance in TOLERANCES
                 for strategy in ('local', 'unsmoothed')]
    sim = {name: load(name, 'simulate') for name in names}
    plan = {name: load(name, 'plan') for name in names
            if '_calm_' not in name and '_tolerance_' not in name}
    with open(f'{out}/controller_study.md') as stream:
        study = stream.read()
    sys.stdout.write(Report(sim, plan, study).text())


def mission_file(name):
    """The mission file of a mission, relative to the repository."""
    return f'config/missions/{name}.yaml'


def setting(path, name):
    """The number that a repository file assigns to `name`: a `name: number` line of a YAML
    file (a parameter default, a mission's setting), or `name=number` in run_experiments.sh
    (a `--set` of its runs). Read as scripts/prose_figures.py reads a marker's source."""
    kind = 'yaml' if path.endswith('.yaml') else 'code'
    return prose_figures.file_value(kind, {kind: path, 'key': name, 'name': name}, ROOT, path)


def figure(path, name, unit, scale=1):
    """A setting as a figure of the prose, followed by the marker by which prose_figures.py
    checks it against its file."""
    kind = 'yaml' if path.endswith('.yaml') else 'code'
    text = f'{setting(path, name) * scale:g} {unit}'
    end = prose_figures.FIGURE.match(text).end()
    marker = f'<!-- checked: {kind}="{path}" {"key" if kind == "yaml" else "name"}="{name}"'
    marker += f' scale="{scale:g}" -->' if scale != 1 else ' -->'
    return text[:end] + marker + text[end:]


def script_settings(array):
    """The `--set` arguments of a bash array of run_experiments.sh, as written there."""
    with open(os.path.join(ROOT, SCRIPT), encoding='utf-8') as stream:
        match = re.search(rf'^{array}=\((.*)\)$', stream.read(), re.MULTILINE)
    if not match:
        raise SystemExit(f'experiments_report.py: {SCRIPT} has no array {array}')
    return match.group(1)


def extent(name):
    """'A m x B m', the extent of a mission's hull."""
    with open(os.path.join(ROOT, mission_file(name)), encoding='utf-8') as stream:
        hull = json.loads(re.search(r'^\s*hull:\s*(\[.*\])\s*$', stream.read(), re.MULTILINE).group(1))
    xs, ys = [x for x, _ in hull], [y for _, y in hull]
    return f'{max(xs) - min(xs):g} m x {max(ys) - min(ys):g} m'


def seconds(value):
    return f'{value:.1f} s'


def metres(value, digits=2):
    return f'{value:.{digits}f} m'


def percent(value):
    return f'{value:.2f} %'


def ratio(a, b):
    return f'{a / b:.2f}'


def where_reversal(in_lake, in_calm):
    """Where the thesis's reversal (the smoothed run tracking worse) appears."""
    return {(True, True): 'both in the lake and in calm water',
            (True, False): 'in the lake and not in calm water',
            (False, True): 'in calm water and not in the lake',
            (False, False): 'neither in the lake nor in calm water'}[(in_lake, in_calm)]


def change(a, b):
    """How `a` compares with `b`, as 'N % less' or 'N % more' (with a decimal where N would
    round to nothing)."""
    share = 100 * (1 - a / b)
    digits = 1 if f'{abs(share):.0f}' == '0' else 0
    return f'{share:.{digits}f} % less' if share >= 0 else f'{-share:.{digits}f} % more'


class Report:
    """The document, table by table; each table gets a figures marker for doc_figures.py."""

    def __init__(self, sim, plan, study):
        self.sim = sim
        self.plan = plan
        self.study = study
        self.tables = 0

    def marker(self):
        self.tables += 1
        return (f'<!-- figures: id="experiments-{self.tables}" command="{COMMAND}" '
                f'table={self.tables} -->\n')

    def metrics_table(self, mission, extra_rows):
        """Metric rows for the four trajectories of `mission` beside the thesis's figures."""
        runs = [self.sim[f'{mission}_{strategy}'] for strategy, _ in STRATEGIES]
        plans = [self.plan[f'{mission}_{strategy}'] for strategy, _ in STRATEGIES]
        thesis = THESIS[mission]
        rows = [
            ('traversing time', [seconds(r['traversal_time_s']) for r in runs],
             [f'{time:g} s' for time in thesis['time']]),
            ('coverage loss (actual poses)', [percent(r['coverage_loss_percent']) for r in runs],
             ['0 %', '0 %']),
            ('coverage loss (planned trajectory)',
             [percent(p['coverage_loss_percent']) for p in plans], ['0 %', '0 %']),
            ('unseen reachable area (planned trajectory)',
             [f"{p['unseen_reachable_area_m2']:.3f} m^2" for p in plans], ['-', '-']),
            ('seen by the unsmoothed trajectory, unseen (planned)',
             [f"{p.get('smoothing_lost_area_m2', 0.0):.3f} m^2" for p in plans], ['-', '-']),
            ('closest approach to a wall or obstacle (driven)',
             [metres(r['driven_min_clearance_m'], 3) for r in runs], ['-', '-']),
            ('trajectory error (sum)', [metres(r['tracking_error_sum_m']) for r in runs],
             [metres(error) for error in thesis['error']]),
            ('trajectory error (mean)', [metres(r['tracking_error_mean_m'], 4) for r in runs],
             ['-', '-']),
            ('error to the targeted piece (sum)',
             [metres(r['tracking_error_target_sum_m']) for r in runs], ['-', '-']),
            ('mean x / y part of the error',
             [f"{r['tracking_error_x_mean_m']:.4f} / {r['tracking_error_y_mean_m']:.4f} m"
              for r in runs], ['-', '-']),
        ] + [(label, [format_value(run, plan_metrics) for run, plan_metrics in zip(runs, plans)],
              ['-', '-']) for label, format_value in extra_rows]
        text = self.marker()
        text += '| metric | ' + ' | '.join(label for _, label in STRATEGIES)
        text += ' | thesis smoothed | thesis unsmoothed |\n|---|' + '---|' * (len(STRATEGIES) + 2) + '\n'
        for label, ours, theirs in rows:
            text += f'| {label} | ' + ' | '.join(ours + theirs) + ' |\n'
        return text

    def conditions_table(self, mission):
        """Time, error sum and median error of Algorithm 1 and unsmoothed on `mission`: in the
        lake with the dynamic vehicle, and in calm water with exact navigation with either
        vehicle."""
        text = self.marker()
        text += '| condition | Algorithm 1: time | error sum | median error | unsmoothed: time '
        text += '| error sum | median error |\n|---|---|---|---|---|---|---|\n'
        for condition, suffix in (('lake, dynamic vehicle (the tables above)', ''),
                                  ('calm water, exact navigation, dynamic vehicle', '_calm_dynamic'),
                                  ('calm water, exact navigation, kinematic vehicle',
                                   '_calm_kinematic')):
            runs = [self.sim[f'{mission}_{strategy}{suffix}'] for strategy in ('local', 'unsmoothed')]
            text += f'| {condition} | ' + ' | '.join(
                f"{seconds(run['traversal_time_s'])} | {metres(run['tracking_error_sum_m'])} | "
                f"{metres(run['tracking_error_percentiles_m']['50'], 3)}" for run in runs) + ' |\n'
        return text

    def tolerance_table(self):
        """Experiment 1 in the lake with the default position_tolerance and each of TOLERANCES:
        time and error sum of Algorithm 1 and unsmoothed."""
        text = self.marker()
        text += '| `position_tolerance` | Algorithm 1: time | error sum | unsmoothed: time '
        text += '| error sum |\n|---|---|---|---|---|\n'
        default = f"{setting(DEFAULTS, 'position_tolerance'):g}"
        for tolerance in [default] + TOLERANCES:
            suffix = '' if tolerance == default else f'_tolerance_{tolerance}'
            runs = [self.sim[f'lake_30x30_{strategy}{suffix}'] for strategy in ('local', 'unsmoothed')]
            label = f'{tolerance} m' + (' (default, the tables above)' if not suffix else '')
            text += f'| {label} | ' + ' | '.join(
                f"{seconds(run['traversal_time_s'])} | {metres(run['tracking_error_sum_m'])}"
                for run in runs) + ' |\n'
        return text

    def trends(self, mission, suffix=''):
        """Traversal time and error sum of the runs of STRATEGIES, in order; `suffix`
        '_calm_dynamic' for the runs in calm water with exact navigation."""
        runs = [self.sim[f'{mission}_{strategy}{suffix}'] for strategy, _ in STRATEGIES]
        return [(r['traversal_time_s'], r['tracking_error_sum_m']) for r in runs]

    def text(self):
        sim, plan = self.sim, self.plan
        local1, default1, clothoid1, unsmoothed1 = self.trends('lake_30x30')
        local2, default2, clothoid2, unsmoothed2 = self.trends('lake_7_5')
        local3, default3, clothoid3, unsmoothed3 = self.trends('lake_7_5_high_gain')
        calm_local1, calm_default1, calm_clothoid1, calm_unsmoothed1 = self.trends('lake_30x30', '_calm_dynamic')
        calm_local2, calm_default2, calm_clothoid2, calm_unsmoothed2 = self.trends('lake_7_5', '_calm_dynamic')
        calm, drift = sim['lake_30x30_default'], sim['lake_30x30_current']
        m30, m7 = mission_file('lake_30x30'), mission_file('lake_7_5')
        lake, low_gain = script_settings('lake'), script_settings('robot_low_gain')
        thesis1, thesis2 = THESIS['lake_30x30'], THESIS['lake_7_5']
        # Experiment 2's footprint (docs/REFERENCE.md, Sensor footprint and coverage) and
        # the largest radius of the default strategy's turns (max_turning_radius, its 0 the
        # radius of full speed at full yaw rate).
        width, length = (2 * setting(m7, 'sensor_distance') * math.tan(setting(m7, fov) / 2)
                         for fov in ('lateral_fov', 'onward_fov'))
        largest_radius = setting(DEFAULTS, 'max_turning_radius') or max(
            setting(m7, 'turning_radius'), setting(DEFAULTS, 'v_max') / setting(DEFAULTS, 'yaw_rate_max'))
        mean_current = f"({setting(SCRIPT, 'current_x'):g}, {setting(SCRIPT, 'current_y'):g}) m/s"

        def holds(condition):
            return 'holds' if condition else 'does NOT hold'

        text = f'''<!-- document: command="{COMMAND}" source="scripts/experiments_report.py" -->
# Experiments: smoothed against unsmoothed trajectories, in simulation

Generated by `scripts/run_experiments.sh` (do not edit by hand; rerun it). Every table is
printed by `{COMMAND}`, and the `doc_figures` test (CI) reruns it and compares every figure
with this document (all of them are machine-independent: the simulation runs at a fixed
step). The thesis compared smoothed and unsmoothed trajectories on the Proteus vehicle in
Lake Zurich (Chapter 4, Tables 4.1 to 4.3). Here the vehicle is the robot model of
`coverage_tool simulate` and of the `auv_simulator` node. Each mission is planned four
times with `coverage_tool plan`: smoothed by the thesis's Algorithm 1 with its
no-contact check (`smoothing_strategy: local`, `smoothing_clearance: 0`), smoothed with the
default strategy (`coverage_safe`, keeping its turns at the wall distance: every
corner's smoothing chosen jointly to minimise the traversal time while the path as a whole
still sees the reachable area the unsmoothed path sees), the same with continuous-curvature turns
(`turn_curve: clothoid`: clothoid-arc-clothoid instead of an arc between two legs, where
the legs leave room and the turn comes no nearer an obstacle and sees no less), and
unsmoothed (`smoothing: false`), all four from the same waypoints (with the default
`coverage_repair`); the same robot follows every trajectory with `coverage_tool simulate`.
The metrics (docs/REFERENCE.md, Metrics) are the traversal time, the tracking error (the
distance from the robot to the nearest point of the desired path, once per simulation
step: its sum, mean and percentiles; the error to the targeted trajectory
piece; the mean x and y parts) and the coverage loss of the poses the robot actually
drove. The robot meets the lake's disturbances (below); the same trajectories in calm
water with exact navigation are compared at the end of each experiment. Whether each of
the thesis's trends holds is reported, not asserted: the tests check the vehicle's physics
and its controllers' laws (test/simulation), never which trajectory wins.

## The robot model

`TrajectoryFollower` (trajectory_generation_tools/simulation/trajectory_follower.h) with
`controller: setpoint`, as the thesis's robot: it is handed the trajectory's poses one after
the other, not a timetable, so the traversal time comes out of its dynamics and controllers
(the default controller, `timed`, tracks the planned times instead; it and the others are
compared in the last section):

- a pose at the same position as the pose before it (an in-place rotation) is a heading
  target, reached within `yaw_tolerance`; any other pose is a position target, reached
  within `position_tolerance` or once passed;
- navigation: the robot knows its position only as the true one plus a navigation error,
  and steers by that estimate; the tracking error is measured at the true position;
- position controller: towards a position target it asks for a velocity over ground of
  `position_gain` times the distance to the target, at most `v_max` and at most
  `sqrt(2 a_max d)` with d the distance along the poses to the next stop (so that it stops
  on a corner where it turns in place), and steers the velocity through the water that
  gives it in the mean current; towards a heading target it turns in place;
- yaw controller: a yaw-rate command of `yaw_gain` times the heading error, at most
  `yaw_rate_max`;
- shared thrust: the speed command is at most `v_max * (1 - |yaw rate| / yaw_rate_max)`,
  and its reference changes by at most `a_max` per second;
- the vehicle (`vehicle_model: dynamic`, the default): a rigid body in surge, sway and yaw
  (`PlanarRigidBody`, Fossen's planar model with mass, added mass, Coriolis and centripetal
  terms, linear and quadratic damping), whose surge speed and yaw rate follow the commands
  through two velocity loops (`surge_loop_gain` 5 1/s, `yaw_rate_loop_gain` 10 1/s, each a
  proportional term plus feedforwards of the damping and, in surge, of the reference's
  acceleration), and whose sway speed through the water a third loop holds at zero (the
  Coriolis force that slips a turning body outwards fed forward; `sway_actuated`, the
  default: the BlueROV2's four vectored thrusters drive sway too, and surge, sway and yaw
  share their limits, a demand beyond them scaled down whole). `sway_actuated: false` is a
  torpedo-like variant that slips outwards in a turn. Its values are a BlueROV2's (C.-J. Wu, "6-DoF Modelling and Control
  of a Remotely Operated Vehicle", MSc thesis, Flinders University, 2018: 11.5 kg, added
  mass 5.5 kg in surge and 12.7 kg in sway, damping 4.03 + 18.18 |u| N s/m in surge and
  6.22 + 21.66 |v| N s/m in sway; four T200 thrusters at 40 N), a small hovering vehicle of
  the Proteus's kind, set in `config/default.yaml` before any of these experiments ran
  and not changed after. `vehicle_model: kinematic` is the first model, whose speed and
  yaw rate follow their commands at once;
- the lake (`{lake}`, with the defaults
  `current_time_constant` {figure(DEFAULTS, 'current_time_constant', 's')}, `navigation_time_constant` {figure(DEFAULTS, 'navigation_time_constant', 's')},
  `disturbance_seed` {setting(DEFAULTS, 'disturbance_seed'):g}):
  a current that fluctuates about no mean by {figure(SCRIPT, 'current_sigma', 'm/s')} per axis (lake currents are a few
  cm/s; Wuest and Lorke, Annu. Rev. Fluid Mech. 35:373, 2003), of which the controller
  knows nothing, and a navigation error of {figure(SCRIPT, 'navigation_sigma', 'm')} per axis
  (what an acoustic short-baseline system such as the Water Linked Underwater GPS achieves
  at short range: config/default.yaml, `navigation_sigma`), each axis a first-order
  Gauss-Markov process (Fossen 2011, Section 8.3). These values were set
  before the experiments first ran with them and not changed after; the thesis does not
  say how Proteus navigated.

The braking and the surge loop's acceleration feedforward were added after the first
runs of these experiments, to mend a defect those runs showed: the robot braked too late
and ran past every corner it was to turn in place at, towards the walls.
Those runs had the smoothed trajectory tracked better in experiment 1, as the thesis
did; it was the overshoot that made the unsmoothed errors large, and with the defect
mended that trend is gone (below).

Two mechanisms produce the thesis's time trends. The set-point controller slows towards
every pose it is handed, so following densely sampled arcs (a pose every
{figure(m30, 'arc_sampling_distance', 'm')}) costs time,
while a turn in place with a high yaw gain runs at the saturated yaw rate. With a low
yaw gain each rotation pose is approached exponentially, so finely sampled rotations are
slow: the in-place turns lose their advantage. The tracking errors come from the lake and
the vehicle: the robot holds its estimate on the path, so its true position strays by the
navigation error, and the current pushes it off until the controller steers back; the
smoothed robot also lags behind its targets on the arcs (and, as the torpedo-like variant,
slips outwards on them).

## Experiment 1: lake_30x30, high yaw gain (Tables 4.1 and 4.2)

Mission `{m30}` (the thesis's {extent('lake_30x30')} map with two
obstacles, boustrophedon, time cost, {figure(m30, 'wall_distance', 'm')} wall offset, {figure(m30, 'lateral_overlap', '%', 100)} overlap, frustum
sensor {figure(m30, 'sensor_distance', 'm')} above the bottom, {figure(m30, 'turning_radius', 'm')} turning radius, sampling
{figure(m30, 'segment_sampling_distance', 'm')} on segments, {figure(m30, 'arc_sampling_distance', 'm')} on arcs). Robot, the same for
every trajectory: `config/default.yaml`, i.e. the dynamic vehicle, `v_max`
{figure(DEFAULTS, 'v_max', 'm/s')}, `a_max` {figure(DEFAULTS, 'a_max', 'm/s^2')}, `yaw_rate_max` {figure(DEFAULTS, 'yaw_rate_max', 'rad/s')},
`yaw_gain` {setting(DEFAULTS, 'yaw_gain'):g} 1/s, `position_gain` {setting(DEFAULTS, 'position_gain'):g} 1/s,
`position_tolerance` {figure(DEFAULTS, 'position_tolerance', 'm')}, `yaw_tolerance` {figure(DEFAULTS, 'yaw_tolerance', 'rad')},
`rotation_sampling_angle` {figure(DEFAULTS, 'rotation_sampling_angle', 'rad')}, `sim_dt` {figure(DEFAULTS, 'sim_dt', 's')}, in the lake.

    coverage_tool plan {m30} --out DIR \\
        --set smoothing=true --set smoothing_strategy=local --set smoothing_clearance=0
        # or the default, with or without --set turn_curve=clothoid, or smoothing=false
    coverage_tool simulate {m30} --trajectory DIR/trajectory.csv --out SIM \\
        {lake}

'''
        text += self.metrics_table('lake_30x30', [
            ('planned traversal time', lambda run, p: seconds(p['traversal_time_s'])),
            ('turns smoothed', lambda run, p: f"{p['turns_smoothed']} / {p['turns_total']}"),
        ])
        text += '\nPercentiles of the tracking error, metres (Table 4.2):\n\n'
        text += self.marker()
        text += '| | ' + ' | '.join('1st' if q == '1' else f'{q}th' for q in PERCENTILES)
        text += ' |\n|---|' + '---|' * len(PERCENTILES) + '\n'
        for strategy, label in STRATEGIES:
            metrics = sim[f'lake_30x30_{strategy}']
            text += f'| {label} | ' + ' | '.join(
                f"{metrics['tracking_error_percentiles_m'][q]:.3f}" for q in PERCENTILES) + ' |\n'
        text += '''| thesis unsmoothed | 0.01 | 0.03 | 0.04 | 0.07 | 0.13 | 0.23 | 0.34 | 0.47 | 0.63 |
| thesis smoothed | 0.01 | 0.02 | 0.03 | 0.05 | 0.08 | 0.13 | 0.21 | 0.28 | 0.54 |
'''
        thesis_percentiles = {
            'local': [0.01, 0.02, 0.03, 0.05, 0.08, 0.13, 0.21, 0.28, 0.54],
            'unsmoothed': [0.01, 0.03, 0.04, 0.07, 0.13, 0.23, 0.34, 0.47, 0.63]}

        def within_three(strategy):
            """The percentiles from the 50th to the 99th within a factor 3 of the thesis's."""
            ours = sim[f'lake_30x30_{strategy}']['tracking_error_percentiles_m']
            outside = [q for q, theirs in zip(PERCENTILES, thesis_percentiles[strategy])
                       if int(q) >= 50 and not theirs / 3 <= ours[q] <= 3 * theirs]
            if not outside:
                return 'all within a factor of 3'
            return 'outside a factor of 3: the ' + ', '.join(f'{q}th' for q in outside)

        text += f'''
Against Table 4.2, from the 50th to the 99th percentile: Algorithm 1's smoothed run
{within_three('local')}; the unsmoothed run {within_three('unsmoothed')}.

The thesis's two findings, turning in place is faster (the thesis: the unsmoothed run took
{ratio(thesis1['time'][1], thesis1['time'][0])} of the smoothed run's time) and the smoothed trajectory is tracked better (the thesis:
{change(*thesis1['error'])} error):

- Algorithm 1: the unsmoothed run takes {ratio(unsmoothed1[0], local1[0])} of the smoothed run's time (faster in place:
  {holds(unsmoothed1[0] < local1[0])}); error sum {metres(local1[1])} against {metres(unsmoothed1[1])}, {change(local1[1], unsmoothed1[1])}
  (tracked better: {holds(local1[1] < unsmoothed1[1])}).
- Default strategy: the unsmoothed run takes {ratio(unsmoothed1[0], default1[0])} of the smoothed run's time (faster in
  place: {holds(unsmoothed1[0] < default1[0])}); error sum {metres(default1[1])} against {metres(unsmoothed1[1])}, {change(default1[1], unsmoothed1[1])}
  (tracked better: {holds(default1[1] < unsmoothed1[1])}).
- Beyond the thesis, the default strategy with continuous-curvature turns
  (`turn_curve: clothoid`, {plan['lake_30x30_clothoid']['turns_clothoid']} of its {plan['lake_30x30_clothoid']['turns_smoothed']} smoothed turns clothoid-arc-clothoid): error sum
  {metres(clothoid1[1])} against {metres(unsmoothed1[1])}, {change(clothoid1[1], unsmoothed1[1])} (tracked better: {holds(clothoid1[1] < unsmoothed1[1])}), and
  {change(clothoid1[1], default1[1])} than with its arcs; 99th percentile {metres(sim['lake_30x30_clothoid']['tracking_error_percentiles_m']['99'], 3)} against {metres(sim['lake_30x30_default']['tracking_error_percentiles_m']['99'], 3)}. In the
  lake the navigation error and the longer run outweigh what the turns change. In calm
  water with exact navigation the clothoid turns' error sum is {change(calm_clothoid1[1], calm_default1[1])} than the
  arcs' ({metres(calm_clothoid1[1])} against {metres(calm_default1[1])}; tracked better than arcs: {holds(calm_clothoid1[1] < calm_default1[1])}); tracked better than
  unsmoothed ({metres(calm_unsmoothed1[1])}): {holds(calm_clothoid1[1] < calm_unsmoothed1[1])}.

Clearance, which the thesis does not measure: Algorithm 1 with the thesis's no-contact
check runs its arcs in the wall band (the planned trajectory comes within
{metres(plan['lake_30x30_local']['min_obstacle_clearance_m'], 3)} of a wall or obstacle), and with the lake's navigation error the robot drove
within {metres(sim['lake_30x30_local']['driven_min_clearance_m'], 3)} of one. The default strategy keeps its turns at the wall distance: it comes
no nearer than {metres(plan['lake_30x30_default']['min_obstacle_clearance_m'], 3)} planned and {metres(sim['lake_30x30_default']['driven_min_clearance_m'], 3)} driven, as the unsmoothed trajectory
({metres(plan['lake_30x30_unsmoothed']['min_obstacle_clearance_m'], 3)} planned, {metres(sim['lake_30x30_unsmoothed']['driven_min_clearance_m'], 3)} driven). With the thesis's check instead
(`--set smoothing_clearance=0`) the default strategy smooths
{plan['lake_30x30_no_contact']['turns_smoothed']} of {plan['lake_30x30_no_contact']['turns_total']} turns (against {plan['lake_30x30_default']['turns_smoothed']}), comes within {metres(plan['lake_30x30_no_contact']['min_obstacle_clearance_m'], 3)} planned and {metres(sim['lake_30x30_no_contact']['driven_min_clearance_m'], 3)}
driven, and takes {seconds(plan['lake_30x30_no_contact']['traversal_time_s'])} planned against {seconds(plan['lake_30x30_default']['traversal_time_s'])}.

Where the numbers differ from the thesis, and why:

- The percentiles are the lake's kind: the navigation error puts the median near the
  thesis's, and both trajectories share it, so it says little about the turns.
- The smoothed trajectory is not tracked better: the sums count one error per simulation
  step, so the slower run adds more of the same navigation error, and the arcs add their
  slip. The thesis's sums and percentiles imply about two samples per second; the vehicle
  was not tuned to reproduce its finding.
- Times are {ratio(local1[0], thesis1['time'][0])} (Algorithm 1) and {ratio(unsmoothed1[0], thesis1['time'][1])} (unsmoothed) times the thesis's. The
  model uses the planner's `v_max` and `a_max` (the thesis gives no speed or acceleration of
  Proteus), and with the navigation error it hunts near every pose: close to a pose, the
  navigation error turns the bearing to it by tenths of a radian, the high yaw gain turns that
  into a yaw-rate command near `yaw_rate_max`, and the shared thrust leaves no surge for
  it. In calm water with exact navigation (below) the same
  trajectories take {seconds(calm_local1[0])} and {seconds(calm_unsmoothed1[0])}; the lake's Proteus was not slowed this much, so
  its navigation error was smoother, or its controller steered through it, or it counted
  a pose as reached farther from it. The default `position_tolerance` (the first row of
  the table below) is half the navigation error's standard deviation, so the estimate wanders out of the tolerance
  of a pose it has reached (`simulate` warns of a tolerance under 3 standard deviations).
  The same runs with larger tolerances, a sensitivity study after the fact (the tables
  above keep the default):

'''
        text += self.tolerance_table()
        loose_local = sim[f'lake_30x30_local_tolerance_{TOLERANCES[-1]}']
        loose_unsmoothed = sim[f'lake_30x30_unsmoothed_tolerance_{TOLERANCES[-1]}']
        text += f'''
  With a tolerance of {TOLERANCES[-1]} m (three standard deviations) the hunting has mostly gone and the
  times (the last row) come near the thesis's: {ratio(loose_local['traversal_time_s'], thesis1['time'][0])} (Algorithm 1) and {ratio(loose_unsmoothed['traversal_time_s'], thesis1['time'][1])} (unsmoothed) times
  them; the smoothed trajectory is tracked better there:
  {holds(loose_local['tracking_error_sum_m'] < loose_unsmoothed['tracking_error_sum_m'])}.
- In calm water with exact navigation the straight sweeps have no error at all: the
  unsmoothed robot brakes to a stop on each corner and turns there, and the smoothed one
  lags on its arcs; tracked better when smoothed: {holds(calm_local1[1] < calm_unsmoothed1[1])}. The kinematic vehicle, whose speed and yaw rate
  follow their commands at once, stays on the arcs within millimetres:

'''
        text += self.conditions_table('lake_30x30')
        text += f'''
Smoothed by Algorithm 1, by the default strategy, by the default strategy with clothoid
turns, and unsmoothed (left to right): the desired trajectory in black, the path the robot drove coloured by its tracking error, over
the heatmap of what its sensor saw.

<img src="images/experiments_lake_30x30_local.png" width="24%"> <img src="images/experiments_lake_30x30_default.png" width="24%"> <img src="images/experiments_lake_30x30_clothoid.png" width="24%"> <img src="images/experiments_lake_30x30_unsmoothed.png" width="24%">

As the thesis's figures, Algorithm 1 (left) against unsmoothed (right). The planned
trajectories over the heatmaps of what they let the sensor see (Fig. 4.2):

<img src="images/experiments_lake_30x30_local_plan.png" width="48%"> <img src="images/experiments_lake_30x30_unsmoothed_plan.png" width="48%">

The desired trajectory in red and the poses the robot drove as black arrows, about one a
second (Fig. 4.3):

<img src="images/experiments_lake_30x30_local_poses.png" width="48%"> <img src="images/experiments_lake_30x30_unsmoothed_poses.png" width="48%">

The error statistics (Fig. 4.5): the histogram of the error with its normal fit, the
histograms of its x and y parts, and the x, y and Euclidean errors over time:

<img src="images/experiments_lake_30x30_local_errors.png" width="48%"> <img src="images/experiments_lake_30x30_unsmoothed_errors.png" width="48%">

## Experiment 2: lake_7_5, low yaw gain, finer rotations (Table 4.3)

Mission `{m7}` (a {extent('lake_7_5')} map with many turns and an
obstacle beside the lanes, {figure(m7, 'turning_radius', 'm')} turning radius). Robot, the same for every trajectory:
as in experiment 1 but `yaw_gain` {setting(SCRIPT, 'yaw_gain'):g} 1/s (from {setting(DEFAULTS, 'yaw_gain'):g}) and `rotation_sampling_angle`
{figure(SCRIPT, 'rotation_sampling_angle', 'rad')} (from {setting(DEFAULTS, 'rotation_sampling_angle'):g}: twice as many poses on each in-place rotation), the
thesis's two changes; in the lake.

    coverage_tool plan {m7} --out DIR --set smoothing=true \\
        --set smoothing_strategy=local --set smoothing_clearance=0 \\
        {low_gain}
    coverage_tool simulate {m7} --trajectory DIR/trajectory.csv --out SIM \\
        {low_gain} \\
        {lake}

'''
        text += self.metrics_table('lake_7_5', [
            ('trajectory error (99th percentile)',
             lambda run, p: metres(run['tracking_error_percentiles_m']['99'], 3)),
            ('turns smoothed', lambda run, p: f"{p['turns_smoothed']} / {p['turns_total']}"),
        ])
        text += f'''
The smoothed trajectories see less of the lake bottom as planned than the unsmoothed one
({percent(plan['lake_7_5_default']['coverage_loss_percent'])} unseen with the default strategy against {percent(plan['lake_7_5_unsmoothed']['coverage_loss_percent'])}; of what the unsmoothed trajectory sees, the default
one misses {plan['lake_7_5_default']['smoothing_lost_area_m2']:.3f} m^2, and `plan` warns of it), almost all of it outside the reachable area
({plan['lake_7_5_default']['smoothing_lost_reachable_area_m2']:.3f} m^2 of it reachable, of {plan['lake_7_5_default']['unreachable_area_m2']:.2f} m^2 outside the reachable area): here the
footprint is {metres(width)} wide and {metres(length)} long, so the reachable area reaches only {metres(length / 2)}
beyond the {figure(m7, 'wall_distance', 'm')} wall distance, while the unsmoothed path, running along the walls
between lanes and turning in place at the corners, sees more of the wall band. No stage
guards the area beyond the reachable area (docs/REFERENCE.md, Reachable area).

The thesis's reversal, the smoothed trajectory now the faster one (the thesis: {ratio(*thesis2['time'])} of the
unsmoothed run's time):

- Algorithm 1: {ratio(local2[0], unsmoothed2[0])} of the unsmoothed run's time ({holds(local2[0] < unsmoothed2[0])}).
- Default strategy: {ratio(default2[0], unsmoothed2[0])} ({holds(default2[0] < unsmoothed2[0])}).
- Default strategy with clothoid turns ({plan['lake_7_5_clothoid']['turns_clothoid']} of {plan['lake_7_5_clothoid']['turns_smoothed']} turns: most legs here are too short for
  the longer turn): {ratio(clothoid2[0], unsmoothed2[0])} ({holds(clothoid2[0] < unsmoothed2[0])}), and it tracks better than the unsmoothed run: {metres(clothoid2[1])}
  against {metres(unsmoothed2[1])} ({holds(clothoid2[1] < unsmoothed2[1])}).
- In calm water with exact navigation: Algorithm 1 {ratio(calm_local2[0], calm_unsmoothed2[0])} of the unsmoothed run's time
  ({holds(calm_local2[0] < calm_unsmoothed2[0])}), the default strategy {ratio(calm_default2[0], calm_unsmoothed2[0])} ({holds(calm_default2[0] < calm_unsmoothed2[0])}), with clothoid turns
  {ratio(calm_clothoid2[0], calm_unsmoothed2[0])} ({holds(calm_clothoid2[0] < calm_unsmoothed2[0])}); the clothoid turns' error sum is {change(calm_clothoid2[1], calm_default2[1])} than the arcs'
  (tracked better than arcs: {holds(calm_clothoid2[1] < calm_default2[1])}); tracked better than unsmoothed ({metres(calm_clothoid2[1])} against {metres(calm_unsmoothed2[1])}): {holds(calm_clothoid2[1] < calm_unsmoothed2[1])}.

It comes from the robot, not from the map: the same map with experiment 1's robot
(`yaw_gain` {setting(DEFAULTS, 'yaw_gain'):g}, `rotation_sampling_angle` {setting(DEFAULTS, 'rotation_sampling_angle'):g}):

'''
        text += self.marker()
        text += '| robot | ' + ' | '.join(label for _, label in STRATEGIES) + ' |\n|---|'
        text += '---|' * len(STRATEGIES) + '\n'
        text += '| traversing time, experiment 1 robot | ' + ' | '.join(
            seconds(time) for time, _ in (local3, default3, clothoid3, unsmoothed3)) + ' |\n'
        text += '| traversing time, experiment 2 robot | ' + ' | '.join(
            seconds(time) for time, _ in (local2, default2, clothoid2, unsmoothed2)) + ' |\n'
        text += f'''
With experiment 1's robot, turning in place is faster than Algorithm 1's smoothing:
{holds(unsmoothed3[0] < local3[0])}; than the default strategy's: {holds(unsmoothed3[0] < default3[0])}.

Where the numbers differ from the thesis, and why:

- The thesis's smoothed run tracked worse ({change(*thesis2['error'])} error). In the lake the
  smoothed run tracks worse under Algorithm 1: {holds(local2[1] > unsmoothed2[1])}; under the default strategy:
  {holds(default2[1] > unsmoothed2[1])}. The unsmoothed robot stops at every corner and turns in place there,
  slowly with the low yaw gain and twice the rotation poses, while the unknown current
  and the navigation error push it off the corner: every simulation step of the turn adds its offset to the sum. In calm
  water with exact navigation there is nothing to push it, the unsmoothed robot turns on
  the path, and the smoothed one lags on the tight arcs with the low gain: there
  the smoothed run tracks worse ({holds(calm_local2[1] > calm_unsmoothed2[1])}, {metres(calm_local2[1])} against {metres(calm_unsmoothed2[1])}). The thesis's
  reversal thus appears {where_reversal(local2[1] > unsmoothed2[1], calm_local2[1] > calm_unsmoothed2[1])}
  under Algorithm 1; neither vehicle nor lake was tuned to reproduce it.

'''
        text += self.conditions_table('lake_7_5')
        text += f'''
- The planned times order the trajectories otherwise: {seconds(plan['lake_7_5_local']['traversal_time_s'])} (Algorithm 1),
  {seconds(plan['lake_7_5_default']['traversal_time_s'])} (default) and {seconds(plan['lake_7_5_unsmoothed']['traversal_time_s'])} (unsmoothed) by the planner's velocity model, in
  which an arc is driven at `yaw_rate_max` times its radius. The default strategy takes
  its turns at up to `max_turning_radius` ({largest_radius:g} m here, where that keeps coverage), which the
  planner drives at full speed and full yaw rate; the robot model shares thrust between
  surge and yaw and has no surge left at full yaw rate, so it slows to about half speed on
  those arcs, and its set-point controller slows it towards every pose along them.
- The coverage loss is a few percent here even for the planned trajectories: with the
  sensor {figure(m7, 'sensor_distance', 'm')} above the bottom, the strips along the walls, the map's corners and a
  strip beside the obstacle lie beyond the footprints (the red cells); the thesis reports
  no loss for its map of that size (the table's thesis columns), whose sensor height and
  wall offset it does not state.

<img src="images/experiments_lake_7_5_local.png" width="24%"> <img src="images/experiments_lake_7_5_default.png" width="24%"> <img src="images/experiments_lake_7_5_clothoid.png" width="24%"> <img src="images/experiments_lake_7_5_unsmoothed.png" width="24%">

Algorithm 1 (left) against unsmoothed (right): the planned trajectories over their
heatmaps, the driven poses and the error statistics.

<img src="images/experiments_lake_7_5_local_plan.png" width="48%"> <img src="images/experiments_lake_7_5_unsmoothed_plan.png" width="48%">

<img src="images/experiments_lake_7_5_local_poses.png" width="48%"> <img src="images/experiments_lake_7_5_unsmoothed_poses.png" width="48%">

<img src="images/experiments_lake_7_5_local_errors.png" width="48%"> <img src="images/experiments_lake_7_5_unsmoothed_errors.png" width="48%">

## A constant current

The thesis's outlook asks for trials "in an underwater environment with stronger water
currents". The default-strategy lake_30x30 trajectory of experiment 1, followed by the same
robot in the same lake with a mean current of {mean_current} added
(`{script_settings('current')}`):

'''
        text += self.marker()
        text += f'''| metric | no mean current | mean current {mean_current} |
|---|---|---|
| traversing time | {seconds(calm['traversal_time_s'])} | {seconds(drift['traversal_time_s'])} |
| trajectory error (sum) | {metres(calm['tracking_error_sum_m'])} | {metres(drift['tracking_error_sum_m'])} |
| trajectory error (mean) | {metres(calm['tracking_error_mean_m'], 4)} | {metres(drift['tracking_error_mean_m'], 4)} |
| trajectory error (99th percentile) | {metres(calm['tracking_error_percentiles_m']['99'], 3)} | {metres(drift['tracking_error_percentiles_m']['99'], 3)} |
| coverage (actual poses) | {percent(calm['coverage_percent'])} | {percent(drift['coverage_percent'])} |

The robot crabs into the current to hold its line, which turns its sensor footprint, and
drifts off its sweeps wherever it slows down (at every pose it is handed, and while it
turns in place). The tracking error grows and coverage drops; the plot shows where: the
red cells along the southern wall, which the first sweep, carried north, no longer
reaches, and the lighter (seen once) stripes between the sweeps.

<img src="images/experiments_lake_30x30_current.png" width="70%">
'''
        return text + self.study_section()

    def study_section(self):
        """Both experiments as a sensitivity study of the controllers: controller_study's
        paragraphs (wrapped) and tables (each with its marker), after a word on why."""
        planned = [ratio(self.plan[f'{mission}_local']['traversal_time_s'],
                         self.plan[f'{mission}_unsmoothed']['traversal_time_s'])
                   for mission in ('lake_30x30', 'lake_7_5')]
        text = f'''
## The controllers: both experiments as a sensitivity study

The thesis ran one run per condition and does not state its controller, how its poses were
released in time, its error sampling or its metric, so its numbers cannot be reproduced; the
study asks instead under which controllers and settings its trends appear. The simulator's
controllers (docs/REFERENCE.md, simulate): `setpoint`, the follower of the tables above,
homing on each pose in turn; `timed`, the default, feedforward plus PD on the planner's
times; `pose_stream`, the same tracker on poses released at a fixed rate; `los`,
line-of-sight guidance at the reference's speed. In the planner's own times the smoothed
trajectory takes {planned[0]} (experiment 1) and {planned[1]} (experiment 2) of the unsmoothed
one's time, which is what a controller that follows those times drives.

    scripts/run_experiments.sh   # runs build/devel/lib/kinematic_coverage/controller_study on the trajectories above

'''
        for block in self.study.strip().split('\n\n'):
            if block.startswith('|'):
                text += self.marker() + block + '\n\n'
            else:
                text += textwrap.fill(block, width=92, break_long_words=False,
                                      break_on_hyphens=False) + '\n\n'
        return text.rstrip('\n') + '\n'


if __name__ == '__main__':
    main()
