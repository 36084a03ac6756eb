#!/usr/bin/python3
"""Pipeline rostest: the lake mission through mission_publisher, coverage_planner and
smooth_trajectory_generator. The received trajectory lies in the free area, is
continuous, starts at the start and ends at the goal; both ~status report success."""

import math
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseArray
from kinematic_coverage.msg import PlanStatus
from nav_msgs.msg import OccupancyGrid, Path
from visualization_msgs.msg import MarkerArray

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ros_test_support import Collector, inside_ring, load_mission, strictly_inside_hole, wait_until, yaw_of  # noqa: E402

TIMEOUT_S = 60.0


class PipelineLakeTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('pipeline_lake_test')
        cls.mission = load_mission(rospy.get_param('~mission'))
        cls.waypoints = Collector('waypoint_list', PoseArray)
        cls.trajectory = Collector('trajectory', PoseArray)
        cls.path = Collector('trajectory_path', Path)
        cls.planner_status = Collector('coverage_planner/status', PlanStatus)
        cls.smoother_status = Collector('smooth_trajectory_generator/status', PlanStatus)
        cls.planner_markers = Collector('coverage_planner/markers', MarkerArray)
        cls.smoother_markers = Collector('smooth_trajectory_generator/markers', MarkerArray)
        cls.heatmap = Collector('smooth_trajectory_generator/coverage_heatmap', OccupancyGrid)
        for collector in (cls.waypoints, cls.trajectory, cls.path, cls.planner_status,
                          cls.smoother_status, cls.planner_markers, cls.smoother_markers,
                          cls.heatmap):
            collector.wait_for(1, TIMEOUT_S)

    def test_status_reports_success(self):
        self.assertTrue(self.planner_status.messages, 'no coverage_planner/status')
        self.assertTrue(self.planner_status.messages[-1].success,
                        self.planner_status.messages[-1].message)
        self.assertTrue(self.smoother_status.messages, 'no smooth_trajectory_generator/status')
        last = self.smoother_status.messages[-1]
        self.assertTrue(last.success, last.message)
        self.assertEqual(last.stage, 'smooth')

    def test_waypoints_start_and_end_at_the_mission_points(self):
        self.assertTrue(self.waypoints.messages, 'no waypoint_list')
        poses = self.waypoints.messages[-1].poses
        self.assertGreaterEqual(len(poses), 2)
        self.assertEqual(self.waypoints.messages[-1].header.frame_id, self.mission['frame_id'])
        start, goal = self.mission['start'], self.mission['goal']
        self.assertAlmostEqual(poses[0].position.x, start[0], places=6)
        self.assertAlmostEqual(poses[0].position.y, start[1], places=6)
        self.assertAlmostEqual(poses[-1].position.x, goal[0], places=6)
        self.assertAlmostEqual(poses[-1].position.y, goal[1], places=6)
        # The yaw of each waypoint is the heading of the leg leaving it.
        for a, b in zip(poses, poses[1:]):
            heading = math.atan2(b.position.y - a.position.y, b.position.x - a.position.x)
            difference = math.remainder(yaw_of(a.orientation) - heading, 2 * math.pi)
            self.assertLess(abs(difference), 1e-6)

    def test_trajectory_is_continuous_inside_and_from_start_to_goal(self):
        self.assertTrue(self.trajectory.messages, 'no trajectory')
        message = self.trajectory.messages[-1]
        poses = message.poses
        self.assertGreater(len(poses), 100)
        self.assertEqual(message.header.frame_id, self.mission['frame_id'])
        start, goal = self.mission['start'], self.mission['goal']
        self.assertLess(math.hypot(poses[0].position.x - start[0], poses[0].position.y - start[1]),
                        1e-6)
        self.assertLess(math.hypot(poses[-1].position.x - goal[0], poses[-1].position.y - goal[1]),
                        1e-6)
        step_limit = max(self.mission['segment_sampling_distance'],
                         self.mission['arc_sampling_distance']) + 1e-6
        hull = self.mission['polygon']['hull']
        holes = self.mission['polygon']['holes']
        for i, (a, b) in enumerate(zip(poses, poses[1:])):
            step = math.hypot(b.position.x - a.position.x, b.position.y - a.position.y)
            self.assertLessEqual(step, step_limit, 'poses %d and %d' % (i, i + 1))
        for i, pose in enumerate(poses):
            point = (pose.position.x, pose.position.y)
            self.assertTrue(inside_ring(point, hull), 'pose %d outside the hull' % i)
            self.assertFalse(strictly_inside_hole(point, holes), 'pose %d inside a hole' % i)

    def test_trajectory_path_is_stamped_with_planned_times(self):
        self.assertTrue(self.path.messages, 'no trajectory_path')
        path = self.path.messages[-1]
        self.assertEqual(len(path.poses), len(self.trajectory.messages[-1].poses))
        self.assertEqual(path.poses[0].header.stamp, path.header.stamp)
        stamps = [pose.header.stamp.to_sec() for pose in path.poses]
        self.assertTrue(all(b >= a for a, b in zip(stamps, stamps[1:])))
        self.assertGreater(stamps[-1] - stamps[0], 60.0)

    def test_markers_show_what_the_nodes_computed(self):
        self.assertTrue(self.planner_markers.messages, 'no coverage_planner/markers')
        planner = {marker.ns for marker in self.planner_markers.messages[-1].markers}
        for namespace in ('polygon', 'offset_free_area', 'cells', 'waypoint_path', 'waypoints',
                          'start_goal'):
            self.assertIn(namespace, planner)
        self.assertTrue(self.smoother_markers.messages, 'no smooth_trajectory_generator/markers')
        markers = self.smoother_markers.messages[-1].markers
        smoother = {marker.ns for marker in markers}
        for namespace in ('segments', 'arcs_inner'):
            self.assertIn(namespace, smoother)
        # What rviz draws stays small: the heatmap is one grid (a texture), not a primitive
        # per cell, and the path markers hold a few thousand points at most.
        self.assertNotIn('coverage_heatmap', smoother)
        self.assertLess(sum(max(1, len(marker.points)) for marker in markers), 20000)
        self.assertTrue(self.heatmap.messages, 'no smooth_trajectory_generator/coverage_heatmap')
        grid = self.heatmap.messages[-1]
        self.assertEqual(len(grid.data), grid.info.width * grid.info.height)
        self.assertGreater(grid.info.width * grid.info.height, 10000)
        seen = sum(1 for value in grid.data if 0 < value < 100)
        unseen = sum(1 for value in grid.data if value == 100)
        self.assertGreater(seen, 100 * max(1, unseen))

    def test_wall_band_turns_are_marked_where_allowed(self):
        # By default the lake's turns keep wall_distance: no closest_approach marker and no
        # warning. Let into the wall band (smoothing_clearance 0, the thesis's no-contact
        # check), its arcs pass an obstacle nearer than that: marked and warned of.
        markers = self.smoother_markers.messages[-1].markers
        self.assertNotIn('closest_approach', {marker.ns for marker in markers})
        self.assertNotIn('nearer than wall_distance', self.smoother_status.messages[-1].message)
        rospy.set_param('smooth_trajectory_generator/smoothing_clearance', 0.0)
        try:
            marker_count = len(self.smoother_markers.messages)
            status_count = len(self.smoother_status.messages)
            publisher = rospy.Publisher('waypoint_list', PoseArray, queue_size=1, latch=True)
            wait_until(lambda: publisher.get_num_connections() > 0, TIMEOUT_S)
            publisher.publish(self.waypoints.messages[-1])
            self.assertTrue(self.smoother_markers.wait_for(marker_count + 1, TIMEOUT_S))
            self.assertTrue(self.smoother_status.wait_for(status_count + 1, TIMEOUT_S))
            marked = [marker for marker in self.smoother_markers.messages[-1].markers
                      if marker.ns == 'closest_approach']
            self.assertEqual(len(marked), 2)
            self.assertIn('m from a wall', marked[1].text)
            last = self.smoother_status.messages[-1]
            self.assertTrue(last.success, last.message)
            self.assertIn('nearer than wall_distance', last.message)
        finally:
            rospy.delete_param('smooth_trajectory_generator/smoothing_clearance')

    def test_nodes_hold_only_the_paths_of_their_parameter_files(self):
        # pipeline.launch sets each node's config and mission paths, not 121 parameters and
        # the mission's geometry in every node's namespace.
        names = rospy.get_param_names()
        for node in ('coverage_planner', 'smooth_trajectory_generator', 'replanner'):
            self.assertTrue(rospy.get_param('/%s/config' % node).endswith('config/default.yaml'))
            self.assertEqual(rospy.get_param('/%s/mission' % node), rospy.get_param('~mission'))
            held = sorted(name for name in names if name.startswith('/%s/' % node))
            self.assertLessEqual(len(held), 3, held)
            self.assertNotIn('/%s/turning_radius' % node, held)
            self.assertNotIn('/%s/polygon' % node, names)


if __name__ == '__main__':
    rostest.rosrun('kinematic_coverage', 'pipeline_lake', PipelineLakeTest)
