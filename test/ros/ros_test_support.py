"""Helpers shared by the rostests: the mission's geometry and waiting for messages."""

import math
import time
import xmlrpc.client

import rosgraph
import rospy
import yaml
from geometry_msgs.msg import Point32, PointStamped, Polygon
from kinematic_coverage.msg import PolygonWithHolesStamped
from rosgraph_msgs.msg import Log


def load_mission(path):
    """The mission file as a dict (polygon hull and holes, start, goal, parameters)."""
    with open(path) as stream:
        return yaml.safe_load(stream)


def stamped_polygon(hull, holes=(), frame='map'):
    """A polygon with holes (lists of (x, y)) stamped in `frame`."""
    def ring(points):
        return Polygon(points=[Point32(x=x, y=y, z=0.0) for x, y in points])

    message = PolygonWithHolesStamped()
    message.header.frame_id = frame
    message.header.stamp = rospy.Time.now()
    message.polygon.hull = ring(hull)
    message.polygon.holes = [ring(hole) for hole in holes]
    return message


def point_message(x, y, frame='map'):
    """A stamped point (a start or goal) in `frame`."""
    message = PointStamped()
    message.header.frame_id = frame
    message.header.stamp = rospy.Time.now()
    message.point.x = x
    message.point.y = y
    return message


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


def wait_until(condition, timeout):
    """Polls `condition` until it holds or `timeout` seconds passed; returns its last value."""
    deadline = time.time() + timeout
    while not condition() and time.time() < deadline and not rospy.is_shutdown():
        time.sleep(0.05)
    return condition()


def wait_for_subscribers(publisher, nodes, timeout=30.0):
    """Waits until every node named in `nodes` (e.g. '/replanner') is connected to `publisher`;
    returns whether they are. A count of connections is not enough when the test itself
    listens to the topic it publishes on."""
    def connected():
        return set(nodes) <= {c.endpoint_id for c in publisher.impl.connections}
    return wait_until(connected, timeout)


def node_pid(name, caller):
    """The process id of a running node, from its XML-RPC API (as `rosnode info` finds it)."""
    master = rosgraph.Master(caller)
    uri = master.lookupNode(name)
    code, _, pid = xmlrpc.client.ServerProxy(uri).getPid(caller)
    if code != 1:
        raise RuntimeError('getPid failed for %s' % name)
    return pid


def rss_bytes(pid):
    """Resident set size of a process (VmRSS in /proc/<pid>/status); None once it is gone."""
    try:
        with open('/proc/%d/status' % pid) as status:
            for line in status:
                if line.startswith('VmRSS:'):
                    return int(line.split()[1]) * 1024
    except FileNotFoundError:
        pass
    return None


class RejectionChecks:
    """Mixin for a unittest.TestCase with a `log` Collector of /rosout: a bad message to a node
    gives exactly one ROS_ERROR from it, exactly one failed ~status and nothing on its
    outputs; a good one after it is handled (docs/REFERENCE.md, Nodes and topics)."""

    TIMEOUT_S = 30.0
    # A second error, status or output would have arrived by then.
    QUIET_S = 1.0

    def node_errors(self, node):
        return sum(1 for entry in self.log.messages
                   if entry.level == Log.ERROR and entry.name == node)

    def assert_rejected(self, node, status, outputs, send, expected=()):
        """Calls `send`; asserts one ROS_ERROR of `node`, one failed message on the `status`
        Collector naming every string of `expected`, and no new message on the `outputs`
        Collectors. Returns the status message."""
        statuses = len(status.messages)
        errors = self.node_errors(node)
        published = [len(output.messages) for output in outputs]
        send()
        self.assertTrue(status.wait_for(statuses + 1, self.TIMEOUT_S), 'no status from %s' % node)
        # The node's ROS_ERROR reaches /rosout a moment after its status.
        wait_until(lambda: self.node_errors(node) > errors, 10.0)
        time.sleep(self.QUIET_S)
        message = status.messages[statuses]
        self.assertFalse(message.success, message.message)
        for text in expected:
            self.assertIn(text, message.message)
        self.assertEqual(len(status.messages), statuses + 1, 'one status expected')
        self.assertEqual(self.node_errors(node) - errors, 1, 'one ROS_ERROR expected')
        self.assertEqual([len(output.messages) for output in outputs], published,
                         'nothing may be published for a bad message')
        return message

    def assert_handled(self, status, output, send):
        """Calls `send`; asserts a successful status and one new message on `output`, and
        returns that message."""
        statuses = len(status.messages)
        published = len(output.messages)
        send()
        self.assertTrue(status.wait_for(statuses + 1, self.TIMEOUT_S), 'no status')
        self.assertTrue(status.messages[-1].success, status.messages[-1].message)
        self.assertTrue(output.wait_for(published + 1, self.TIMEOUT_S), 'no output')
        return output.messages[-1]
