#!/usr/bin/env python3
"""scripts/stage_graph.py --check: the repository passes, and each kind of violation in a
copy of it fails (an include beyond a stage's floor, a stage library whose CMake DEPENDS
miss or exceed the stages it includes, a ROS header in the core, CGAL reaching node code
or the rviz plugins, a stage of a half including a composition of coverage_system/)."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FOLDERS = ('polygon_coverage_ros_bridge', 'trajectory_generation_tools', 'coverage_system',
           'rviz_plugins')


def run_check(root):
    return subprocess.run([sys.executable, os.path.join(root, 'scripts', 'stage_graph.py'),
                           '--check'], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True)


class StageGraphTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp()
        os.makedirs(os.path.join(self.directory, 'scripts'))
        shutil.copy(os.path.join(ROOT, 'scripts', 'stage_graph.py'),
                    os.path.join(self.directory, 'scripts'))
        for folder in FOLDERS:
            shutil.copytree(os.path.join(ROOT, folder), os.path.join(self.directory, folder))

    def tearDown(self):
        shutil.rmtree(self.directory)

    def append(self, path, line):
        with open(os.path.join(self.directory, path), 'a', encoding='utf-8') as source:
            source.write(line + '\n')

    def assert_fails_with(self, words):
        result = run_check(self.directory)
        self.assertEqual(result.returncode, 1, result.stderr)
        self.assertIn(words, result.stderr)

    def test_the_repository_passes(self):
        result = run_check(ROOT)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(run_check(self.directory).returncode, 0)

    def test_an_include_beyond_the_floor_fails(self):
        self.append('polygon_coverage_ros_bridge/geometry/planar_geometry.cpp',
                    '#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"')
        self.assert_fails_with('geometry includes polygon_coverage_ros_bridge/gtsp, '
                               'which is not below it')

    def test_a_half_including_a_composition_fails(self):
        self.append('trajectory_generation_tools/smoothing/corner.h',
                    '#include "coverage_system/parameters/planner_parameters.h"')
        self.assert_fails_with('trajectory_generation_tools/smoothing includes '
                               'coverage_system/parameters, which is not below it')

    def test_a_half_whose_floor_names_a_composition_fails(self):
        self.edit('scripts/stage_graph.py',
                  "'trajectory_generation_tools/path': {'geometry', 'base'}",
                  "'trajectory_generation_tools/path': {'geometry', 'base', 'planner'}")
        self.assert_fails_with('trajectory_generation_tools/path: a stage of a half whose '
                               'floor names a composition')

    def edit(self, path, old, new):
        path = os.path.join(self.directory, path)
        with open(path, encoding='utf-8') as source:
            text = source.read()
        self.assertIn(old, text)
        with open(path, 'w', encoding='utf-8') as source:
            source.write(text.replace(old, new))

    def test_a_stage_library_missing_a_stage_it_includes_fails(self):
        self.edit('polygon_coverage_ros_bridge/route/sources.cmake', 'DEPENDS kc_geometry',
                  'DEPENDS')
        self.assert_fails_with('kc_route includes kc_geometry but does not list it in DEPENDS')

    def test_a_stage_library_linking_a_stage_it_does_not_include_fails(self):
        self.edit('polygon_coverage_ros_bridge/route/sources.cmake', 'DEPENDS kc_geometry',
                  'DEPENDS kc_geometry kc_gtsp')
        self.assert_fails_with('kc_route lists kc_gtsp in DEPENDS but includes none')

    def test_a_ros_header_in_the_core_fails(self):
        self.append('trajectory_generation_tools/smoothing/corner.h', '#include <ros/ros.h>')
        self.assert_fails_with('corner.h includes a ROS, rviz or Qt header in the core')

    def test_cgal_reaching_node_code_fails(self):
        self.append('polygon_coverage_ros_bridge/geometry/polygon_with_holes.h',
                    '#include <CGAL/Polygon_2.h>')
        self.assert_fails_with(
            'polygon_with_holes.h includes CGAL and node or rviz code includes it')

    def test_cgal_reaching_the_rviz_plugins_fails(self):
        self.append('coverage_system/mission/polygon_sketch.h',
                    '#include <CGAL/Polygon_2.h>')
        self.assert_fails_with('polygon_sketch.h includes CGAL and node or rviz code includes it')


if __name__ == '__main__':
    unittest.main()
