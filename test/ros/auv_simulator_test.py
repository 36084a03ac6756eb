#!/usr/bin/python3
"""Simulated-robot rostest: auv_simulator follows the lake trajectory. `pose` stays near the
trajectory, `visited` grows oldest first from the trajectory's first pose,
`estimated_pose` strays from `pose` by the navigation error, the robot arrives at the end; a newer trajectory restarts it from where it is with the history
kept, and an empty or older trajectory is refused without stopping the node."""

import math
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Pose, PoseArray, PoseStamped, Quaternion
from kinematic_coverage.msg import PlanStatus

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, distance_to_segment  # noqa: E402

TIMEOUT_S = 60.0


def position(pose):
    return (pose.position.x, pose.position.y)


def distance_to_path(point, poses):
    points = [position(pose) for pose in poses]
    return min(distance_to_segment(point, a, b) for a, b in zip(points, points[1:]))


def wait_until(condition, timeout):
    deadline = time.time() + timeout
    while not condition() and time.time() < deadline and not rospy.is_shutdown():
        time.sleep(0.05)
    return condition()


def last_status_is(collector, text):
    return bool(collector.messages) and text in collector.messages[-1].message


class AuvSimulatorTest(unittest.TestCase):

    def test_follows_the_trajectory_then_restarts_on_a_newer_one(self):
        rospy.init_node('auv_simulator_test')
        trajectory = Collector('trajectory', PoseArray)
        pose = Collector('pose', PoseStamped)
        estimated = Collector('estimated_pose', PoseStamped)
        visited = Collector('visited', PoseArray)
        status = Collector('auv_simulator/status', PlanStatus)
        self.assertTrue(trajectory.wait_for(1, TIMEOUT_S), 'no trajectory')
        planned = trajectory.messages[-1].poses

        # The lake trajectory takes about 820 s of simulated time: 8 s at 100 times.
        self.assertTrue(wait_until(lambda: last_status_is(status, 'reached the last pose'),
                                   TIMEOUT_S), 'the robot did not arrive')
        self.assertTrue(all(message.success for message in status.messages))
        self.assertGreater(len(pose.messages), 20)
        for message in pose.messages:
            self.assertEqual(message.header.frame_id, 'map')
            self.assertLess(distance_to_path(position(message.pose), planned), 0.5)
        self.check_estimated_poses(pose.messages, estimated.messages)
        end = pose.messages[-1].pose.position
        goal = planned[-1].position
        self.assertLess(math.hypot(end.x - goal.x, end.y - goal.y), 0.5)

        sizes = [len(message.poses) for message in visited.messages]
        self.assertGreater(len(sizes), 5)
        self.assertTrue(all(b > a for a, b in zip(sizes, sizes[1:])), 'visited must grow')
        history = visited.messages[-1].poses
        self.assertLess(math.hypot(history[0].position.x - planned[0].position.x,
                                   history[0].position.y - planned[0].position.y), 1e-6)
        for visited_pose in history:
            self.assertLess(distance_to_path(position(visited_pose), planned), 0.5)

        # A newer trajectory: a straight run from where the robot stopped.
        publisher = rospy.Publisher('trajectory', PoseArray, queue_size=1)
        time.sleep(1.0)
        detour = PoseArray()
        detour.header.frame_id = 'map'
        detour.header.stamp = rospy.Time.now()
        heading = Quaternion(x=0.0, y=0.0, z=-math.sqrt(0.5), w=math.sqrt(0.5))
        for step in range(11):
            waypoint = Pose(orientation=heading)
            waypoint.position.x = end.x
            waypoint.position.y = end.y - 0.5 * step
            detour.poses.append(waypoint)
        # Turn to the detour's heading first: an in-place rotation at the robot's position.
        here = Pose(orientation=heading)
        here.position.x = end.x
        here.position.y = end.y
        detour.poses.insert(0, Pose(position=here.position,
                                    orientation=pose.messages[-1].pose.orientation))
        statuses = len(status.messages)
        publisher.publish(detour)
        self.assertTrue(wait_until(lambda: len(status.messages) >= statuses + 2
                                   and last_status_is(status, 'reached the last pose'),
                                   TIMEOUT_S), 'the robot did not finish the detour')
        self.assertIn('following 12 poses', status.messages[statuses].message)
        final = pose.messages[-1].pose.position
        self.assertLess(math.hypot(final.x - end.x, final.y - (end.y - 5.0)), 0.5)
        kept = visited.messages[-1].poses
        self.assertGreater(len(kept), len(history))
        self.assertEqual(position(kept[0]), position(history[0]))

        # Refused: an empty trajectory and one older than the detour; the node keeps going.
        statuses = len(status.messages)
        publisher.publish(PoseArray(header=detour.header))
        self.assertTrue(wait_until(lambda: len(status.messages) > statuses, TIMEOUT_S))
        self.assertFalse(status.messages[-1].success)
        self.assertIn('no poses', status.messages[-1].message)
        older = PoseArray(header=detour.header, poses=planned)
        older.header.stamp = detour.header.stamp - rospy.Duration(10.0)
        poses_before = len(pose.messages)
        publisher.publish(older)
        time.sleep(1.0)
        self.assertGreater(len(pose.messages), poses_before, 'the node stopped publishing')
        latest = pose.messages[-1].pose.position
        self.assertLess(math.hypot(latest.x - final.x, latest.y - final.y), 1e-6)

    def check_estimated_poses(self, poses, estimates):
        # Published with the pose at every tick: the true pose plus a navigation error of
        # 0.015 m per axis, which is nowhere 0 and hardly ever beyond 5 sigma.
        true_at = {message.header.stamp: position(message.pose) for message in poses}
        offsets = [math.dist(position(message.pose), true_at[message.header.stamp])
                   for message in estimates if message.header.stamp in true_at]
        self.assertGreater(len(offsets), 20)
        self.assertTrue(all(message.header.frame_id == 'map' for message in estimates))
        self.assertGreater(min(offsets), 0.0)
        self.assertLess(max(offsets), 0.1)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'auv_simulator_follows_trajectory', AuvSimulatorTest)
