#!/usr/bin/env python3
"""The vehicle's mission files of `coverage_tool plan AREA.geojson`, read back independently
of their writer: mission.plan with Python's json module as QGroundControl's Plan File Format
describes it, mission.waypoints as mavlink.io's plain-text QGC WPL 110 format does. Both
hold the same items; their waypoints run from the trajectory's first pose to its last, every
pose of trajectory.geojson lies near the waypoint path, and the depth and the corner-cutting
radius are the ones set.

  autopilot_mission_files_test.py COVERAGE_TOOL
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAKE = os.path.join(ROOT, 'config', 'missions', 'kleinhesseloher_see.geojson')
NAV_WAYPOINT = 16
DO_CHANGE_SPEED = 178
FRAME_GLOBAL_RELATIVE_ALT = 3
FRAME_MISSION = 2
DEPTH = 2.5
CORNER_CUTTING_RADIUS = 1.5
V_MAX = 0.5
# How far a pose of the trajectory may lie from the waypoint path: a turn's waypoints lie
# on it or on its tangent polygon, pi/8 of heading apart, within 1 / cos(pi/16) - 1, 2 %, of
# its radius (a few metres at most on this lake) from it.
POSE_TOLERANCE_M = 0.1
DEGREE_TOLERANCE = 1e-7


def metres(origin, point):
    """Local east-north metres of `point` [lon, lat] from `origin` (equirectangular, exact
    enough over a lake of a few hundred metres)."""
    scale = 111320.0
    return ((point[0] - origin[0]) * scale * math.cos(math.radians(origin[1])),
            (point[1] - origin[1]) * scale)


def segment_distance(p, a, b):
    ab = (b[0] - a[0], b[1] - a[1])
    length_sq = ab[0] ** 2 + ab[1] ** 2
    t = 0.0 if length_sq == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ab[0] +
                                                       (p[1] - a[1]) * ab[1]) / length_sq))
    return math.hypot(p[0] - a[0] - t * ab[0], p[1] - a[1] - t * ab[1])


class AutopilotMissionFilesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.mkdtemp()
        result = subprocess.run(
            [sys.argv[1], 'plan', LAKE, '--out', cls.directory, '--set',
             f'mission_depth={DEPTH}', '--set', f'corner_cutting_radius={CORNER_CUTTING_RADIUS}'],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert result.returncode == 0, result.stdout + result.stderr
        cls.log = result.stdout
        with open(os.path.join(cls.directory, 'mission.plan'), encoding='utf-8') as stream:
            cls.plan = json.load(stream)
        with open(os.path.join(cls.directory, 'mission.waypoints'), encoding='utf-8') as stream:
            cls.wpl = stream.read().splitlines()
        with open(os.path.join(cls.directory, 'trajectory.geojson'), encoding='utf-8') as stream:
            cls.trajectory = json.load(stream)['features'][0]['geometry']['coordinates']

    def plan_items(self):
        return self.plan['mission']['items']

    def test_the_plan_file_is_a_qgroundcontrol_plan(self):
        self.assertEqual(self.plan['fileType'], 'Plan')
        self.assertEqual(self.plan['version'], 1)
        mission = self.plan['mission']
        self.assertEqual(mission['version'], 2)
        self.assertEqual(len(mission['plannedHomePosition']), 3)
        self.assertEqual(self.plan['kinematic_coverage']['corner_cutting_radius_m'],
                         CORNER_CUTTING_RADIUS)
        for number, item in enumerate(self.plan_items(), start=1):
            self.assertEqual(item['type'], 'SimpleItem')
            self.assertEqual(item['doJumpId'], number)
            self.assertTrue(item['autoContinue'])
            self.assertEqual(len(item['params']), 7)
            if item['command'] == NAV_WAYPOINT:
                self.assertEqual(item['frame'], FRAME_GLOBAL_RELATIVE_ALT)
                self.assertEqual(item['params'][6], -DEPTH)
                self.assertEqual(item['params'][1], CORNER_CUTTING_RADIUS)
                self.assertIn(item['params'][0], (0, 1))
            else:
                self.assertEqual(item['command'], DO_CHANGE_SPEED)
                self.assertEqual(item['frame'], FRAME_MISSION)
                self.assertGreater(item['params'][1], 0.0)
                self.assertLessEqual(item['params'][1], V_MAX)

    def test_the_waypoints_file_holds_the_same_items(self):
        self.assertEqual(self.wpl[0], 'QGC WPL 110')
        home = self.wpl[1].split('\t')
        self.assertEqual(len(home), 12)
        self.assertEqual(home[:4], ['0', '1', '0', str(NAV_WAYPOINT)])
        lines = [line.split('\t') for line in self.wpl[2:]]
        self.assertEqual(len(lines), len(self.plan_items()))
        for index, (fields, item) in enumerate(zip(lines, self.plan_items()), start=1):
            self.assertEqual(len(fields), 12)
            self.assertEqual(int(fields[0]), index)
            self.assertEqual(int(fields[1]), 0)
            self.assertEqual(int(fields[2]), item['frame'])
            self.assertEqual(int(fields[3]), item['command'])
            for value, param in zip(fields[4:11], item['params']):
                self.assertAlmostEqual(float(value), param, places=12)
            self.assertEqual(fields[11], '1')

    def waypoints(self):
        """[lon, lat] of the NAV_WAYPOINT items, in order."""
        return [[item['params'][5], item['params'][4]] for item in self.plan_items()
                if item['command'] == NAV_WAYPOINT]

    def test_the_waypoints_follow_the_trajectory(self):
        waypoints = self.waypoints()
        for end in (0, -1):
            self.assertAlmostEqual(waypoints[end][0], self.trajectory[end][0],
                                   delta=DEGREE_TOLERANCE)
            self.assertAlmostEqual(waypoints[end][1], self.trajectory[end][1],
                                   delta=DEGREE_TOLERANCE)
        origin = waypoints[0]
        path = [metres(origin, p) for p in waypoints]
        segment = 0
        for pose in self.trajectory:
            p = metres(origin, pose)
            # Poses come in order: look from the last segment matched a little way on, and
            # along the whole path where the path comes back near itself.
            nearest, segment = min((segment_distance(p, path[k], path[k + 1]), k)
                                   for k in range(segment, min(segment + 40, len(path) - 1)))
            if nearest >= POSE_TOLERANCE_M:
                nearest, segment = min((segment_distance(p, path[k], path[k + 1]), k)
                                       for k in range(len(path) - 1))
            self.assertLess(nearest, POSE_TOLERANCE_M, f'pose {pose}')

    def test_the_log_states_the_corner_cutting_radius(self):
        self.assertIn(f'cuts each waypoint by {CORNER_CUTTING_RADIUS:g} m', self.log)
        self.assertIn('WPNAV_RADIUS to 150 cm', self.log)


class UnsmoothedMissionFilesTest(unittest.TestCase):
    """Without smoothing the vehicle drives the planner's waypoint path itself: every waypoint
    of waypoints.geojson is among the mission's waypoints, in order, within 1e-7 degrees
    (a smoothed plan's turns leave its corners, so there the trajectory test above holds)."""

    def test_every_planned_waypoint_is_a_mission_waypoint_in_order(self):
        directory = tempfile.mkdtemp()
        result = subprocess.run(
            [sys.argv[1], 'plan', LAKE, '--out', directory, '--set', 'smoothing=false', '--set',
             f'mission_depth={DEPTH}'], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(os.path.join(directory, 'mission.plan'), encoding='utf-8') as stream:
            items = json.load(stream)['mission']['items']
        with open(os.path.join(directory, 'waypoints.geojson'), encoding='utf-8') as stream:
            planned = json.load(stream)['features'][0]['geometry']['coordinates']
        mission = [[item['params'][5], item['params'][4]] for item in items
                   if item['command'] == NAV_WAYPOINT]
        self.assertGreater(len(planned), 10)
        found = 0
        for waypoint in planned:
            while found < len(mission) and not (
                    abs(mission[found][0] - waypoint[0]) <= DEGREE_TOLERANCE * 1.0001 and
                    abs(mission[found][1] - waypoint[1]) <= DEGREE_TOLERANCE * 1.0001):
                found += 1
            self.assertLess(found, len(mission), f'planned waypoint {waypoint} not in order')


if __name__ == '__main__':
    unittest.main(argv=sys.argv[:1])
