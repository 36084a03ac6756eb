#include "trajectory_generation_tools/plot/coverage_plot.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// Visits of the test heatmap's cells: 0 left of x = 5, 1 right of x = 15 below y = 8,
/// 3 outside the hull (hidden by the clip), 2 elsewhere.
std::uint16_t sceneVisits(const Point2& centre) {
  if (centre.x() + centre.y() > 42.0) return 3;
  if (centre.x() < 5.0) return 0;
  if (centre.x() > 15.0 && centre.y() < 8.0) return 1;
  return 2;
}

/// A 30 x 20 m area with its top-right corner cut off and one square obstacle, a heatmap of
/// 1 m cells reaching beyond the hull, and a path well away from the probed points.
CoveragePlotData scene() {
  CoveragePlotData data;
  data.free_area.hull = {{0, 0}, {30, 0}, {30, 12}, {22, 20}, {0, 20}};
  data.free_area.holes = {{{8, 6}, {8, 12}, {14, 12}, {14, 6}}};
  data.offset_parts = {PolygonWithHoles{{{1, 1}, {29, 1}, {29, 11.6}, {21.6, 19}, {1, 19}},
                                        {{{7, 5}, {7, 13}, {15, 13}, {15, 5}}}}};
  Heatmap heatmap;
  heatmap.origin = Point2(-1.0, -1.0);
  heatmap.cell_size = 1.0;
  heatmap.columns = 32;
  heatmap.rows = 22;
  for (int row = 0; row < heatmap.rows; ++row) {
    for (int column = 0; column < heatmap.columns; ++column) {
      heatmap.visits.push_back(
          sceneVisits(heatmap.origin + Point2(column + 0.5, row + 0.5) * heatmap.cell_size));
    }
  }
  data.heatmap = heatmap;
  data.waypoints = {{6, 2, M_PI / 2}, {6, 17, 0.0}, {26, 17, 0.0}};
  for (int k = 0; k <= 15; ++k) data.trajectory.push_back({6.0, 2.0 + k, M_PI / 2});
  for (int k = 1; k <= 20; ++k) data.trajectory.push_back({6.0 + k, 17.0, 0.0});
  data.start = Point2(6, 2);
  data.goal = Point2(26, 17);
  data.title_lines = {"Test scene", "coverage 80.0 %"};
  return data;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};

/// A PNG file read back with cairo.
class PngImage {
 public:
  explicit PngImage(const std::string& path)
      : surface_(cairo_image_surface_create_from_png(path.c_str())) {}

  bool valid() const { return cairo_surface_status(surface_.get()) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface_.get()); }
  int height() const { return cairo_image_surface_get_height(surface_.get()); }

  /// Colour of the pixel containing image point `pixel`.
  PlotColour colourAt(const Point2& pixel) const {
    const int x = static_cast<int>(std::floor(pixel.x()));
    const int y = static_cast<int>(std::floor(pixel.y()));
    const unsigned char* row = cairo_image_surface_get_data(surface_.get()) +
                               y * cairo_image_surface_get_stride(surface_.get());
    const std::uint32_t value = reinterpret_cast<const std::uint32_t*>(row)[x];
    return {static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 8),
            static_cast<std::uint8_t>(value)};
  }

 private:
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface_;
};

/// A fresh path in the test's temporary directory.
std::string tempPng(const std::string& name) {
  const std::string path = ::testing::TempDir() + "coverage_plot_" + name + ".png";
  std::remove(path.c_str());
  return path;
}

void expectColour(const PlotColour& expected, const PlotColour& actual, const std::string& what) {
  EXPECT_EQ(expected.red, actual.red) << what;
  EXPECT_EQ(expected.green, actual.green) << what;
  EXPECT_EQ(expected.blue, actual.blue) << what;
}

TEST(CoveragePlotTest, WritesPngOfRequestedSize) {
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  const std::string path = tempPng("size");
  plot.writePng(scene(), path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());
  EXPECT_EQ(800, image.width());
  EXPECT_EQ(600, image.height());
}

TEST(CoveragePlotTest, AutomaticHeightFollowsTheAreaAtEqualAspect) {
  const CoveragePlot plot;
  const CoveragePlotData data = scene();
  const CoveragePlotLayout layout = plot.layout(data);
  const std::string path = tempPng("auto_height");
  plot.writePng(data, path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());
  EXPECT_EQ(1200, image.width());
  EXPECT_EQ(layout.height, image.height());
  // The 30 x 20 m area is wider than high, and so is the box that fits it closely.
  EXPECT_LT(layout.box_height, layout.box_width);
  EXPECT_GT(layout.box_height, 0.6 * layout.box_width);
  for (const Point2& corner : {Point2(0, 0), Point2(30, 20)}) {
    const Point2 p = layout.toPixel(corner);
    EXPECT_GT(p.x(), layout.box_left);
    EXPECT_LT(p.x(), layout.box_left + layout.box_width);
    EXPECT_GT(p.y(), layout.box_top);
    EXPECT_LT(p.y(), layout.box_top + layout.box_height);
  }
  // Equal aspect: a metre along x and along y span the same pixels.
  const Point2 origin = layout.toPixel(Point2(0, 0));
  EXPECT_NEAR((layout.toPixel(Point2(1, 0)) - origin).norm(),
              (layout.toPixel(Point2(0, 1)) - origin).norm(), 1e-9);
}

TEST(CoveragePlotTest, PixelsShowObstaclesHeatmapAndBackground) {
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  const CoveragePlotData data = scene();
  const CoveragePlotLayout layout = plot.layout(data);
  const std::string path = tempPng("probes");
  plot.writePng(data, path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());

  expectColour(kObstacleColour, image.colourAt(layout.toPixel(Point2(11.5, 9.5))),
               "inside the hole, over heatmap cells");
  expectColour(CoveragePlot::visitColour(0), image.colourAt(layout.toPixel(Point2(2.5, 15.5))),
               "unseen free cell");
  expectColour(CoveragePlot::visitColour(1), image.colourAt(layout.toPixel(Point2(18.5, 3.5))),
               "cell seen once");
  expectColour(CoveragePlot::visitColour(2), image.colourAt(layout.toPixel(Point2(10.5, 15.5))),
               "cell seen twice");
  expectColour(kBackgroundColour, image.colourAt(layout.toPixel(Point2(29.0, 19.0))),
               "outside the hull, over heatmap cells");
  expectColour(kBackgroundColour, image.colourAt(Point2(2.0, 2.0)), "image corner");
}

TEST(CoveragePlotTest, ActualPoseArrowsAreBlackOverARedTrajectory) {
  // The thesis's Fig. 4.3: the desired trajectory in red, the poses driven as black arrows.
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  CoveragePlotData data = scene();
  data.heatmap.reset();
  data.actual_pose_arrows = {{20.0, 4.0, 0.0}, {24.0, 4.0, M_PI / 2}};
  const CoveragePlotLayout layout = plot.layout(data);
  const std::string path = tempPng("pose_arrows");
  plot.writePng(data, path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());
  const PlotColour line = image.colourAt(layout.toPixel(Point2(6.0, 9.5)));
  EXPECT_GT(line.red, 150);
  EXPECT_LT(line.green, 90);
  EXPECT_LT(line.blue, 90);
  for (const Pose2& arrow : data.actual_pose_arrows) {
    const PlotColour centre = image.colourAt(layout.toPixel(arrow.position()));
    EXPECT_LT(centre.red + centre.green + centre.blue, 150) << arrow.x;
  }
  data.actual_pose_arrows.push_back({std::nan(""), 0.0, 0.0});
  EXPECT_THROW(plot.writePng(data, tempPng("bad_arrows")), InvalidInputError);
}

TEST(CoveragePlotTest, TheClosestApproachIsCircledWithACross) {
  // Where the trajectory comes nearer the walls than wall_distance: a circle with a cross
  // whose arms meet there, in the unseen region's colour; nothing there when unset.
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  CoveragePlotData data = scene();
  const Point2 approach(20.0, 4.0);
  const CoveragePlotLayout layout = plot.layout(data);
  const std::string without = tempPng("no_approach");
  plot.writePng(data, without);
  expectColour(CoveragePlot::visitColour(1), PngImage(without).colourAt(layout.toPixel(approach)),
               "no mark");
  data.closest_approach = approach;
  const std::string path = tempPng("approach");
  plot.writePng(data, path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());
  const PlotColour centre = image.colourAt(layout.toPixel(approach));
  EXPECT_GT(centre.red, 150);
  EXPECT_LT(centre.green, 60);
  EXPECT_GT(centre.blue, 60);
  data.closest_approach = Point2(std::nan(""), 1.0);
  EXPECT_THROW(plot.writePng(data, tempPng("bad_approach")), InvalidInputError);
}

TEST(CoveragePlotTest, PartsNotEnteredAreOutlinedDashed) {
  // A part of the offset free area that is not entered: its outline in the unseen region's
  // colour (dashed: some of the points along an edge), none there when unset.
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  CoveragePlotData data = scene();
  const PolygonWithHoles part = {{{20, 3}, {28, 3}, {28, 9}, {20, 9}}, {}};
  const CoveragePlotLayout layout = plot.layout(data);
  const auto magentaAlongTheBottomEdge = [&](const std::string& path) {
    const PngImage image(path);
    int count = 0;
    for (int k = 0; k <= 40; ++k) {
      const PlotColour colour = image.colourAt(layout.toPixel(Point2(20.0 + 0.2 * k, 3.0)));
      if (colour.red > 150 && colour.green < 60 && colour.blue > 60) ++count;
    }
    return count;
  };
  const std::string without = tempPng("no_unreachable");
  plot.writePng(data, without);
  EXPECT_EQ(magentaAlongTheBottomEdge(without), 0);
  data.unreachable_parts = {part};
  const std::string path = tempPng("unreachable");
  plot.writePng(data, path);
  ASSERT_TRUE(PngImage(path).valid());
  EXPECT_GE(magentaAlongTheBottomEdge(path), 10);
  data.unreachable_parts = {{{{20, 3}, {28, std::nan("")}, {28, 9}}, {}}};
  EXPECT_THROW(plot.writePng(data, tempPng("bad_unreachable")), InvalidInputError);
}

TEST(CoveragePlotTest, FreeAreaWithoutHeatmapHasItsFill) {
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  CoveragePlotData data = scene();
  data.heatmap.reset();
  const CoveragePlotLayout layout = plot.layout(data);
  const std::string path = tempPng("no_heatmap");
  plot.writePng(data, path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());
  expectColour(kFreeAreaColour, image.colourAt(layout.toPixel(Point2(2.5, 15.5))), "free area");
  expectColour(kObstacleColour, image.colourAt(layout.toPixel(Point2(11.5, 9.5))), "hole");
}

TEST(CoveragePlotTest, VisitColoursSaturateAtFour) {
  for (const std::uint16_t visits : {5, 100, 65535}) {
    expectColour(CoveragePlot::visitColour(4), CoveragePlot::visitColour(visits), "4+");
  }
  for (std::uint16_t visits = 1; visits <= 4; ++visits) {
    const PlotColour a = CoveragePlot::visitColour(visits - 1);
    const PlotColour b = CoveragePlot::visitColour(visits);
    EXPECT_TRUE(a.red != b.red || a.green != b.green || a.blue != b.blue) << visits;
  }
}

TEST(CoveragePlotTest, RejectsInvalidInput) {
  const CoveragePlot plot;
  const std::string path = tempPng("invalid");
  const double nan = std::numeric_limits<double>::quiet_NaN();

  CoveragePlotData empty_hull = scene();
  empty_hull.free_area.hull.clear();
  EXPECT_THROW(plot.writePng(empty_hull, path), InvalidInputError);

  CoveragePlotData flat_hull = scene();
  flat_hull.free_area.hull = {{0, 0}, {10, 0}, {20, 0}};
  EXPECT_THROW(plot.writePng(flat_hull, path), InvalidInputError);

  CoveragePlotData nan_pose = scene();
  nan_pose.trajectory[3].yaw = nan;
  EXPECT_THROW(plot.writePng(nan_pose, path), InvalidInputError);

  CoveragePlotData nan_waypoint = scene();
  nan_waypoint.waypoints[1].x = nan;
  EXPECT_THROW(plot.writePng(nan_waypoint, path), InvalidInputError);

  CoveragePlotData nan_hole = scene();
  nan_hole.free_area.holes[0][2].y() = nan;
  EXPECT_THROW(plot.writePng(nan_hole, path), InvalidInputError);

  CoveragePlotData short_heatmap = scene();
  short_heatmap.heatmap->visits.pop_back();
  EXPECT_THROW(plot.writePng(short_heatmap, path), InvalidInputError);

  CoveragePlotData nan_goal = scene();
  nan_goal.goal = Point2(nan, 0.0);
  EXPECT_THROW(plot.writePng(nan_goal, path), InvalidInputError);

  std::FILE* file = std::fopen(path.c_str(), "rb");
  EXPECT_EQ(nullptr, file) << "no file for rejected input";
  if (file != nullptr) std::fclose(file);

  EXPECT_THROW(CoveragePlot(CoveragePlotOptions{100, 0}), InvalidInputError);
  EXPECT_THROW(CoveragePlot(CoveragePlotOptions{1200, 0, -1.0}), InvalidInputError);
}

TEST(CoveragePlotTest, UnwritablePathIsNamedInTheError) {
  const CoveragePlot plot;
  const std::string path = "/nonexistent/dir/plot.png";
  try {
    plot.writePng(scene(), path);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string::npos, std::string(error.what()).find(path)) << error.what();
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
