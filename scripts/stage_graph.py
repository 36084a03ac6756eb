#!/usr/bin/env python3
"""The stage graph of the core and the nodes: which stage folder includes which.

Every folder of the two halves (polygon_coverage_ros_bridge/, trajectory_generation_tools/)
and of the compositions above them (coverage_system/) is a stage.
An edge A -> B means that a source of A includes a header of B. The floors (FLOORS) are the
stages each stage may include, the architecture of docs/ARCHITECTURE.md; an edge outside
them is a violation.

  scripts/stage_graph.py           prints the graph as a Markdown table (docs/ARCHITECTURE.md)
  scripts/stage_graph.py --check   exits 1 on an edge beyond a stage's floor, on a stage
                                   library whose CMake DEPENDS differ from the stage
                                   libraries it includes, on a ROS, rviz or Qt header in the
                                   core, and on CGAL in a header that node code or the rviz
                                   plugins include
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HALVES = ('polygon_coverage_ros_bridge', 'trajectory_generation_tools')
COMPOSITIONS = 'coverage_system'
FOLDERS = HALVES + (COMPOSITIONS,)
INCLUDE = re.compile(r'^\s*#\s*include\s+"((?:' + '|'.join(FOLDERS) + r')/[a-z_]+)/[^"]+"')

# The floors, lowest first: each stage with the stages it may include. The base floor
# (geometry, base) is below both halves; the compositions of coverage_system/ are above
# both: the parameters above every stage they map the flat parameter set to, the planner
# and missions above them, the tool and the ROS adapters on top. No stage of a half may
# include a composition.
LOWER_STAGES = {'geometry', 'base', 'validation', 'decomposition', 'sweeps', 'route', 'gtsp',
                'path', 'coverage', 'repair', 'smoothing', 'trajectory', 'plot', 'simulation',
                'replanning'}
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
    'trajectory_generation_tools/smoothing': {'geometry', 'base', 'sweeps', 'path'},
    'trajectory_generation_tools/trajectory': {'geometry', 'base', 'path', 'smoothing'},
    'trajectory_generation_tools/plot': {'geometry', 'base', 'sweeps', 'coverage'},
    'trajectory_generation_tools/simulation': {'geometry', 'base', 'validation', 'path'},
    'trajectory_generation_tools/replanning': {'geometry', 'base', 'validation', 'sweeps',
                                               'coverage'},
    'coverage_system/parameters': LOWER_STAGES,
    'coverage_system/planner': LOWER_STAGES | {'parameters'},
    'coverage_system/mission': LOWER_STAGES | {'parameters', 'planner'},
    'coverage_system/tool': LOWER_STAGES | {'parameters', 'planner', 'mission'},
    'coverage_system/ros': LOWER_STAGES | {'parameters', 'planner', 'mission'},
}

def qualified(stage, name):
    """The stage `name` (short, as in FLOORS, or qualified) as seen from `stage`."""
    if '/' in name:
        return name
    for folder in FOLDERS:
        if f'{folder}/{name}' in FLOORS:
            return f'{folder}/{name}'
    raise KeyError(f'{stage}: unknown stage {name} in FLOORS')


def stages():
    found = []
    for folder in FOLDERS:
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            if os.path.isdir(os.path.join(ROOT, folder, name)):
                found.append(f'{folder}/{name}')
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
    folder, name = stage.split('/')
    return {HALVES[0]: 'poly/', HALVES[1]: 'traj/', COMPOSITIONS: 'sys/'}[folder] + name


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


# System headers the core must not include: ROS, its messages and tools, rviz, Qt, Ogre.
ROS_HEADER = re.compile(r'^\s*#\s*include\s+<(ros/|rviz/|pluginlib/|tf2|std_msgs/|std_srvs/|'
                        r'geometry_msgs/|nav_msgs/|visualization_msgs/|kinematic_coverage/|'
                        r'Q[A-Za-z]|Ogre)')
CGAL_HEADER = re.compile(r'^\s*#\s*include\s+<CGAL/')
PROJECT_HEADER = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
NODE_STAGES = ('coverage_system/ros',)


def lines_of(path):
    with open(os.path.join(ROOT, path), encoding='utf-8') as source:
        return source.read().splitlines()


def sources(folder):
    return [f'{folder}/{name}' for name in sorted(os.listdir(os.path.join(ROOT, folder)))
            if name.endswith(('.h', '.cpp'))]


def rule_problems():
    """The two rules beside the floors: no ROS in the core, no CGAL in a header that node
    code or the rviz plugins (thin adapters both) include, directly or through other
    headers."""
    problems = []
    for stage in stages():
        if stage in NODE_STAGES:
            continue
        for path in sources(stage):
            if any(ROS_HEADER.match(line) for line in lines_of(path)):
                problems.append(f'{path} includes a ROS, rviz or Qt header in the core')
    seen = set()
    pending = [match.group(1) for stage in NODE_STAGES + ('rviz_plugins',)
               for path in sources(stage)
               for match in map(PROJECT_HEADER.match, lines_of(path)) if match]
    while pending:
        header = pending.pop()
        if header in seen or not header.startswith(FOLDERS) or \
                not os.path.exists(os.path.join(ROOT, header)):
            continue
        seen.add(header)
        for line in lines_of(header):
            if CGAL_HEADER.match(line):
                problems.append(f'{header} includes CGAL and node or rviz code includes it')
            match = PROJECT_HEADER.match(line)
            if match:
                pending.append(match.group(1))
    return problems


STAGE_LIBRARY = re.compile(r'kc_add_stage_library\((kc_[a-z_]+)(.*?)\)', re.S)


def library_of(stage):
    """The static library of a stage folder, from its sources.cmake (None: header-only
    or not a stage library), and the kc_ libraries it DEPENDS on."""
    path = os.path.join(ROOT, stage, 'sources.cmake')
    if not os.path.exists(path):
        return None, set()
    with open(path, encoding='utf-8') as listing:
        match = STAGE_LIBRARY.search(listing.read())
    if not match:
        return None, set()
    arguments = match.group(2).split()
    depends = arguments[arguments.index('DEPENDS') + 1:] if 'DEPENDS' in arguments else []
    return match.group(1), {name for name in depends if name.startswith('kc_')}


def library_problems(graph):
    """Each stage library must link (DEPENDS) exactly the stage libraries whose headers
    its sources include, so the link graph is the include graph."""
    problems = []
    for stage, used in graph.items():
        library, depends = library_of(stage)
        if library is None:
            continue
        included = {library_of(target)[0] for target in used} - {None}
        for missing in sorted(included - depends):
            problems.append(f'{stage}: {library} includes {missing} but does not list it in '
                            'DEPENDS (sources.cmake)')
        for extra in sorted(depends - included):
            problems.append(f'{stage}: {library} lists {extra} in DEPENDS but includes none '
                            'of its headers')
    return problems


def check(graph):
    problems = rule_problems()
    for stage in FLOORS:
        if not stage.startswith(COMPOSITIONS) and \
                any(target.startswith(COMPOSITIONS) for target in allowed(stage)):
            problems.append(f'{stage}: a stage of a half whose floor names a composition')
    for stage in graph:
        if stage not in FLOORS:
            problems.append(f'{stage}: a stage folder without a floor in scripts/stage_graph.py')
            continue
        for target in graph[stage]:
            if target not in allowed(stage):
                problems.append(f'{stage} includes {target}, which is not below it')
    problems += library_problems(graph)
    for problem in problems:
        print(f'stage_graph: {problem}', file=sys.stderr)
    if not problems:
        print(f'stage_graph: {sum(len(t) for t in graph.values())} edges between '
              f'{len(graph)} stages, every one within its floor, every stage library '
              'linking exactly the stages it includes', file=sys.stderr)
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
