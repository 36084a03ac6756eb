#!/usr/bin/python3
"""Memory rostest of the replanner: a robot driving 0.5 m/s lawnmower lanes over a 30 m lake
and reporting at 10 Hz. The test sends `visited` with the first 1 000 poses and reads the
node's resident memory (VmRSS of /proc/<pid>/status), then grows `visited` to 20 000 poses
in four messages (as a robot republishing its history does) and sends the remaining
80 000 poses one by one on `pose`: 100 000 poses, 2.8 hours of the mission. The resident
memory must grow by less than 5 MB, and the replan must count the poses that arrived."""

import math
import re
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point32, PointStamped, Pose, PoseArray, PoseStamped, Polygon
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, node_pid, rss_bytes, wait_until  # noqa: E402

TOTAL = 100000
FIRST = 1000
VISITED_STEPS = (5000, 10000, 15000, 20000)
GROWTH_LIMIT_BYTES = 5 * 1024 * 1024
TIMEOUT_S = 120.0
# Poses sent before the test pauses for the node (its `pose` queue holds 100, and folding
# 2 048 poses into the history takes it some milliseconds): about 2 500 poses a second.
BURST = 50
PAUSE_S = 0.02


def lawnmower_pose(i):
    """Pose i of the robot: lanes 28 m long and 7 m apart, 0.05 m per pose."""
    step, lane_length, spacing, lanes = 0.05, 28.0, 7.0, 4
    s = math.fmod(i * step, lanes * (lane_length + spacing))
    lane = int(s // (lane_length + spacing))
    along = s - lane * (lane_length + spacing)
    forward = lane % 2 == 0
    y = 1.0 + lane * spacing
    if along < lane_length:
        x, yaw = (1.0 + along, 0.0) if forward else (29.0 - along, math.pi)
    else:
        x, y, yaw = (29.0 if forward else 1.0), y + along - lane_length, math.pi / 2
    pose = Pose()
    pose.position.x = x
    pose.position.y = y
    pose.orientation.z = math.sin(yaw / 2.0)
    pose.orientation.w = math.cos(yaw / 2.0)
    return pose


def stamped(frame, poses):
    message = PoseArray(poses=poses)
    message.header.frame_id = frame
    message.header.stamp = rospy.Time.now()
    return message


class ReplannerMemoryTest(unittest.TestCase):

    def test_memory_stays_flat_over_100000_poses(self):
        rospy.init_node('replanner_memory_test')
        status = Collector('replanner/status', PlanStatus)
        visited = rospy.Publisher('visited', PoseArray, queue_size=1)
        pose = rospy.Publisher('pose', PoseStamped, queue_size=BURST * 4)
        goal = rospy.Publisher('goal', PointStamped, queue_size=1, latch=True)
        updated = rospy.Publisher('updated_polygon', PolygonWithHolesStamped, queue_size=1)
        for publisher in (visited, pose, goal, updated):
            self.assertTrue(wait_until(lambda: publisher.get_num_connections() > 0, 30.0))
        pid = node_pid('/replanner', '/replanner_memory_test')
        poses = [lawnmower_pose(i) for i in range(VISITED_STEPS[-1])]

        visited.publish(stamped('map', poses[:FIRST]))
        time.sleep(2.0)
        at_first = rss_bytes(pid)
        for count in VISITED_STEPS:
            visited.publish(stamped('map', poses[:count]))
            time.sleep(1.0)
        began = time.time()
        message = PoseStamped()
        message.header.frame_id = 'map'
        for i in range(VISITED_STEPS[-1], TOTAL):
            message.header.stamp = rospy.Time.now()
            message.pose = lawnmower_pose(i)
            pose.publish(message)
            if i % BURST == 0:
                time.sleep(PAUSE_S)
        time.sleep(2.0)
        at_total = rss_bytes(pid)
        print('replanner_memory: VmRSS %.2f MB after %d poses, %.2f MB after %d (%+.2f MB); '
              '%d poses sent in %.1f s' % (at_first / 1e6, FIRST, at_total / 1e6, TOTAL,
                                           (at_total - at_first) / 1e6, TOTAL - VISITED_STEPS[-1],
                                           time.time() - began))

        goal_message = PointStamped()
        goal_message.header.frame_id = 'map'
        goal_message.point.x = 28.0
        goal_message.point.y = 28.0
        goal.publish(goal_message)
        time.sleep(0.5)
        polygon = PolygonWithHolesStamped()
        polygon.header.frame_id = 'map'
        polygon.polygon.hull = Polygon(points=[Point32(x=x, y=y) for x, y in
                                               [(0, 0), (30, 0), (30, 30), (0, 30)]])
        updated.publish(polygon)
        self.assertTrue(status.wait_for(1, TIMEOUT_S), 'no replanner/status')
        self.assertTrue(status.messages[-1].success, status.messages[-1].message)
        # At 2 500 poses a second the node's `pose` queue may drop a few (a robot at 10 Hz
        # loses none); the history must hold every pose that arrived.
        counted = int(re.search(r'last of (\d+) visited poses', status.messages[-1].message)
                      .group(1))
        print('replanner_memory: the replan counts %d visited poses' % counted)
        self.assertGreater(counted, TOTAL - 1000)
        self.assertLessEqual(counted, TOTAL)
        self.assertLess(at_total - at_first, GROWTH_LIMIT_BYTES,
                        'VmRSS grew from %d to %d bytes' % (at_first, at_total))


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'replanner_memory', ReplannerMemoryTest)
