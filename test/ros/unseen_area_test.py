#!/usr/bin/python3
"""Unseen-area rostest: smooth_trajectory_generator measures what its trajectory sees of the
reachable area and, below 99.9 %, says so with a ROS_WARN and in its ~status, which
still reports success (the trajectory is published; docs/REFERENCE.md, Nodes and topics);
and what the smoothing loses of what the unsmoothed trajectory sees, with a second warning."""

import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseArray
from kinematic_coverage.msg import PlanStatus
from rosgraph_msgs.msg import Log

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, wait_for_subscribers, wait_until  # noqa: E402

TIMEOUT_S = 60.0
NODE = '/smooth_trajectory_generator'


class UnseenAreaTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('unseen_area_test')
        cls.log = Collector('/rosout', Log)
        cls.waypoints = Collector('waypoint_list', PoseArray)
        cls.trajectory = Collector('trajectory', PoseArray)
        cls.status = Collector('smooth_trajectory_generator/status', PlanStatus)
        for collector in (cls.waypoints, cls.trajectory, cls.status):
            collector.wait_for(1, TIMEOUT_S)

    def warnings(self):
        return [entry.msg for entry in self.log.messages
                if entry.level == Log.WARN and entry.name == NODE]

    def test_status_succeeds_and_names_the_unseen_area(self):
        self.assertTrue(self.trajectory.messages, 'no trajectory')
        self.assertTrue(self.status.messages, 'no smooth_trajectory_generator/status')
        last = self.status.messages[-1]
        self.assertTrue(last.success, last.message)
        self.assertIn('of the reachable area', last.message)
        self.assertIn('warning: the trajectory sees', last.message)
        self.assertIn('largest unseen region', last.message)
        self.assertIn('warning: smoothing loses', last.message)

    def test_ros_warns_per_trajectory_name_the_unseen_and_the_lost_area(self):
        # The first trajectory may have been smoothed before /rosout was listened to: the
        # planner's waypoints again make a second one, and its warning.
        self.assertTrue(self.waypoints.messages, 'no waypoint_list')
        warnings = len(self.warnings())
        statuses = len(self.status.messages)
        publisher = rospy.Publisher('waypoint_list', PoseArray, queue_size=1)
        wait_for_subscribers(publisher, ['/smooth_trajectory_generator'], 10.0)
        rospy.sleep(0.5)  # a message published as the connection opens may be dropped
        publisher.publish(self.waypoints.messages[-1])
        self.assertTrue(self.status.wait_for(statuses + 1, TIMEOUT_S), 'no second status')
        # The node's ROS_WARNs reach /rosout a moment after its status: the unseen reachable
        # area, then what smoothing loses of the unsmoothed trajectory's view.
        wait_until(lambda: len(self.warnings()) >= warnings + 2, 10.0)
        new = self.warnings()[warnings:]
        self.assertEqual(len(new), 2, new)
        self.assertIn('less than 99.9 %', new[0])
        self.assertIn('largest unseen region', new[0])
        self.assertIn('smoothing loses', new[1])
        self.assertIn('in the reachable area', new[1])


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'unseen_area', UnseenAreaTest)
