#!/usr/bin/python3
"""rviz plugin rostest: the rviz Set Start / Set Goal tools and the Activate panel in the real
rviz, driven with xdotool under Xvfb (thesis Fig. 3.14: set and change start and goal, then
activate). The test publishes the lake's polygon, starts rviz with config/rviz/pipeline.rviz
(a TopDownOrtho view of known scale, so a pixel maps to known metres), picks Start by its
shortcut and clicks, picks Goal and clicks, picks Start again and clicks elsewhere, then
presses the Activate button (Alt+A). coverage_planner's waypoint_list must start at the
second start click and end at the goal click, within one pixel in metres. rviz's output
must hold no pluginlib error. rviz loads a copy of the config whose Set Start and Set Goal
tools name invalid topics ("bad topic!", "1abc"): the tools must refuse them, say so, and
keep publishing on their default topics, where the clicks above arrive. A screenshot and
rviz's log are kept in `~artifact_dir`. Without a DISPLAY the test skips."""

import os
import sys
import time

import rospy
import rostest
import yaml
from geometry_msgs.msg import Point32, PointStamped, Polygon, PoseArray
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from std_msgs.msg import Empty

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, load_mission  # noqa: E402
from rviz_gui_support import (PLUGIN_ERRORS, RvizTestCase,  # noqa: E402
                              check_gui_programs, default_artifact_dir, start_rviz,
                              top_down_view)

# Points clicked, in metres in the map frame: inside the lake's offset free area
# (config/missions/lake_30x30.yaml) and inside the view of pipeline.rviz.
FIRST_START = (27.0, 27.0)
GOAL = (27.0, 3.0)
SECOND_START = (3.0, 5.0)

MESSAGE_TIMEOUT_S = 10.0
PLAN_TIMEOUT_S = 30.0
# Topic names the config copy gives the tools: not valid ROS names (ros::names::validate).
INVALID_TOPICS = {'kinematic_coverage/SetStart': ('bad topic!', '/start'),
                  'kinematic_coverage/SetGoal': ('1abc', '/goal')}


def ring(points):
    return Polygon(points=[Point32(x=x, y=y, z=0.0) for x, y in points])


class RvizToolTest(RvizTestCase):
    TEST_NAME = 'rviz_tool'

    @classmethod
    def start_rviz(cls):
        """Publishes the polygon, starts rviz and waits until its render window settled and
        its tools publish."""
        check_gui_programs()
        rospy.init_node('rviz_tool_test')
        cls.artifact_dir = rospy.get_param('~artifact_dir', '') or default_artifact_dir()
        os.makedirs(cls.artifact_dir, exist_ok=True)
        cls.screenshot = os.path.join(cls.artifact_dir, 'rviz_tool.png')
        cls.rviz_log = os.path.join(cls.artifact_dir, 'rviz_tool_rviz.log')
        config_path = rospy.get_param('~rviz_config')
        with open(config_path) as stream:
            config = yaml.safe_load(stream)
        view = top_down_view(config, config_path)
        for tool in config['Visualization Manager']['Tools']:
            if tool['Class'] in INVALID_TOPICS:
                tool['Topic'] = INVALID_TOPICS[tool['Class']][0]
        config_path = os.path.join(cls.artifact_dir, 'rviz_tool_invalid_topics.rviz')
        with open(config_path, 'w') as stream:
            yaml.safe_dump(config, stream, sort_keys=False)

        cls.waypoints = Collector('waypoint_list', PoseArray)
        cls.status = Collector('coverage_planner/status', PlanStatus)
        mission = load_mission(rospy.get_param('~mission'))
        polygon = PolygonWithHolesStamped()
        polygon.header.frame_id = mission['frame_id']
        polygon.header.stamp = rospy.Time.now()
        polygon.polygon.hull = ring(mission['polygon']['hull'])
        polygon.polygon.holes = [ring(hole) for hole in mission['polygon']['holes']]
        cls.polygon_publisher = rospy.Publisher('polygon', PolygonWithHolesStamped,
                                                queue_size=1, latch=True)
        cls.polygon_publisher.publish(polygon)

        cls.rviz = start_rviz(config_path, cls.rviz_log, view)
        cls.addClassCleanup(cls.rviz.stop)
        cls.viewport = cls.rviz.viewport
        # Subscribed only now: while rviz starts, its built-in 2D Nav Goal tool briefly
        # advertises PoseStamped on `goal` before the config replaces the tools, and a rospy
        # subscriber connecting then may not reconnect. Then wait until the tools' and the
        # panel's publishers are connected, so no click is lost.
        cls.start = Collector('start', PointStamped)
        cls.goal = Collector('goal', PointStamped)
        cls.activate = Collector('activate', Empty)
        cls.rviz.wait_for_publishers((cls.start, cls.goal, cls.activate))
        print('rviz_tool: rviz ready after %.1f s, render area %dx%d at +%d+%d' % (
            time.time() - cls.rviz.started, cls.viewport.width, cls.viewport.height,
            cls.viewport.left, cls.viewport.top))

    def click(self, point):
        """Left click on the ground plane point; returns the pixel clicked."""
        return self.rviz.click(point)

    def assert_point_clicked(self, collector, count, pixel, what):
        self.assertTrue(collector.wait_for(count, MESSAGE_TIMEOUT_S),
                        'no %s message %d after the click' % (what, count))
        message = collector.messages[count - 1]
        self.assertEqual(message.header.frame_id, 'map')
        expected = self.viewport.metres(pixel)
        resolution = 1.0 / self.viewport.scale
        self.assertAlmostEqual(message.point.x, expected[0], delta=resolution)
        self.assertAlmostEqual(message.point.y, expected[1], delta=resolution)
        return message.point

    def setUp(self):
        self.check_setup()

    def take_screenshot(self):
        self.rviz.screenshot(self.screenshot)

    def test_start_goal_and_activate_plan_from_the_last_start(self):
        # After the test, passed or failed: what rviz showed.
        self.addCleanup(self.take_screenshot)
        # A click with the default Interact tool gives the render panel the keyboard focus.
        self.rviz.focus()
        self.rviz.key('s')
        first_start = self.assert_point_clicked(self.start, 1, self.click(FIRST_START), 'start')
        self.rviz.key('g')
        goal = self.assert_point_clicked(self.goal, 1, self.click(GOAL), 'goal')
        self.rviz.key('s')
        second_start = self.assert_point_clicked(self.start, 2, self.click(SECOND_START), 'start')
        self.assertEqual(len(self.goal.messages), 1, 'the Start tool published a goal')
        self.assertEqual(len(self.waypoints.messages), 0, 'planned before activate')

        self.rviz.key('alt+a')
        self.assertTrue(self.activate.wait_for(1, MESSAGE_TIMEOUT_S),
                        'the Activate button (Alt+A) published nothing on activate')
        self.assertTrue(self.waypoints.wait_for(1, PLAN_TIMEOUT_S),
                        'no waypoint_list after activate; status: %s' % [
                            status.message for status in self.status.messages])
        self.addCleanup(time.sleep, 1.0)  # rviz draws the plan before the screenshot

        poses = self.waypoints.messages[-1].poses
        self.assertGreaterEqual(len(poses), 2)
        self.assertEqual(self.waypoints.messages[-1].header.frame_id, 'map')
        self.assertAlmostEqual(poses[0].position.x, second_start.x, places=6)
        self.assertAlmostEqual(poses[0].position.y, second_start.y, places=6)
        self.assertAlmostEqual(poses[-1].position.x, goal.x, places=6)
        self.assertAlmostEqual(poses[-1].position.y, goal.y, places=6)
        # The first start was replaced, not kept: the clicks are far apart.
        self.assertGreater(abs(first_start.x - second_start.x), 10.0)

    def test_invalid_topic_names_are_refused_and_the_default_topics_kept(self):
        self.assertIsNone(self.rviz.process.poll(), 'rviz exited; see %s' % self.rviz_log)
        log = self.rviz.log()
        for name, kept in INVALID_TOPICS.values():
            self.assertIn('Topic "%s" is not a valid topic name' % name, log)
            refusals = [line for line in log.splitlines() if '"%s"' % name in line]
            self.assertEqual(len(refusals), 1, refusals)
            self.assertIn('still published on %s.' % kept, refusals[0])
        # The clicks of the other test arrive on these topics; the tools advertise them.
        self.assertGreater(self.start.subscriber.get_num_connections(), 0)
        self.assertGreater(self.goal.subscriber.get_num_connections(), 0)

    def test_plugins_load_without_pluginlib_errors(self):
        log = self.rviz.log()
        self.assertIn('rviz version', log, 'rviz wrote no log to %s' % self.rviz_log)
        errors = [line for line in log.splitlines()
                  if any(pattern in line for pattern in PLUGIN_ERRORS)]
        self.assertEqual(errors, [], 'pluginlib errors in %s' % self.rviz_log)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'rviz_tool', RvizToolTest)
