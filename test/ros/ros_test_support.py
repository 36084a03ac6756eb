"""Helpers shared by the rostests: the mission's geometry and waiting for messages."""

import math
import time

import rospy
import yaml


def load_mission(path):
    """The mission file as a dict (polygon hull and holes, start, goal, parameters)."""
    with open(path) as stream:
        return yaml.safe_load(stream)


def inside_ring(point, ring):
    """Even-odd test of a point against a ring of [x, y] pairs (boundary counts inside
    within 1e-6 m)."""
    x, y = point
    inside = False
    n = len(ring)
    for i in range(n):
        (ax, ay), (bx, by) = ring[i], ring[(i + 1) % n]
        if distance_to_segment(point, (ax, ay), (bx, by)) <= 1e-6:
            return True
        if (ay > y) != (by > y):
            cross_x = ax + (y - ay) * (bx - ax) / (by - ay)
            if x < cross_x:
                inside = not inside
    return inside


def distance_to_segment(p, a, b):
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0.0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2))
    return math.hypot(p[0] - (ax + t * dx), p[1] - (ay + t * dy))


def strictly_inside_hole(point, holes, margin=1e-6):
    """True when the point lies inside a hole farther than `margin` from its boundary."""
    for hole in holes:
        if inside_ring(point, hole):
            edges = [distance_to_segment(point, hole[i], hole[(i + 1) % len(hole)])
                     for i in range(len(hole))]
            if min(edges) > margin:
                return True
    return False


class Collector:
    """Keeps every message of a topic, with the time it arrived."""

    def __init__(self, topic, message_type):
        self.messages = []
        self.subscriber = rospy.Subscriber(topic, message_type, self._receive, queue_size=100)

    def _receive(self, message):
        self.messages.append(message)

    def wait_for(self, count, timeout):
        """Waits until `count` messages arrived; returns whether they did."""
        deadline = time.time() + timeout
        while len(self.messages) < count and time.time() < deadline and not rospy.is_shutdown():
            time.sleep(0.05)
        return len(self.messages) >= count


def yaw_of(orientation):
    return math.atan2(2.0 * (orientation.w * orientation.z + orientation.x * orientation.y),
                      1.0 - 2.0 * (orientation.y * orientation.y + orientation.z * orientation.z))
