#!/usr/bin/python3
"""Replanning rostest: `updated_polygon` and `visited` in, a new `waypoint_list` and
`trajectory` out, starting at the last visited pose and avoiding the moved obstacles."""

import math
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point32, PoseArray, Polygon
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from visualization_msgs.msg import MarkerArray

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, strictly_inside_hole  # noqa: E402

TIMEOUT_S = 60.0
MOVED_HOLES = [[(9, 10), (14, 10), (14, 16), (9, 16)],
               [(20, 18), (25, 19), (26, 24), (21, 26), (18, 22)]]


class ReplanningTest(unittest.TestCase):

    def test_replan_from_the_last_visited_pose_around_moved_obstacles(self):
        rospy.init_node('replanning_test')
        trajectory = Collector('trajectory', PoseArray)
        waypoints = Collector('waypoint_list', PoseArray)
        status = Collector('replanner/status', PlanStatus)
        remaining = Collector('remaining_polygon', MarkerArray)
        self.assertTrue(trajectory.wait_for(1, TIMEOUT_S), 'no first trajectory')
        first = trajectory.messages[-1]
        visited = PoseArray(header=first.header, poses=first.poses[:len(first.poses) * 4 // 10])
        visited_publisher = rospy.Publisher('visited', PoseArray, queue_size=1, latch=True)
        updated_publisher = rospy.Publisher('updated_polygon', PolygonWithHolesStamped,
                                            queue_size=1, latch=True)
        visited_publisher.publish(visited)
        time.sleep(1.0)
        updated = PolygonWithHolesStamped()
        updated.header.frame_id = 'map'
        updated.header.stamp = rospy.Time.now()
        updated.polygon.hull = Polygon(points=[Point32(x=x, y=y) for x, y in
                                               [(0, 0), (30, 0), (30, 30), (0, 30)]])
        updated.polygon.holes = [Polygon(points=[Point32(x=x, y=y) for x, y in hole])
                                 for hole in MOVED_HOLES]
        trajectories = len(trajectory.messages)
        updated_publisher.publish(updated)

        self.assertTrue(status.wait_for(1, TIMEOUT_S), 'no replanner/status')
        self.assertTrue(status.messages[-1].success, status.messages[-1].message)
        self.assertTrue(remaining.wait_for(1, TIMEOUT_S), 'no remaining_polygon')
        self.assertTrue(trajectory.wait_for(trajectories + 1, TIMEOUT_S), 'no new trajectory')
        newest = max(waypoints.messages, key=lambda message: message.header.stamp)
        last = visited.poses[-1].position
        start = newest.poses[0].position
        self.assertLess(math.hypot(start.x - last.x, start.y - last.y), 1e-6)
        new_trajectory = trajectory.messages[-1]
        begin = new_trajectory.poses[0].position
        self.assertLess(math.hypot(begin.x - last.x, begin.y - last.y), 1e-6)
        for pose in new_trajectory.poses:
            self.assertFalse(strictly_inside_hole((pose.position.x, pose.position.y),
                                                  MOVED_HOLES))


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'replanning', ReplanningTest)
