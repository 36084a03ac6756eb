#!/usr/bin/python3
"""Parameter-type rostest: a wrongly typed node parameter is an error naming the parameter
and the type it must have, never a silent default: auv_simulator and mission_publisher
refuse to start (exit status 2); a running auv_simulator refuses a trajectory while a
planner parameter has the wrong type, and a trajectory with a bad pose, then follows the
next good one."""

import json
import math
import os
import subprocess
import sys
import unittest

import roslib.packages
import rospy
import rostest
from geometry_msgs.msg import Pose, PoseArray, PoseStamped
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from rosgraph_msgs.msg import Log

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, RejectionChecks, wait_until  # noqa: E402

START_TIMEOUT_S = 30.0
SIMULATOR = '/auv_simulator'


def run_node(node_type, name, *parameters):
    """Runs a node with private parameters (`_name:=value`: an integer, a double, true or
    false, else a string) until it exits; returns its exit status and output."""
    # The executable as roslaunch finds it (rosrun's own search trips over build trees
    # inside the package's folder).
    executables = roslib.packages.find_node('kinematic_coverage', node_type)
    if not executables:
        raise AssertionError('no executable %s in package kinematic_coverage' % node_type)
    done = subprocess.run([executables[0], '__name:=' + name] + list(parameters),
                          capture_output=True, text=True, timeout=START_TIMEOUT_S)
    return done.returncode, done.stdout + done.stderr


def trajectory(points, quaternion=(0.0, 0.0, 0.0, 1.0)):
    message = PoseArray()
    message.header.frame_id = 'map'
    message.header.stamp = rospy.Time.now()
    for x, y in points:
        pose = Pose()
        pose.position.x = x
        pose.position.y = y
        (pose.orientation.x, pose.orientation.y, pose.orientation.z,
         pose.orientation.w) = quaternion
        message.poses.append(pose)
    return message


class NodeParametersTest(RejectionChecks, unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('node_parameters_test')

    def test_simulator_refuses_a_string_where_a_number_is_expected(self):
        # One node name per case: a parameter stays on the server after its node exits.
        for case, (parameter, value, given) in enumerate((
                ('real_time_factor', 'fast', "a string ('fast')"),
                ('publish_rate', 'true', 'a boolean (true)'))):
            name = 'typed_simulator_%d' % case
            status, output = run_node('auv_simulator', name, '_%s:=%s' % (parameter, value))
            self.assertEqual(status, 2, output)
            self.assertIn('/%s/%s must be a number (double)' % (name, parameter), output)
            self.assertIn(given, output)
            self.assertNotIn('waiting for a trajectory', output)

    def test_mission_publisher_refuses_a_mission_that_is_not_a_string(self):
        status, output = run_node('mission_publisher', 'typed_mission', '_mission:=5')
        self.assertEqual(status, 2, output)
        self.assertIn('/typed_mission/mission must be a string, not an integer (5)', output)

    def test_mission_publisher_refuses_a_datum_that_is_not_a_point_on_earth(self):
        mission = os.path.join(roslib.packages.get_pkg_dir('kinematic_coverage'), 'config',
                               'missions', 'kleinhesseloher_see.geojson')
        # A list parameter is set on the server (the command line's _name:= gives scalars).
        for case, (value, expected) in enumerate((
                ('abc', 'datum must be [latitude, longitude] (two numbers, WGS84 degrees), '
                        "not a string ('abc')"),
                ([48.1], 'datum must be [latitude, longitude] (two numbers, WGS84 degrees), '
                         'not a list'),
                ([91, 11.6], 'the datum (longitude 11.6, latitude 91) lies outside'))):
            name = 'typed_datum_%d' % case
            rospy.set_param(name + '/datum', value)
            status, output = run_node('mission_publisher', name, '_mission:=' + mission)
            self.assertEqual(status, 2, output)
            self.assertIn(expected, output)

    def test_mission_publisher_publishes_a_geojson_mission_in_metres_from_its_datum(self):
        mission = os.path.join(roslib.packages.get_pkg_dir('kinematic_coverage'), 'config',
                               'missions', 'kleinhesseloher_see.geojson')
        with open(mission) as stream:
            longitude, latitude = json.load(stream)['features'][0]['geometry']['coordinates'][0][0]
        # The datum 0.001 degrees south of the hull's first vertex: that vertex is published
        # about 111.2 m north of the origin.
        polygons = Collector('datum_test/polygon', PolygonWithHolesStamped)
        executable = roslib.packages.find_node('kinematic_coverage', 'mission_publisher')[0]
        rospy.set_param('datum_publisher/datum', [latitude - 0.001, longitude])
        process = subprocess.Popen(
            [executable, '__name:=datum_publisher', '_mission:=' + mission,
             'polygon:=datum_test/polygon'],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            received = polygons.wait_for(1, START_TIMEOUT_S)
        finally:
            process.terminate()
            output = process.communicate(timeout=START_TIMEOUT_S)[0]
        self.assertTrue(received, 'no polygon: ' + output)
        first = polygons.messages[-1].polygon.hull.points[0]
        self.assertLess(abs(first.x), 0.01)
        self.assertLess(abs(first.y - 111.2), 0.5)

    def test_running_simulator_refuses_bad_requests_then_follows(self):
        self.log = Collector('/rosout', Log)
        status = Collector('auv_simulator/status', PlanStatus)
        pose = Collector('pose', PoseStamped)
        publisher = rospy.Publisher('trajectory', PoseArray, queue_size=10)
        self.assertTrue(wait_until(lambda: publisher.get_num_connections() > 0, START_TIMEOUT_S))
        lane = [(0.5 * i, 0.0) for i in range(10)]
        rospy.set_param('auv_simulator/v_max', 'fast')
        self.assert_rejected(SIMULATOR, status, [pose], lambda: publisher.publish(trajectory(lane)),
                             ('v_max', 'fast'))
        rospy.set_param('auv_simulator/v_max', 0.5)
        # A value out of range names the parameter on the server it came from.
        rospy.set_param('auv_simulator/lateral_overlap', 1)
        self.assert_rejected(SIMULATOR, status, [pose], lambda: publisher.publish(trajectory(lane)),
                             ('parameter /auv_simulator/lateral_overlap: lateral_overlap = 1 is '
                              'out of range: it must be in [0, 1)',))
        rospy.delete_param('auv_simulator/lateral_overlap')
        for bad, expected in (((0, 0, 0, 0), 'trajectory pose 0'),
                              ((0, 0, math.nan, 1), 'unit quaternion')):
            self.assert_rejected(SIMULATOR, status, [pose],
                                 lambda: publisher.publish(trajectory(lane, bad)), (expected,))
        self.assert_handled(status, pose, lambda: publisher.publish(trajectory(lane)))
        self.assertIn('following 10 poses', status.messages[-1].message)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'node_parameters', NodeParametersTest)
