#!/usr/bin/python3
"""rviz Draw Polygon rostest: the survey area drawn in the real rviz (config/rviz/pipeline.rviz,
a TopDownOrtho view of known scale) with xdotool under Xvfb, then planned. The test presses
`p` and clicks a 26 m square hull (with a stray vertex deleted by Shift + click before the
ring is closed by a click on its first vertex) and a 6 m square hole in its middle (closed
by a right click). It then drags a hole vertex across the hole, which makes the hole
self-intersecting, and back. The published `polygon` must equal the clicked rings within one
pixel in metres, arrive once per valid closed state and never for an open or invalid one,
whose validator message rviz's log names. After Set Start, Set Goal and Activate (Alt+A),
coverage_planner and smooth_trajectory_generator must give a `trajectory` whose every pose
lies inside the hull and outside the hole. Screenshots (the invalid drawing, the end) and
rviz's log are kept in `~artifact_dir`. Without a DISPLAY the test skips."""

import os
import sys
import time

import rospy
import rostest
import yaml
from geometry_msgs.msg import PointStamped, PoseArray
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from std_msgs.msg import Empty

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, inside_ring  # noqa: E402
from rviz_gui_support import (RvizTestCase, check_gui_programs,  # noqa: E402
                              default_artifact_dir, start_rviz, top_down_view)

# Points clicked, in metres in the map frame, inside the view of pipeline.rviz.
HULL = [(2.0, 2.0), (28.0, 2.0), (28.0, 28.0), (2.0, 28.0)]
HOLE = [(12.0, 12.0), (18.0, 12.0), (18.0, 18.0), (12.0, 18.0)]
# Clicked into the hull after its second vertex, then deleted with Shift + click.
STRAY = (20.0, 8.0)
# Hole vertex 1 dragged here: its edge to vertex 2 crosses the edge from vertex 3 to 0.
CROSSED = (9.0, 15.0)
# A right click here, away from every vertex, closes the open ring.
CENTRE = (15.0, 15.0)
# Inside the hull's free area (1 m wall distance) and away from the hole.
START = (4.0, 4.0)
GOAL = (26.0, 26.0)

MESSAGE_TIMEOUT_S = 10.0
PLAN_TIMEOUT_S = 60.0
# A polygon published for an edit would have arrived by then.
QUIET_S = 1.0
INVALID_HOLE = 'the polygon is invalid and not published: hole 0 is self-intersecting'


class PolygonToolTest(RvizTestCase):
    TEST_NAME = 'polygon_tool'

    @classmethod
    def start_rviz(cls):
        """Starts rviz and waits until its render window settled and its tools publish."""
        check_gui_programs()
        rospy.init_node('polygon_tool_test')
        cls.artifact_dir = rospy.get_param('~artifact_dir', '') or default_artifact_dir()
        os.makedirs(cls.artifact_dir, exist_ok=True)
        config_path = rospy.get_param('~rviz_config')
        with open(config_path) as stream:
            view = top_down_view(yaml.safe_load(stream), config_path)
        cls.status = Collector('coverage_planner/status', PlanStatus)
        cls.smoother_status = Collector('smooth_trajectory_generator/status', PlanStatus)
        cls.trajectory = Collector('trajectory', PoseArray)
        log_path = os.path.join(cls.artifact_dir, 'polygon_tool_rviz.log')
        cls.rviz = start_rviz(config_path, log_path, view)
        cls.addClassCleanup(cls.rviz.stop)
        # Subscribed once the window settled, as rviz_tool_test.py explains (2D Nav Goal).
        cls.polygon = Collector('polygon', PolygonWithHolesStamped)
        cls.start = Collector('start', PointStamped)
        cls.goal = Collector('goal', PointStamped)
        cls.activate = Collector('activate', Empty)
        cls.rviz.wait_for_publishers((cls.polygon, cls.start, cls.goal, cls.activate))

    def setUp(self):
        self.check_setup()

    def screenshot(self, name):
        self.rviz.screenshot(os.path.join(self.artifact_dir, name))

    def assert_polygon(self, count, hull_pixels, hole_pixels):
        """Waits for polygon message `count`, asserts that no other follows within QUIET_S
        and that it holds the rings clicked at these pixels, within one pixel in metres."""
        self.assertTrue(self.polygon.wait_for(count, MESSAGE_TIMEOUT_S),
                        'no polygon message %d; see %s' % (count, self.rviz.log_path))
        time.sleep(QUIET_S)
        self.assertEqual(len(self.polygon.messages), count, 'one polygon per valid edit')
        message = self.polygon.messages[-1]
        self.assertEqual(message.header.frame_id, 'map')
        rings = [message.polygon.hull] + list(message.polygon.holes)
        self.assertEqual(len(rings), 1 + len(hole_pixels))
        resolution = 1.0 / self.rviz.viewport.scale
        for ring, pixels in zip(rings, [hull_pixels] + hole_pixels):
            self.assertEqual(len(ring.points), len(pixels))
            for point, pixel in zip(ring.points, pixels):
                expected = self.rviz.viewport.metres(pixel)
                self.assertAlmostEqual(point.x, expected[0], delta=resolution)
                self.assertAlmostEqual(point.y, expected[1], delta=resolution)
        return [[(point.x, point.y) for point in ring.points] for ring in rings]

    def draw_hull(self):
        """Clicks the hull with a stray vertex deleted on the way; closes it on its first
        vertex. Returns the pixels of the hull's vertices."""
        pixels = [self.rviz.click(point) for point in HULL[:2]]
        self.rviz.click(STRAY)
        self.rviz.click(STRAY, modifier='shift')
        pixels += [self.rviz.click(point) for point in HULL[2:]]
        time.sleep(QUIET_S)
        self.assertEqual(len(self.polygon.messages), 0, 'an open ring was published')
        self.rviz.click(HULL[0])
        return pixels

    def draw_hole(self):
        """Clicks the hole and closes it with a right click; returns its vertices' pixels."""
        pixels = [self.rviz.click(point) for point in HOLE]
        time.sleep(QUIET_S)
        self.assertEqual(len(self.polygon.messages), 1, 'an open ring was published')
        self.rviz.click(CENTRE, button=3)
        return pixels

    def set_start_goal_and_activate(self):
        self.rviz.key('s')
        self.rviz.click(START)
        self.assertTrue(self.start.wait_for(1, MESSAGE_TIMEOUT_S), 'no start after its click')
        self.rviz.key('g')
        self.rviz.click(GOAL)
        self.assertTrue(self.goal.wait_for(1, MESSAGE_TIMEOUT_S), 'no goal after its click')
        self.rviz.key('alt+a')
        self.assertTrue(self.activate.wait_for(1, MESSAGE_TIMEOUT_S),
                        'the Activate button (Alt+A) published nothing on activate')

    def test_drawn_polygon_is_published_when_valid_and_planned_around_its_hole(self):
        self.addCleanup(self.screenshot, 'polygon_tool.png')
        self.rviz.focus()
        self.rviz.key('p')
        hull_pixels = self.draw_hull()
        self.assert_polygon(1, hull_pixels, [])
        hole_pixels = self.draw_hole()
        drawn = self.assert_polygon(2, hull_pixels, [hole_pixels])

        # An invalid edit is drawn red, named in rviz's log (and status bar), not published.
        self.rviz.drag(HOLE[1], CROSSED)
        time.sleep(QUIET_S)
        self.screenshot('polygon_tool_invalid.png')
        self.assertEqual(len(self.polygon.messages), 2, 'an invalid polygon was published')
        self.assertIn(INVALID_HOLE, self.rviz.log())
        self.rviz.drag(CROSSED, HOLE[1])
        self.assertEqual(self.assert_polygon(3, hull_pixels, [hole_pixels]), drawn)

        self.set_start_goal_and_activate()
        self.assertTrue(self.trajectory.wait_for(1, PLAN_TIMEOUT_S),
                        'no trajectory after activate; planner: %s; smoother: %s' % (
                            [status.message for status in self.status.messages],
                            [status.message for status in self.smoother_status.messages]))
        self.addCleanup(time.sleep, 1.0)  # rviz draws the plan before the screenshot
        hull, hole = drawn
        poses = self.trajectory.messages[-1].poses
        self.assertGreater(len(poses), 10)
        outside_hull = [pose.position for pose in poses
                        if not inside_ring((pose.position.x, pose.position.y), hull)]
        inside_hole = [pose.position for pose in poses
                       if inside_ring((pose.position.x, pose.position.y), hole)]
        self.assertEqual(outside_hull, [], 'trajectory poses outside the drawn hull')
        self.assertEqual(inside_hole, [], 'trajectory poses inside the drawn hole')


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'polygon_tool', PolygonToolTest)
