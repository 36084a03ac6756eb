#!/usr/bin/env python3
"""The stage graph of the core and the nodes: which stage folder includes which.

Every folder of polygon_coverage_ros_bridge/ and trajectory_generation_tools/ is a stage.
An edge A -> B means that a source of A includes a header of B. The floors (FLOORS) are the
stages each stage may include, the architecture of docs/ARCHITECTURE.md; an edge outside
them is a violation.

  scripts/stage_graph.py           prints the graph and the known violations as Markdown
                                   tables (docs/ARCHITECTURE.md)
  scripts/stage_graph.py --check   exits 1 on an edge that is neither allowed nor one of the
                                   known violations (KNOWN_VIOLATIONS), on a known
                                   violation that is gone (so the list only shrinks), on a
                                   ROS, rviz or Qt header in the core, on CGAL in a header
                                   that node code includes, and on the core in rviz_plugins/
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HALVES = ('polygon_coverage_ros_bridge', 'trajectory_generation_tools')
INCLUDE = re.compile(r'^\s*#\s*include\s+"((?:' + '|'.join(HALVES) + r')/[a-z_]+)/[^"]+"')

# The floors, lowest first: each stage with the stages it may include. The base floor
# (geometry, base) is below both halves; the tool and the ROS adapters are above them.
FLOORS = {
    'polygon_coverage_ros_bridge/geometry': set(),
    'polygon_coverage_ros_bridge/base': {'geometry'},
    'polygon_coverage_ros_bridge/validation': {'geometry', 'base'},
    'polygon_coverage_ros_bridge/decomposition': {'geometry', 'base'},
    'polygon_coverage_ros_bridge/sweeps': {'geometry', 'base', 'decomposition'},
    'polygon_coverage_ros_bridge/route': {'geometry', 'base'},
    'polygon_coverage_ros_bridge/gtsp': {'geometry', 'base'},
    'trajectory_generation_tools/path': {'geometry', 'base'},
    'trajectory_generation_tools/coverage': {'geometry', 'base', 'sweeps'},
    'polygon_coverage_ros_bridge/repair': {'geometry', 'base', 'sweeps', 'route', 'coverage'},
    'polygon_coverage_ros_bridge/planner': {'geometry', 'base', 'validation', 'decomposition',
                                            'sweeps', 'route', 'gtsp', 'repair'},
    'trajectory_generation_tools/smoothing': {'geometry', 'base', 'sweeps', 'path'},
    'trajectory_generation_tools/trajectory': {'geometry', 'base', 'path', 'smoothing'},
    'trajectory_generation_tools/plot': {'geometry', 'base', 'sweeps', 'coverage'},
    'trajectory_generation_tools/simulation': {'geometry', 'base', 'validation', 'path'},
    'trajectory_generation_tools/replanning': {'geometry', 'base', 'validation', 'sweeps',
                                               'coverage', 'planner'},
    'polygon_coverage_ros_bridge/mission': {'geometry', 'base', 'validation', 'sweeps',
                                            'planner', 'coverage', 'smoothing', 'trajectory',
                                            'plot', 'simulation', 'replanning'},
    'polygon_coverage_ros_bridge/tool': {'geometry', 'base', 'gtsp', 'mission'},
    'polygon_coverage_ros_bridge/ros': {'geometry', 'base', 'mission', 'planner', 'trajectory'},
    'trajectory_generation_tools/ros': {'geometry', 'base', 'validation', 'sweeps', 'planner',
                                        'mission', 'coverage', 'path', 'plot', 'replanning',
                                        'simulation', 'trajectory', 'polygon_coverage_ros_bridge/ros'},
}

# Edges the floors do not allow yet, each with what removes it. The check fails on any
# other violation, and on an entry here that the code no longer has.
KNOWN_VIOLATIONS = {
    ('polygon_coverage_ros_bridge/validation', 'polygon_coverage_ros_bridge/planner'):
        'PlannerParameters: validation checks the flat parameter set; stage options instead',
    ('polygon_coverage_ros_bridge/sweeps', 'polygon_coverage_ros_bridge/planner'):
        'PlannerParameters: the sensor reads the flat parameter set; stage options instead',
    ('polygon_coverage_ros_bridge/route', 'polygon_coverage_ros_bridge/planner'):
        'PlannerParameters: the segment cost reads the flat parameter set; stage options instead',
    ('trajectory_generation_tools/smoothing', 'polygon_coverage_ros_bridge/planner'):
        'PlannerParameters: the smoothing options read the flat parameter set',
    ('trajectory_generation_tools/trajectory', 'polygon_coverage_ros_bridge/planner'):
        'PlannerParameters: the trajectory generator reads the flat parameter set',
    ('trajectory_generation_tools/simulation', 'polygon_coverage_ros_bridge/planner'):
        'PlannerParameters: the robot model reads the flat parameter set',
}


def qualified(stage, name):
    """The stage `name` (short, as in FLOORS, or qualified) as seen from `stage`."""
    if '/' in name:
        return name
    for half in HALVES:
        if f'{half}/{name}' in FLOORS:
            return f'{half}/{name}'
    raise KeyError(f'{stage}: unknown stage {name} in FLOORS')


def stages():
    found = []
    for half in HALVES:
        for name in sorted(os.listdir(os.path.join(ROOT, half))):
            if os.path.isdir(os.path.join(ROOT, half, name)):
                found.append(f'{half}/{name}')
    return found


def edges():
    """{stage: {included stage: number of include lines}}."""
    graph = {}
    for stage in stages():
        counts = graph.setdefault(stage, {})
        folder = os.path.join(ROOT, stage)
        for name in sorted(os.listdir(folder)):
            if not name.endswith(('.h', '.cpp')):
                continue
            with open(os.path.join(folder, name), encoding='utf-8') as source:
                for line in source:
                    match = INCLUDE.match(line)
                    if match and match.group(1) != stage:
                        counts[match.group(1)] = counts.get(match.group(1), 0) + 1
    return graph


def allowed(stage):
    return {qualified(stage, name) for name in FLOORS.get(stage, set())}


def short(stage):
    half, name = stage.split('/')
    return ('poly/' if half == HALVES[0] else 'traj/') + name


def print_graph(graph):
    print('| stage | may include (its floor) | includes (include lines) | includes beyond its floor |')
    print('|---|---|---|---|')
    for stage in FLOORS:
        if stage not in graph:
            continue
        used = graph[stage]
        may = allowed(stage)
        floor = ', '.join(short(t) for t in sorted(may, key=short))
        includes = ', '.join(f'{short(t)} ({used[t]})' for t in sorted(used, key=short))
        beyond = ', '.join(short(t) for t in sorted(set(used) - may, key=short))
        print(f'| {short(stage)} | {floor or "-"} | {includes or "-"} | {beyond or "-"} |')
    print()
    print('| stage | includes, beyond its floor | why, and what removes it |')
    print('|---|---|---|')
    for (stage, target), why in KNOWN_VIOLATIONS.items():
        print(f'| {short(stage)} | {short(target)} | {why} |')


# System headers the core must not include: ROS, its messages and tools, rviz, Qt, Ogre.
ROS_HEADER = re.compile(r'^\s*#\s*include\s+<(ros/|rviz/|pluginlib/|tf2|std_msgs/|std_srvs/|'
                        r'geometry_msgs/|nav_msgs/|visualization_msgs/|kinematic_coverage/|'
                        r'Q[A-Za-z]|Ogre)')
CGAL_HEADER = re.compile(r'^\s*#\s*include\s+<CGAL/')
PROJECT_HEADER = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
NODE_STAGES = ('polygon_coverage_ros_bridge/ros', 'trajectory_generation_tools/ros')


def lines_of(path):
    with open(os.path.join(ROOT, path), encoding='utf-8') as source:
        return source.read().splitlines()


def sources(folder):
    return [f'{folder}/{name}' for name in sorted(os.listdir(os.path.join(ROOT, folder)))
            if name.endswith(('.h', '.cpp'))]


def rule_problems():
    """The three rules beside the floors: no ROS in the core, no CGAL in a header that
    node code includes (directly or through other headers), no core in rviz_plugins/."""
    problems = []
    for stage in stages():
        if stage in NODE_STAGES:
            continue
        for path in sources(stage):
            if any(ROS_HEADER.match(line) for line in lines_of(path)):
                problems.append(f'{path} includes a ROS, rviz or Qt header in the core')
    seen = set()
    pending = [match.group(1) for stage in NODE_STAGES for path in sources(stage)
               for match in map(PROJECT_HEADER.match, lines_of(path)) if match]
    while pending:
        header = pending.pop()
        if header in seen or not header.startswith(HALVES) or \
                not os.path.exists(os.path.join(ROOT, header)):
            continue
        seen.add(header)
        for line in lines_of(header):
            if CGAL_HEADER.match(line):
                problems.append(f'{header} includes CGAL and node code includes it')
            match = PROJECT_HEADER.match(line)
            if match:
                pending.append(match.group(1))
    for path in sources('rviz_plugins'):
        for line in lines_of(path):
            match = PROJECT_HEADER.match(line)
            if match and match.group(1).startswith(HALVES):
                problems.append(f'{path} includes the core ({match.group(1)})')
    return problems


def check(graph):
    problems = rule_problems()
    for stage in graph:
        if stage not in FLOORS:
            problems.append(f'{stage}: a stage folder without a floor in scripts/stage_graph.py')
            continue
        for target in graph[stage]:
            if target not in allowed(stage) and (stage, target) not in KNOWN_VIOLATIONS:
                problems.append(f'{stage} includes {target}, which is not below it')
    for (stage, target) in KNOWN_VIOLATIONS:
        if target not in graph.get(stage, {}):
            problems.append(f'{stage} no longer includes {target}: remove it from '
                            'KNOWN_VIOLATIONS')
    for problem in problems:
        print(f'stage_graph: {problem}', file=sys.stderr)
    if not problems:
        print(f'stage_graph: {sum(len(t) for t in graph.values())} edges between '
              f'{len(graph)} stages, {len(KNOWN_VIOLATIONS)} known violations left',
              file=sys.stderr)
    return 1 if problems else 0


def main(arguments):
    if arguments not in ([], ['--check']):
        print(__doc__, file=sys.stderr)
        return 2
    graph = edges()
    if arguments == ['--check']:
        return check(graph)
    print_graph(graph)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
