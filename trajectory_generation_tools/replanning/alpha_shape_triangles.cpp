#include "trajectory_generation_tools/replanning/alpha_shape_triangles.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Alpha_shape_vertex_base_2<Kernel>;
using FaceBase = CGAL::Alpha_shape_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Triangulation = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using AlphaShape = CGAL::Alpha_shape_2<Triangulation>;

}  // namespace

std::vector<std::array<Point2, 3>> alphaShapeTriangles(const std::vector<Point2>& points,
                                                       double alpha) {
  if (!std::isfinite(alpha) || alpha <= 0.0) {
    throw InvalidInputError("the alpha-shape parameter must be > 0, got " + std::to_string(alpha));
  }
  std::vector<Kernel::Point_2> cgal_points;
  cgal_points.reserve(points.size());
  for (const Point2& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
      throw InvalidInputError("alpha shape: a point has a non-finite coordinate");
    }
    cgal_points.emplace_back(p.x(), p.y());
  }
  std::vector<std::array<Point2, 3>> triangles;
  if (cgal_points.size() < 3) return triangles;
  const AlphaShape shape(cgal_points.begin(), cgal_points.end(), alpha * alpha,
                         AlphaShape::REGULARIZED);
  for (auto face = shape.finite_faces_begin(); face != shape.finite_faces_end(); ++face) {
    if (shape.classify(face) != AlphaShape::INTERIOR) continue;
    std::array<Point2, 3> triangle;
    for (int i = 0; i < 3; ++i) {
      const Kernel::Point_2& p = face->vertex(i)->point();
      triangle[i] = Point2(p.x(), p.y());
    }
    triangles.push_back(triangle);
  }
  return triangles;
}

}  // namespace kinematic_coverage::core
