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
import re
import shutil
import signal
import subprocess
import sys
import time
import unittest

import rospy
import rostest
import yaml
from geometry_msgs.msg import Point32, PointStamped, Polygon, PoseArray
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from std_msgs.msg import Empty

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, load_mission  # noqa: E402

# Points clicked, in metres in the map frame: inside the lake's offset free area
# (config/missions/lake_30x30.yaml) and inside the view of pipeline.rviz.
FIRST_START = (27.0, 27.0)
GOAL = (27.0, 3.0)
SECOND_START = (3.0, 5.0)

RVIZ_WINDOW_TIMEOUT_S = 30.0
MESSAGE_TIMEOUT_S = 10.0
PLAN_TIMEOUT_S = 30.0
# rviz first lays out at 640x480, then resizes to the config's geometry.
STABLE_POLLS = 4
POLL_INTERVAL_S = 0.5
PLUGIN_ERRORS = ('PluginlibFactory', 'Failed to load library', 'could not be loaded')
# Topic names the config copy gives the tools: not valid ROS names (ros::names::validate).
INVALID_TOPICS = {'kinematic_coverage/SetStart': ('bad topic!', '/start'),
                  'kinematic_coverage/SetGoal': ('1abc', '/goal')}
GUI_PROGRAMS = ('xdotool', 'xwininfo', 'import')
XML_OUTPUT_FLAG = '--gtest_output=xml:'
XWININFO_LINE = re.compile(
    r'^\s*(0x[0-9a-f]+) (.*?): .*\s(\d+)x(\d+)\+-?\d+\+-?\d+\s+\+(-?\d+)\+(-?\d+)\s*$')


def run(*command):
    return subprocess.run(command, check=True, capture_output=True, text=True,
                          timeout=10).stdout


def ring(points):
    return Polygon(points=[Point32(x=x, y=y, z=0.0) for x, y in points])


def default_artifact_dir():
    """The directory of the result file rostest asks for (its --gtest_output=xml: argument),
    else ROS_HOME or ~/.ros."""
    for argument in sys.argv:
        if argument.startswith(XML_OUTPUT_FLAG):
            return os.path.dirname(argument[len(XML_OUTPUT_FLAG):])
    return os.environ.get('ROS_HOME', os.path.expanduser('~/.ros'))


class Viewport:
    """The render window's place on the screen and the TopDownOrtho view it shows."""

    def __init__(self, geometry, view):
        self.left, self.top, self.width, self.height = geometry
        self.scale = float(view['Scale'])  # pixels per metre
        self.focus = (float(view['X']), float(view['Y']))

    def pixel(self, point):
        """The screen pixel nearest to a point of the ground plane."""
        return (round(self.left + self.width / 2.0 + (point[0] - self.focus[0]) * self.scale),
                round(self.top + self.height / 2.0 - (point[1] - self.focus[1]) * self.scale))

    def metres(self, pixel):
        """The point of the ground plane a screen pixel shows."""
        return (self.focus[0] + (pixel[0] - self.left - self.width / 2.0) / self.scale,
                self.focus[1] - (pixel[1] - self.top - self.height / 2.0) / self.scale)


def render_window_geometry(rviz_window):
    """(left, top, width, height) on the screen of the rviz window's render area: Ogre's own
    unnamed child window, the largest one, or None before it exists."""
    tree = run('xwininfo', '-tree', '-id', rviz_window)
    best = None
    for line in tree.splitlines():
        match = XWININFO_LINE.match(line)
        if not match or match.group(2) != '(has no name)':
            continue
        width, height, left, top = (int(match.group(i)) for i in range(3, 7))
        if width >= 200 and height >= 200 and (best is None or width * height > best[2] * best[3]):
            best = (left, top, width, height)
    return best


class RvizToolTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.setup_error = None
        if not os.environ.get('DISPLAY'):
            message = ('rviz_tool: SKIPPED: no DISPLAY. This GUI test drives rviz with xdotool; '
                       'run ctest under xvfb-run -a -s "-screen 0 1280x1024x24".')
            print(message, file=sys.stderr)
            raise unittest.SkipTest(message)
        # rosunit's result file drops errors raised in setUpClass: the tests report them.
        try:
            cls.start_rviz()
        except Exception as error:  # reported by every test
            cls.setup_error = '%s: %s' % (type(error).__name__, error)

    @classmethod
    def start_rviz(cls):
        """Publishes the polygon, starts rviz and waits until its render window settled and
        its tools publish."""
        missing = [program for program in GUI_PROGRAMS if shutil.which(program) is None]
        if missing:
            raise RuntimeError('missing %s: run scripts/install_dependencies.sh' % ', '.join(missing))
        rospy.init_node('rviz_tool_test')
        cls.artifact_dir = rospy.get_param('~artifact_dir', '') or default_artifact_dir()
        os.makedirs(cls.artifact_dir, exist_ok=True)
        cls.screenshot = os.path.join(cls.artifact_dir, 'rviz_tool.png')
        cls.rviz_log = os.path.join(cls.artifact_dir, 'rviz_tool_rviz.log')
        config_path = rospy.get_param('~rviz_config')
        with open(config_path) as stream:
            config = yaml.safe_load(stream)
        view = config['Visualization Manager']['Views']['Current']
        if view['Class'] != 'rviz/TopDownOrtho' or float(view['Angle']) != 0.0:
            raise RuntimeError('%s: the test needs a TopDownOrtho view with Angle 0' % config_path)
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

        environment = dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED='1')
        with open(cls.rviz_log, 'w') as log:
            cls.rviz = subprocess.Popen(['rosrun', 'rviz', 'rviz', '-d', config_path],
                                        stdout=log, stderr=subprocess.STDOUT, env=environment,
                                        start_new_session=True)
        cls.addClassCleanup(cls.stop_rviz)
        started = time.time()
        cls.rviz_window, geometry = cls.wait_for_render_window()
        cls.viewport = Viewport(geometry, view)
        # Subscribed only now: while rviz starts, its built-in 2D Nav Goal tool briefly
        # advertises PoseStamped on `goal` before the config replaces the tools, and a rospy
        # subscriber connecting then may not reconnect. Then wait until the tools' and the
        # panel's publishers are connected, so no click is lost.
        cls.start = Collector('start', PointStamped)
        cls.goal = Collector('goal', PointStamped)
        cls.activate = Collector('activate', Empty)
        for collector in (cls.start, cls.goal, cls.activate):
            while collector.subscriber.get_num_connections() == 0:
                if time.time() - started > RVIZ_WINDOW_TIMEOUT_S:
                    raise RuntimeError('rviz does not publish %s after %.0f s; see %s' % (
                        collector.subscriber.name, RVIZ_WINDOW_TIMEOUT_S, cls.rviz_log))
                time.sleep(0.1)
        print('rviz_tool: rviz ready after %.1f s, render area %dx%d at +%d+%d' % (
            time.time() - started, cls.viewport.width, cls.viewport.height,
            cls.viewport.left, cls.viewport.top))

    @classmethod
    def stop_rviz(cls):
        """SIGINT to rviz's process group (rosrun execs rviz); SIGKILL after 10 s."""
        os.killpg(cls.rviz.pid, signal.SIGINT)
        try:
            cls.rviz.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(cls.rviz.pid, signal.SIGKILL)
            cls.rviz.wait()

    @classmethod
    def wait_for_render_window(cls):
        """rviz's main window and its render area, once the area's geometry stayed the same
        over STABLE_POLLS polls (the splash screen and the first 640x480 layout pass)."""
        deadline = time.time() + RVIZ_WINDOW_TIMEOUT_S
        readings = []
        while time.time() < deadline:
            if cls.rviz.poll() is not None:
                raise RuntimeError('rviz exited with %d; see %s' % (cls.rviz.returncode,
                                                                    cls.rviz_log))
            readings.append(cls.find_render_window())
            recent = readings[-STABLE_POLLS:]
            if (len(recent) == STABLE_POLLS and recent[0] is not None
                    and recent.count(recent[0]) == STABLE_POLLS):
                return recent[0]
            time.sleep(POLL_INTERVAL_S)
        raise RuntimeError('no settled rviz render window after %.0f s (last: %s); see %s' % (
            RVIZ_WINDOW_TIMEOUT_S, readings[-STABLE_POLLS:], cls.rviz_log))

    @classmethod
    def find_render_window(cls):
        """(rviz window id, render area geometry) or None."""
        found = subprocess.run(['xdotool', 'search', '--onlyvisible', '--pid',
                                str(cls.rviz.pid), '--name', 'RViz'],
                               capture_output=True, text=True)
        for window in found.stdout.split():
            try:
                geometry = render_window_geometry(window)
            except subprocess.CalledProcessError:  # the window went away meanwhile
                continue
            if geometry is not None:
                return window, geometry
        return None

    def click(self, point):
        """Left click on the ground plane point; returns the pixel clicked."""
        pixel = self.viewport.pixel(point)
        run('xdotool', 'mousemove', '--sync', str(pixel[0]), str(pixel[1]))
        run('xdotool', 'click', '1')
        return pixel

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
        if self.setup_error:
            self.fail(self.setup_error)

    def take_screenshot(self):
        run('import', '-window', 'root', self.screenshot)
        print('rviz_tool: screenshot %s' % self.screenshot)

    def test_start_goal_and_activate_plan_from_the_last_start(self):
        # After the test, passed or failed: what rviz showed.
        self.addCleanup(self.take_screenshot)
        run('xdotool', 'windowraise', self.rviz_window)
        run('xdotool', 'windowfocus', '--sync', self.rviz_window)
        # A click with the default Interact tool gives the render panel the keyboard focus.
        self.click(self.viewport.focus)
        run('xdotool', 'key', 's')
        first_start = self.assert_point_clicked(self.start, 1, self.click(FIRST_START), 'start')
        run('xdotool', 'key', 'g')
        goal = self.assert_point_clicked(self.goal, 1, self.click(GOAL), 'goal')
        run('xdotool', 'key', 's')
        second_start = self.assert_point_clicked(self.start, 2, self.click(SECOND_START), 'start')
        self.assertEqual(len(self.goal.messages), 1, 'the Start tool published a goal')
        self.assertEqual(len(self.waypoints.messages), 0, 'planned before activate')

        run('xdotool', 'key', 'alt+a')
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
        self.assertIsNone(self.rviz.poll(), 'rviz exited; see %s' % self.rviz_log)
        with open(self.rviz_log) as stream:
            log = stream.read()
        for name, kept in INVALID_TOPICS.values():
            self.assertIn('Topic "%s" is not a valid topic name' % name, log)
            refusals = [line for line in log.splitlines() if '"%s"' % name in line]
            self.assertEqual(len(refusals), 1, refusals)
            self.assertIn('still published on %s.' % kept, refusals[0])
        # The clicks of the other test arrive on these topics; the tools advertise them.
        self.assertGreater(self.start.subscriber.get_num_connections(), 0)
        self.assertGreater(self.goal.subscriber.get_num_connections(), 0)

    def test_plugins_load_without_pluginlib_errors(self):
        with open(self.rviz_log) as stream:
            log = stream.read()
        self.assertIn('rviz version', log, 'rviz wrote no log to %s' % self.rviz_log)
        errors = [line for line in log.splitlines()
                  if any(pattern in line for pattern in PLUGIN_ERRORS)]
        self.assertEqual(errors, [], 'pluginlib errors in %s' % self.rviz_log)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'rviz_tool', RvizToolTest)
