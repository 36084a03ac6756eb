#!/usr/bin/python3
"""Node rostest: bad input, the ~plan service, replanning on a changed polygon,
start/goal in another frame and the ~save_mission service (the saved mission plans the same
waypoints with coverage_tool), against a running coverage_planner and
smooth_trajectory_generator."""

import csv
import math
import os
import subprocess
import sys
import tempfile
import time
import unittest

import roslib.packages

import rospy
import rostest
from geometry_msgs.msg import PointStamped, PoseArray
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from kinematic_coverage.srv import SaveMission
from rosgraph_msgs.msg import Log
from std_msgs.msg import Empty
from visualization_msgs.msg import MarkerArray
from std_srvs.srv import Trigger

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, point_message, stamped_polygon, strictly_inside_hole  # noqa: E402

TIMEOUT_S = 30.0
SQUARE = [(0, 0), (30, 0), (30, 30), (0, 30)]


class PlannerRequestsTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('planner_requests_test')
        cls.polygon = rospy.Publisher('polygon', PolygonWithHolesStamped, queue_size=1, latch=True)
        cls.start = rospy.Publisher('start', PointStamped, queue_size=1, latch=True)
        cls.goal = rospy.Publisher('goal', PointStamped, queue_size=1, latch=True)
        cls.activate = rospy.Publisher('activate', Empty, queue_size=1)
        cls.waypoints = Collector('waypoint_list', PoseArray)
        cls.trajectory = Collector('trajectory', PoseArray)
        cls.status = Collector('coverage_planner/status', PlanStatus)
        cls.markers = Collector('coverage_planner/markers', MarkerArray)
        cls.log = Collector('/rosout', Log)
        rospy.wait_for_service('coverage_planner/plan', TIMEOUT_S)
        cls.plan_service = rospy.ServiceProxy('coverage_planner/plan', Trigger)
        rospy.wait_for_service('coverage_planner/save_mission', TIMEOUT_S)
        cls.save_service = rospy.ServiceProxy('coverage_planner/save_mission', SaveMission)
        while cls.activate.get_num_connections() == 0 and not rospy.is_shutdown():
            time.sleep(0.05)

    def send(self, hull=SQUARE, holes=(), start=(1, 1), goal=(29, 29), start_frame='map'):
        """Publishes a mission, activates the planner and returns its status, the number
        of coverage_planner ROS_ERRORs and of waypoint lists published for it."""
        statuses = len(self.status.messages)
        waypoints = len(self.waypoints.messages)
        self.polygon.publish(stamped_polygon(hull, holes))
        self.start.publish(point_message(start[0], start[1], start_frame))
        self.goal.publish(point_message(goal[0], goal[1]))
        time.sleep(0.5)  # the latched inputs reach the node before activate
        errors = self.planner_errors()
        self.activate.publish(Empty())
        self.assertTrue(self.status.wait_for(statuses + 1, TIMEOUT_S), 'no status')
        if not self.status.messages[-1].success:
            # The node's ROS_ERROR reaches /rosout a moment after its status.
            deadline = time.time() + 10.0
            while self.planner_errors() == errors and time.time() < deadline:
                time.sleep(0.05)
        time.sleep(1.0)  # a second error or a waypoint list would have arrived by now
        return (self.status.messages[-1], self.planner_errors() - errors,
                len(self.waypoints.messages) - waypoints)

    def test_0_inputs_are_drawn_as_soon_as_they_arrive(self):
        # Before any plan: the polygon's hull and hole, then the start, each on arrival.
        hole = [(12, 8), (18, 8), (18, 22), (12, 22)]
        count = len(self.markers.messages)
        self.polygon.publish(stamped_polygon(SQUARE, [hole]))
        self.assertTrue(self.markers.wait_for(count + 1, TIMEOUT_S), 'no markers')
        drawn = self.markers.messages[-1].markers
        self.assertEqual(sorted(m.ns for m in drawn if m.ns), ['polygon', 'polygon'])
        self.assertEqual(len([m for m in drawn if m.ns == 'polygon' and len(m.points) == 5]), 2)
        self.start.publish(point_message(3, 4))
        self.assertTrue(self.markers.wait_for(count + 2, TIMEOUT_S), 'no markers')
        drawn = self.markers.messages[-1].markers
        self.assertEqual(sorted(m.ns for m in drawn if m.ns),
                         ['polygon', 'polygon', 'start_goal'])
        start = [m for m in drawn if m.ns == 'start_goal'][0]
        self.assertEqual((start.pose.position.x, start.pose.position.y), (3, 4))

    def planner_errors(self):
        return sum(1 for entry in self.log.messages
                   if entry.level == Log.ERROR and entry.name == '/coverage_planner')

    def test_1_invalid_input_is_rejected_and_the_next_mission_planned(self):
        nan = float('nan')
        cases = {
            'self-intersecting': dict(hull=[(0, 0), (30, 30), (30, 0), (0, 30)]),
            'non-finite': dict(hull=[(0, 0), (30, 0), (30, nan), (0, 30)]),
            'fewer than 3': dict(hull=[(0, 0), (30, 0)]),
            'zero area': dict(hull=[(0, 0), (10, 0), (20, 0)]),
            'hole outside': dict(holes=[[(40, 40), (45, 40), (45, 45)]]),
            'empty offset': dict(hull=[(0, 0), (1.5, 0), (1.5, 1.5), (0, 1.5)], start=(0.5, 0.5),
                                 goal=(1, 1)),
            'start in hole': dict(holes=[[(10, 10), (20, 10), (20, 20), (10, 20)]],
                                  start=(15, 15)),
            'unknown frame': dict(start_frame='nowhere'),
            'over the size limit': dict(hull=[
                (15 + 14 * math.cos(2 * math.pi * i / 100001),
                 15 + 14 * math.sin(2 * math.pi * i / 100001)) for i in range(100001)],
                start=(15, 15), goal=(16, 16)),
        }
        for name, case in cases.items():
            status, errors, published = self.send(**case)
            self.assertFalse(status.success, name)
            self.assertTrue(status.message, name)
            self.assertEqual(errors, 1, '%s: one ROS_ERROR expected; log: %s' % (
                name, [(entry.name, entry.level) for entry in self.log.messages][-5:]))
            self.assertEqual(published, 0, '%s: nothing may be published' % name)
        rospy.set_param('coverage_planner/lateral_overlap', 1.5)
        status, errors, published = self.send()
        rospy.set_param('coverage_planner/lateral_overlap', 0.4)
        self.assertFalse(status.success)
        self.assertIn('lateral_overlap', status.message)
        self.assertEqual((errors, published), (1, 0))
        status, errors, published = self.send()
        self.assertTrue(status.success, status.message)
        self.assertEqual((errors, published), (0, 1))

    def test_2_plan_service_answers_and_a_changed_polygon_replaces_the_output(self):
        self.send()
        first = self.waypoints.messages[-1]
        hole = [(12, 8), (18, 8), (18, 22), (12, 22)]
        count = len(self.waypoints.messages)
        trajectories = len(self.trajectory.messages)
        self.polygon.publish(stamped_polygon(SQUARE, [hole]))
        time.sleep(0.5)
        answer = self.plan_service()
        self.assertTrue(answer.success, answer.message)
        self.assertIn('waypoints', answer.message)
        self.assertTrue(self.waypoints.wait_for(count + 1, TIMEOUT_S))
        second = self.waypoints.messages[-1]
        self.assertGreater(second.header.stamp, first.header.stamp)
        for pose in second.poses:
            self.assertFalse(strictly_inside_hole((pose.position.x, pose.position.y), [hole]))
        # The smoother follows with a trajectory around the new hole.
        self.assertTrue(self.trajectory.wait_for(trajectories + 1, TIMEOUT_S))
        for pose in self.trajectory.messages[-1].poses:
            self.assertFalse(strictly_inside_hole((pose.position.x, pose.position.y), [hole]))

    def test_3_start_in_another_frame_is_transformed(self):
        # boat is map shifted by (10, 5): (-8, -3) in boat is (2, 2) in map.
        status, errors, published = self.send(start=(-8, -3), start_frame='boat')
        self.assertTrue(status.success, status.message)
        first = self.waypoints.messages[-1].poses[0].position
        self.assertLess(math.hypot(first.x - 2.0, first.y - 2.0), 1e-5)
        self.assertEqual(self.waypoints.messages[-1].header.frame_id, 'map')

    def test_4_a_saved_mission_plans_the_same_waypoints_with_coverage_tool(self):
        hole = [(12, 8), (18, 8), (18, 22), (12, 22)]
        rospy.set_param('coverage_planner/turning_radius', 0.8)
        try:
            status, errors, published = self.send(holes=[hole], start=(-8, -3), start_frame='boat')
            self.assertTrue(status.success, status.message)
            planned = [(p.position.x, p.position.y) for p in self.waypoints.messages[-1].poses]
            directory = tempfile.mkdtemp(prefix='save_mission_')
            path = os.path.join(directory, 'saved.yaml')
            answer = self.save_service(path)
        finally:
            rospy.delete_param('coverage_planner/turning_radius')
        self.assertTrue(answer.success, answer.message)
        self.assertEqual(answer.message, path)
        with open(path) as stream:
            text = stream.read()
        self.assertIn('\nturning_radius: 0.8\n', text)
        tool = roslib.packages.find_node('kinematic_coverage', 'coverage_tool')
        self.assertTrue(tool, 'no coverage_tool executable')
        out = os.path.join(directory, 'plan')
        done = subprocess.run([tool[0], 'plan', path, '--out', out], capture_output=True,
                              text=True, timeout=120)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(os.path.join(out, 'waypoints.csv')) as stream:
            replanned = [(float(row['x']), float(row['y'])) for row in csv.DictReader(stream)]
        self.assertEqual(len(replanned), len(planned))
        for (x, y), (u, v) in zip(planned, replanned):
            self.assertLess(math.hypot(x - u, y - v), 1e-9)

    def test_5_a_mission_that_cannot_be_saved_is_named(self):
        self.send()
        answer = self.save_service('')
        self.assertFalse(answer.success)
        self.assertIn('no path given', answer.message)
        answer = self.save_service('/nonexistent-directory/saved.yaml')
        self.assertFalse(answer.success)
        self.assertIn('/nonexistent-directory/saved.yaml', answer.message)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'planner_requests', PlannerRequestsTest)
