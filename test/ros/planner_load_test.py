#!/usr/bin/python3
"""Reliability rostest, nodes under load: a burst of 1 000 polygons (100 a second for 10 s) to a
coverage_planner with plan_on_receive. Polygon k is a rectangle with six holes, placed at
x = 100 k m and 60 + k % 7 m wide, so that a waypoint list tells which polygon it answers;
planning one takes longer than the 10 ms between them. The node plans one polygon at a time
and keeps only the newest one waiting (its polygon subscriber has a queue of 1), so after
the burst its last waypoint list must answer the last polygon within seconds; it must still
answer its ~plan service, and its resident memory, sampled during and after the burst, must
settle."""

import sys
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point32, PointStamped, PoseArray, Polygon
from kinematic_coverage.msg import PlanStatus, PolygonWithHolesStamped
from std_srvs.srv import Trigger

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, inside_ring, node_pid, rss_bytes  # noqa: E402

RATE_HZ = 100
BURST_S = 10
POLYGONS = RATE_HZ * BURST_S
SPACING_M = 100.0
TIMEOUT_S = 30.0
# The last polygon's waypoint list must arrive this soon after it was published; answering
# every queued polygon in turn would take minutes.
ANSWER_S = 10.0
# Bound on the resident memory after the burst: twice the first second's plus this.
RSS_SLACK_BYTES = 50 * 1024 * 1024
START = (-5.0, 5.0)
GOAL = (-5.0, 10.0)


def hull_of(k):
    """Polygon k's hull: a rectangle 60 + k % 7 m wide and 40 + k % 5 m high at x = 100 k."""
    x = SPACING_M * k
    width = 60.0 + k % 7
    height = 40.0 + k % 5
    return [(x, 0.0), (x + width, 0.0), (x + width, height), (x, height)]


def holes_of(k):
    """Six 3 x 3 m square holes (clockwise) in two rows across polygon k."""
    hull = hull_of(k)
    width = hull[1][0] - hull[0][0]
    height = hull[2][1]
    holes = []
    for i in range(3):
        for j in range(2):
            cx = hull[0][0] + width * (i + 1) / 4.0
            cy = height * (j + 1) / 3.0 + 2.0 * (i % 2)
            holes.append([(cx - 1.5, cy - 1.5), (cx - 1.5, cy + 1.5), (cx + 1.5, cy + 1.5),
                          (cx + 1.5, cy - 1.5)])
    return holes


def ring(points):
    return Polygon(points=[Point32(x=x, y=y, z=0.0) for x, y in points])


def polygon_message(k):
    message = PolygonWithHolesStamped()
    message.header.frame_id = 'map'
    message.header.stamp = rospy.Time.now()
    message.polygon.hull = ring(hull_of(k))
    message.polygon.holes = [ring(hole) for hole in holes_of(k)]
    return message


def point_message(x, y):
    message = PointStamped()
    message.header.frame_id = 'map'
    message.header.stamp = rospy.Time.now()
    message.point.x = x
    message.point.y = y
    return message


def polygon_answered(waypoints):
    """The polygon whose hull holds every waypoint but the start and the goal (joined from
    outside), or None."""
    inner = [(pose.position.x, pose.position.y) for pose in waypoints.poses[1:-1]]
    if not inner:
        return None
    k = int(round(inner[0][0] / SPACING_M))
    if all(inside_ring(point, hull_of(k)) for point in inner):
        return k
    return None


class PlannerLoadTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('planner_load_test')
        # Every polygon leaves this process (the queue holds the whole burst): only the
        # node may drop stale ones.
        cls.polygon = rospy.Publisher('polygon', PolygonWithHolesStamped, queue_size=POLYGONS,
                                      latch=True)
        cls.start = rospy.Publisher('start', PointStamped, queue_size=1, latch=True)
        cls.goal = rospy.Publisher('goal', PointStamped, queue_size=1, latch=True)
        cls.waypoints = Collector('waypoint_list', PoseArray)
        cls.status = Collector('coverage_planner/status', PlanStatus)
        rospy.wait_for_service('coverage_planner/plan', TIMEOUT_S)
        cls.plan_service = rospy.ServiceProxy('coverage_planner/plan', Trigger)
        while cls.polygon.get_num_connections() == 0 and not rospy.is_shutdown():
            time.sleep(0.05)
        cls.pid = node_pid('/coverage_planner', '/planner_load_test')

    def test_burst_of_polygons(self):
        self.start.publish(point_message(*START))
        self.goal.publish(point_message(*GOAL))
        time.sleep(0.5)
        samples = []  # (seconds since the burst began, RSS bytes)
        began = time.time()
        sampling = threading.Event()

        def sample():
            while not sampling.is_set():
                rss = rss_bytes(self.pid)
                if rss is None:
                    return
                samples.append((time.time() - began, rss))
                time.sleep(0.25)

        sampler = threading.Thread(target=sample, daemon=True)
        sampler.start()
        self.addCleanup(sampling.set)
        rate = rospy.Rate(RATE_HZ)
        for k in range(POLYGONS):
            self.polygon.publish(polygon_message(k))
            rate.sleep()
        last_sent = time.time()
        burst_s = last_sent - began
        answered_in_burst = len(self.waypoints.messages)

        # The last polygon is answered within seconds, not after the queue of the others.
        deadline = last_sent + ANSWER_S
        while time.time() < deadline and not (
                self.waypoints.messages and
                polygon_answered(self.waypoints.messages[-1]) == POLYGONS - 1):
            time.sleep(0.05)
        answer_s = time.time() - last_sent
        self.assertEqual(polygon_answered(self.waypoints.messages[-1]), POLYGONS - 1,
                         'the last waypoint list does not answer the last polygon %.1f s '
                         'after it was published' % answer_s)
        # And nothing older comes after it: the node does not work through a backlog.
        count = len(self.waypoints.messages)
        time.sleep(2.0)
        for message in self.waypoints.messages[count:]:
            self.assertEqual(polygon_answered(message), POLYGONS - 1)

        # Still alive and responsive: the service plans the last polygon again.
        count = len(self.waypoints.messages)
        called = time.time()
        answer = self.plan_service()
        service_s = time.time() - called
        self.assertTrue(answer.success, answer.message)
        self.assertTrue(self.waypoints.wait_for(count + 1, TIMEOUT_S))
        self.assertEqual(polygon_answered(self.waypoints.messages[-1]), POLYGONS - 1)

        time.sleep(1.0)
        sampling.set()
        sampler.join()
        self.assertIsNotNone(rss_bytes(self.pid), 'coverage_planner is gone')
        first_second = max(rss for t, rss in samples if t <= 1.0)
        during = max(rss for t, rss in samples if t <= burst_s)
        final = samples[-1][1]
        failed = sum(1 for status in self.status.messages if not status.success)
        rospy.loginfo(
            'planner_load: %d polygons in %.1f s; %d waypoint lists during the burst, %d in '
            'all, %d failed plans; last polygon answered %.2f s after it was sent; ~plan '
            'answered in %.2f s; RSS %.1f MB after 1 s, %.1f MB max during the burst, '
            '%.1f MB at the end', POLYGONS, burst_s, answered_in_burst,
            len(self.waypoints.messages), failed, answer_s, service_s, first_second / 1e6,
            during / 1e6, final / 1e6)
        print('planner_load: RSS samples (s, MB): %s' % ', '.join(
            '(%.2f, %.1f)' % (t, rss / 1e6) for t, rss in samples))
        self.assertEqual(failed, 0, [s.message for s in self.status.messages if not s.success])
        self.assertLess(final, 2 * first_second + RSS_SLACK_BYTES)
        self.assertLess(during, 2 * first_second + RSS_SLACK_BYTES)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'planner_load', PlannerLoadTest)
