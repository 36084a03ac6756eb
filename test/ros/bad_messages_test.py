#!/usr/bin/python3
"""Bad-message rostest: NaN and infinite coordinates, zero and non-unit quaternions, empty
waypoint lists, invalid polygons and frames that do not match the polygon's, sent to a
running smooth_trajectory_generator, replanner and coverage_planner. Each gives exactly one
ROS_ERROR, one failed ~status and nothing published; the next good message is handled.
The tests run in the order of their names (the smoother's first, before any polygon)."""

import math
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped, Pose, PoseArray, PoseStamped
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from rosgraph_msgs.msg import Log
from std_msgs.msg import Empty

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import (Collector, RejectionChecks, point_message, stamped_polygon,
                              wait_for_subscribers, wait_until)  # noqa: E402

SQUARE = [(0, 0), (30, 0), (30, 30), (0, 30)]
NAN = float('nan')
INF = float('inf')
SMOOTHER = '/smooth_trajectory_generator'
REPLANNER = '/replanner'
PLANNER = '/coverage_planner'


def polygon_message(hull=SQUARE, holes=(), frame='map'):
    return stamped_polygon(hull, holes, frame)


def pose(x, y, yaw=0.0, quaternion=None):
    message = Pose()
    message.position.x = x
    message.position.y = y
    if quaternion is None:
        quaternion = (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))
    (message.orientation.x, message.orientation.y, message.orientation.z,
     message.orientation.w) = quaternion
    return message


def pose_array(poses, frame='map'):
    message = PoseArray(poses=list(poses))
    message.header.frame_id = frame
    message.header.stamp = rospy.Time.now()
    return message


def pose_stamped(x, y, frame='map', quaternion=None):
    message = PoseStamped(pose=pose(x, y, quaternion=quaternion))
    message.header.frame_id = frame
    message.header.stamp = rospy.Time.now()
    return message


def lawnmower(frame='map'):
    """Two lanes of the 30 m square."""
    return pose_array([pose(2, 2), pose(28, 2), pose(28, 9), pose(2, 9)], frame)


def lane(count):
    """`count` poses 0.05 m apart along y = 2, heading east."""
    return [pose(2.0 + 0.05 * i, 2.0) for i in range(count)]


class BadMessagesTest(RejectionChecks, unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('bad_messages_test')
        latched = dict(queue_size=10, latch=True)
        cls.polygon = rospy.Publisher('polygon', PolygonWithHolesStamped, **latched)
        cls.updated = rospy.Publisher('updated_polygon', PolygonWithHolesStamped, **latched)
        cls.waypoint_list = rospy.Publisher('waypoint_list', PoseArray, queue_size=10)
        cls.visited = rospy.Publisher('visited', PoseArray, queue_size=10)
        cls.pose = rospy.Publisher('pose', PoseStamped, queue_size=100)
        cls.goal = rospy.Publisher('goal', PointStamped, **latched)
        cls.start = rospy.Publisher('start', PointStamped, **latched)
        cls.activate = rospy.Publisher('activate', Empty, queue_size=10)
        cls.log = Collector('/rosout', Log)
        cls.trajectory = Collector('trajectory', PoseArray)
        cls.waypoints = Collector('waypoint_list', PoseArray)
        cls.smoother_status = Collector('smooth_trajectory_generator/status', PlanStatus)
        cls.replanner_status = Collector('replanner/status', PlanStatus)
        cls.planner_status = Collector('coverage_planner/status', PlanStatus)
        for publisher, nodes in ((cls.waypoint_list, [SMOOTHER]), (cls.visited, [REPLANNER]),
                                 (cls.pose, [REPLANNER]), (cls.activate, [PLANNER]),
                                 (cls.polygon, [SMOOTHER, REPLANNER, PLANNER]),
                                 (cls.updated, [SMOOTHER, REPLANNER])):
            if not wait_for_subscribers(publisher, nodes):
                raise RuntimeError('%s do not all subscribe to %s' % (nodes, publisher.name))
        # A status or trajectory published before its connection opens would be missed.
        for collector in (cls.trajectory, cls.smoother_status, cls.replanner_status,
                          cls.planner_status):
            if not wait_until(lambda: collector.subscriber.get_num_connections() > 0, 30.0):
                raise RuntimeError('nothing publishes %s' % collector.subscriber.name)

    def send_waypoints(self, message):
        return lambda: self.waypoint_list.publish(message)

    def reject_waypoints(self, message, *expected):
        return self.assert_rejected(SMOOTHER, self.smoother_status, [self.trajectory],
                                    self.send_waypoints(message), expected)

    def test_1_smoother(self):
        # Before any polygon a good waypoint list waits; the polygon then smooths it.
        trajectories = len(self.trajectory.messages)
        self.waypoint_list.publish(lawnmower())
        time.sleep(1.0)
        self.assertEqual(len(self.trajectory.messages), trajectories)
        self.assertEqual(len(self.smoother_status.messages), 0)
        self.assert_handled(self.smoother_status, self.trajectory,
                            lambda: self.polygon.publish(polygon_message()))

        self.reject_waypoints(pose_array([]), 'no poses')
        self.reject_waypoints(pose_array([pose(2, 2), pose(NAN, 2), pose(28, 9)]),
                              'waypoint 1', 'non-finite')
        self.reject_waypoints(pose_array([pose(2, 2), pose(28, INF)]), 'waypoint 1', 'non-finite')
        self.reject_waypoints(pose_array([pose(2, 2, quaternion=(0, 0, 0, 0)), pose(28, 2)]),
                              'waypoint 0', 'unit quaternion')
        self.reject_waypoints(pose_array([pose(2, 2), pose(28, 2, quaternion=(0, 0, 0.5, 0.5))]),
                              'waypoint 1', 'unit quaternion')
        self.reject_waypoints(pose_array([pose(2, 2), pose(28, 2, quaternion=(0, 0, NAN, 1))]),
                              'waypoint 1', 'unit quaternion')
        self.reject_waypoints(lawnmower('odom'), "'odom'", "'map'")
        # An empty frame is map, the polygon's frame.
        self.assert_handled(self.smoother_status, self.trajectory,
                            self.send_waypoints(lawnmower('')))
        # One pose is a robot that stays: a one-pose trajectory.
        one = self.assert_handled(self.smoother_status, self.trajectory,
                                  self.send_waypoints(pose_array([pose(5, 6, yaw=1.0)])))
        self.assertEqual(len(one.poses), 1)
        self.assertEqual((one.poses[0].position.x, one.poses[0].position.y), (5.0, 6.0))
        self.assertAlmostEqual(one.poses[0].orientation.z, math.sin(0.5), places=9)

        # An invalid polygon is rejected when it arrives and forgotten: a waypoint list then
        # waits for the next valid polygon.
        for bad, expected in (
                (polygon_message([(0, 0), (30, 0), (30, NAN), (0, 30)]), 'polygon: '),
                (polygon_message([]), 'polygon: '),
                (polygon_message([(0, 0), (30, 30), (30, 0), (0, 30)]), 'self-intersecting')):
            self.assert_rejected(SMOOTHER, self.smoother_status, [self.trajectory],
                                 lambda: self.updated.publish(bad), (expected,))
        trajectories = len(self.trajectory.messages)
        self.waypoint_list.publish(lawnmower())
        time.sleep(1.0)
        self.assertEqual(len(self.trajectory.messages), trajectories)
        self.assert_handled(self.smoother_status, self.trajectory,
                            lambda: self.updated.publish(polygon_message()))
        # A polygon in another frame: the next waypoint list in map is rejected.
        self.updated.publish(polygon_message(frame='boat'))
        time.sleep(0.5)
        self.reject_waypoints(lawnmower(), "'map'", "'boat'")
        self.assert_handled(self.smoother_status, self.trajectory,
                            self.send_waypoints(lawnmower('boat')))
        self.assert_handled(self.smoother_status, self.trajectory,
                            lambda: (self.updated.publish(polygon_message()), time.sleep(0.5),
                                     self.waypoint_list.publish(lawnmower())))

    def reject_history(self, send, *expected):
        self.assert_rejected(REPLANNER, self.replanner_status, [self.waypoints], send, expected)

    def test_2_replanner(self):
        # The replanner knows the polygon's frame (map) from test_1's polygons.
        self.goal.publish(point_message(28, 28))
        self.visited.publish(pose_array(lane(100)))
        time.sleep(0.5)
        for i in range(100, 150):
            self.pose.publish(pose_stamped(2.0 + 0.05 * i, 2.0))
        time.sleep(1.0)
        # Each bad message is refused and leaves the 150 good poses as they are.
        self.reject_history(lambda: self.visited.publish(pose_array(lane(40), 'odom')),
                            "visited is in frame 'odom'", "'map'")
        self.reject_history(lambda: self.pose.publish(pose_stamped(9, 2, 'odom')),
                            "pose is in frame 'odom'", "'map'")
        self.reject_history(lambda: self.visited.publish(pose_array(lane(10) + [pose(NAN, 2)])),
                            'visited pose 10', 'non-finite')
        self.reject_history(lambda: self.visited.publish(pose_array([pose(2, 2), pose(3, INF)])),
                            'visited pose 1', 'non-finite')
        self.reject_history(lambda: self.visited.publish(
            pose_array([pose(2, 2, quaternion=(0, 0, 0, 0))])), 'visited pose 0', 'unit quaternion')
        self.reject_history(lambda: self.pose.publish(pose_stamped(NAN, 2)), 'pose', 'non-finite')
        self.reject_history(lambda: self.pose.publish(pose_stamped(9, 2, quaternion=(0, 0, 0, 0))),
                            'pose', 'unit quaternion')
        self.reject_history(lambda: self.pose.publish(pose_stamped(3e8, 2)), 'coordinate limit')
        # A goal in another frame; then the updated polygon replans from the good history.
        self.goal.publish(point_message(28, 28, 'odom'))
        time.sleep(0.5)
        self.reject_history(lambda: self.updated.publish(polygon_message()),
                            "goal is in frame 'odom'")
        self.goal.publish(point_message(28, 28, ''))
        time.sleep(0.5)
        replanned = self.assert_handled(self.replanner_status, self.waypoints,
                                        lambda: self.updated.publish(polygon_message()))
        self.assertIn('last of 150 visited poses', self.replanner_status.messages[-1].message)
        last = replanned.poses[0].position
        self.assertAlmostEqual(last.x, 2.0 + 0.05 * 149, places=6)
        # An updated polygon in another frame than the history.
        self.goal.publish(point_message(28, 28, 'boat'))
        time.sleep(0.5)
        self.reject_history(lambda: self.updated.publish(polygon_message(frame='boat')),
                            "visited poses are in frame 'map'", "'boat'")
        # The polygon's frame is now boat: a history in boat is accepted and replanned.
        self.visited.publish(pose_array(lane(20), 'boat'))
        time.sleep(0.5)
        self.assert_handled(self.replanner_status, self.waypoints,
                            lambda: self.updated.publish(polygon_message(frame='boat')))
        self.assertIn('last of 20 visited poses', self.replanner_status.messages[-1].message)
        self.updated.publish(polygon_message())
        time.sleep(0.5)

    def plan(self):
        return lambda: (time.sleep(0.5), self.activate.publish(Empty()))

    def reject_plan(self, *expected):
        self.assert_rejected(PLANNER, self.planner_status, [self.waypoints], self.plan(), expected)

    def test_3_coverage_planner(self):
        self.polygon.publish(polygon_message())
        self.start.publish(point_message(1, 1))
        self.goal.publish(point_message(29, 29))
        self.assert_handled(self.planner_status, self.waypoints, self.plan())
        self.start.publish(point_message(NAN, 1))
        self.reject_plan('start', 'nan')
        self.start.publish(point_message(1, 1))
        self.goal.publish(point_message(INF, 29))
        self.reject_plan('goal', 'inf')
        self.goal.publish(point_message(29, 29))
        self.polygon.publish(polygon_message([]))
        self.reject_plan('hull')
        # An empty frame is map: in a polygon's frame with no transform from map, refused.
        self.polygon.publish(polygon_message(frame='lake'))
        self.start.publish(point_message(1, 1, ''))
        self.goal.publish(point_message(29, 29, 'lake'))
        self.reject_plan("start is in frame 'map'", "'lake'")
        self.polygon.publish(polygon_message())
        self.start.publish(point_message(1, 1, ''))
        self.goal.publish(point_message(29, 29, ''))
        self.assert_handled(self.planner_status, self.waypoints, self.plan())
        # ~plan_on_receive of the wrong type: each message that would plan is refused.
        rospy.set_param('coverage_planner/plan_on_receive', 'yes')
        self.assert_rejected(PLANNER, self.planner_status, [self.waypoints],
                             lambda: self.start.publish(point_message(2, 2)),
                             ('plan_on_receive', 'true or false', "'yes'"))
        rospy.set_param('coverage_planner/plan_on_receive', True)
        self.assert_handled(self.planner_status, self.waypoints,
                            lambda: self.start.publish(point_message(1, 1)))
        rospy.set_param('coverage_planner/plan_on_receive', False)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'bad_messages', BadMessagesTest)
