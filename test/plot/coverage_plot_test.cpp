#include "trajectory_generation_tools/plot/coverage_plot.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

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

  /// Colour of pixel column `x`, row `y`.
  PlotColour colourAt(int x, int y) const { return colourAt(Point2(x, y)); }

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

/// A synthetic boustrophedon survey of a `width` x `height` octagonal lake with two
/// obstacles: parallel lanes `spacing` apart, tilted by kLaneTilt, joined end to end and
/// sampled every `step` as a planner's trajectory is, their ends as waypoints, and a
/// heatmap of `cell` sized cells: seen twice in a band along each lane's edge (the
/// sensor's overlap), never in a patch near the bottom-left corner, once elsewhere.
struct Survey {
  double width;
  double height;
  double spacing;
  double step;
  double cell;
};

/// The lanes' heading, radians from +x.
constexpr double kLaneTilt = 0.3;
/// Share of the lane spacing that neighbouring lanes' footprints overlap.
constexpr double kOverlapShare = 0.1;

/// Samples of the segment from `a` to `b` (without `a`) every `step`, facing along it.
void appendSegment(std::vector<Pose2>& poses, const Point2& a, const Point2& b, double step) {
  const double length = (b - a).norm();
  const int count = std::max(1, static_cast<int>(std::ceil(length / step)));
  const double yaw = std::atan2(b.y() - a.y(), b.x() - a.x());
  for (int k = 1; k <= count; ++k) {
    const Point2 p = a + (b - a) * (static_cast<double>(k) / count);
    poses.push_back({p.x(), p.y(), yaw});
  }
}

/// The lanes of `survey` over the convex `hull`, each from its start to its end.
std::vector<std::pair<Point2, Point2>> surveyLanes(const Survey& survey, const Ring& hull) {
  const Point2 along(std::cos(kLaneTilt), std::sin(kLaneTilt));
  const Point2 across(-along.y(), along.x());
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const Point2& p : hull) {
    low = std::min(low, across.dot(p));
    high = std::max(high, across.dot(p));
  }
  std::vector<std::pair<Point2, Point2>> lanes;
  for (double offset = low + 0.5 * survey.spacing; offset < high; offset += survey.spacing) {
    double first = std::numeric_limits<double>::infinity();
    double last = -first;
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Point2& a = hull[i];
      const Point2& b = hull[(i + 1) % hull.size()];
      const double da = across.dot(a) - offset;
      const double db = across.dot(b) - offset;
      if ((da < 0.0) == (db < 0.0)) continue;
      const double u = along.dot(a + (b - a) * (da / (da - db)));
      first = std::min(first, u);
      last = std::max(last, u);
    }
    const double margin = 0.25 * survey.spacing;
    if (last - first <= 2.0 * margin) continue;
    Point2 start = offset * across + (first + margin) * along;
    Point2 end = offset * across + (last - margin) * along;
    if (lanes.size() % 2 == 1) std::swap(start, end);
    lanes.emplace_back(start, end);
  }
  return lanes;
}

/// Visits of the survey's heatmap cell centred on `centre`.
std::uint16_t surveyVisits(const Survey& survey, const Point2& centre) {
  if (centre.x() < 0.2 * survey.width && centre.y() < 0.3 * survey.height) return 0;
  const Point2 across(-std::sin(kLaneTilt), std::cos(kLaneTilt));
  const double phase = std::fmod(std::abs(across.dot(centre)), survey.spacing) / survey.spacing;
  return phase < kOverlapShare ? 2 : 1;
}

CoveragePlotData surveyData(const Survey& survey) {
  const double w = survey.width;
  const double h = survey.height;
  CoveragePlotData data;
  data.free_area.hull = {{0.1 * w, 0}, {0.9 * w, 0}, {w, 0.3 * h}, {w, 0.8 * h},
                         {0.8 * w, h}, {0.1 * w, h}, {0, 0.7 * h}, {0, 0.2 * h}};
  data.free_area.holes = {
      {{0.3 * w, 0.4 * h}, {0.3 * w, 0.55 * h}, {0.4 * w, 0.55 * h}, {0.4 * w, 0.4 * h}},
      {{0.65 * w, 0.6 * h}, {0.7 * w, 0.75 * h}, {0.75 * w, 0.62 * h}}};
  const auto lanes = surveyLanes(survey, data.free_area.hull);
  data.trajectory.push_back({lanes.front().first.x(), lanes.front().first.y(), kLaneTilt});
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    if (k > 0) appendSegment(data.trajectory, lanes[k - 1].second, lanes[k].first, survey.step);
    appendSegment(data.trajectory, lanes[k].first, lanes[k].second, survey.step);
    for (const Point2& end : {lanes[k].first, lanes[k].second}) {
      data.waypoints.push_back({end.x(), end.y(), data.trajectory.back().yaw});
    }
  }
  Heatmap heatmap;
  heatmap.cell_size = survey.cell;
  heatmap.columns = static_cast<int>(std::ceil(w / survey.cell));
  heatmap.rows = static_cast<int>(std::ceil(h / survey.cell));
  for (int row = 0; row < heatmap.rows; ++row) {
    for (int column = 0; column < heatmap.columns; ++column) {
      heatmap.visits.push_back(surveyVisits(survey, Point2(column + 0.5, row + 0.5) * survey.cell));
    }
  }
  data.heatmap = heatmap;
  data.title_lines = {"Survey"};
  return data;
}

/// A pixel changes visibly when one of its channels changes by more than this: a
/// hairline's faint antialiased fringe over a heatmap cell leaves it readable.
constexpr int kVisibleChange = 40;

bool visiblyDifferent(const PlotColour& a, const PlotColour& b, int threshold) {
  return std::abs(a.red - b.red) > threshold || std::abs(a.green - b.green) > threshold ||
         std::abs(a.blue - b.blue) > threshold;
}

bool isVisitColour(const PlotColour& colour) {
  for (std::uint16_t visits = 0; visits <= 4; ++visits) {
    const PlotColour v = CoveragePlot::visitColour(visits);
    if (v.red == colour.red && v.green == colour.green && v.blue == colour.blue) return true;
  }
  return false;
}

/// Share of the heatmap pixels (those of the box that show a visit colour in the plot
/// without paths) that the trajectory and waypoints change by more than `threshold`.
double coveredHeatmapShare(const CoveragePlotData& data, const std::string& name, int threshold) {
  const CoveragePlot plot;
  CoveragePlotData bare = data;
  bare.trajectory.clear();
  bare.waypoints.clear();
  const CoveragePlotLayout layout = plot.layout(data);
  const std::string with_paths = tempPng(name + "_paths");
  const std::string without_paths = tempPng(name + "_bare");
  plot.writePng(data, with_paths);
  plot.writePng(bare, without_paths);
  const PngImage drawn(with_paths);
  const PngImage heatmap(without_paths);
  EXPECT_TRUE(drawn.valid() && heatmap.valid());
  int heatmap_pixels = 0;
  int covered = 0;
  for (int y = static_cast<int>(layout.box_top); y < layout.box_top + layout.box_height; ++y) {
    for (int x = static_cast<int>(layout.box_left); x < layout.box_left + layout.box_width; ++x) {
      const PlotColour under = heatmap.colourAt(x, y);
      if (!isVisitColour(under)) continue;
      ++heatmap_pixels;
      if (visiblyDifferent(under, drawn.colourAt(x, y), threshold)) ++covered;
    }
  }
  EXPECT_GT(heatmap_pixels, 0.2 * layout.box_width * layout.box_height) << name;
  return static_cast<double>(covered) / heatmap_pixels;
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

/// A 20 x 15 km lake with lanes 120 m apart, sampled every 5 m.
constexpr Survey kLakeSurvey{20000.0, 15000.0, 120.0, 5.0, 40.0};
/// A 30 x 22 m pond with lanes 1.5 m apart, sampled every 0.25 m.
constexpr Survey kPondSurvey{30.0, 22.0, 1.5, 0.25, 0.1};

TEST(CoveragePlotTest, HeatmapStaysVisibleUnderTheLanesOfALake) {
  // About 170 lanes, 5 pixels apart on the image: drawn at today's widths with arrows and
  // waypoint dots they hid most of the heatmap. The map area is the heatmap's pixels: those
  // of the box that show a visit colour in the plot without trajectory and waypoints.
  const CoveragePlotData lake = surveyData(kLakeSurvey);
  ASSERT_GT(lake.waypoints.size(), 2 * 100u);
  ASSERT_LT(lake.waypoints.size(), 2 * 300u);
  const double visibly_covered = coveredHeatmapShare(lake, "lake", kVisibleChange);
  const double touched = coveredHeatmapShare(lake, "lake", 0);
  EXPECT_LE(visibly_covered, 0.25);
  std::printf("lake: %.1f %% of the heatmap pixels visibly changed, %.1f %% changed at all\n",
              100.0 * visibly_covered, 100.0 * touched);
}

TEST(CoveragePlotTest, LanesOfASmallMapAreDrawnAtTheNominalWidths) {
  // The same survey 700 times smaller: lanes far apart on the image, drawn as today, so
  // the lake's check above cannot pass by drawing nothing.
  const CoveragePlotData pond = surveyData(kPondSurvey);
  const double visibly_covered = coveredHeatmapShare(pond, "pond", kVisibleChange);
  EXPECT_GT(visibly_covered, 0.02);
  std::printf("pond: %.1f %% of the heatmap pixels visibly changed\n", 100.0 * visibly_covered);

  const CoveragePlotPathStyle style = CoveragePlot().pathStyle(pond);
  EXPECT_DOUBLE_EQ(1.8, style.trajectory_width);
  EXPECT_DOUBLE_EQ(1.3, style.waypoint_width);
  EXPECT_DOUBLE_EQ(1.1, style.offset_outline_width);
  EXPECT_DOUBLE_EQ(2.8, style.waypoint_dot_radius);
  EXPECT_DOUBLE_EQ(12.0, style.arrow_length);
  EXPECT_DOUBLE_EQ(100.0, style.arrow_spacing_pixels);
  EXPECT_DOUBLE_EQ(1.0, style.path_opacity);
}

TEST(CoveragePlotTest, LinesOfALakeAreThinnerThanAnEighthOfTheLaneSpacing) {
  const CoveragePlot plot;
  const CoveragePlotData lake = surveyData(kLakeSurvey);
  const CoveragePlotPathStyle style = plot.pathStyle(lake);
  // The density estimate (free area / trajectory length) finds the lanes' spacing.
  const double lane_pixels = kLakeSurvey.spacing * plot.layout(lake).pixels_per_metre;
  EXPECT_GT(style.lane_spacing_pixels, 0.7 * lane_pixels);
  EXPECT_LT(style.lane_spacing_pixels, 1.3 * lane_pixels);
  EXPECT_LE(style.trajectory_width, style.lane_spacing_pixels / 8.0 + 1e-9);
  EXPECT_GE(style.trajectory_width, CoveragePlotPathStyle::kHairlineWidth);
  EXPECT_LT(style.waypoint_width, 1.3);
  EXPECT_LT(style.offset_outline_width, 1.1);
  EXPECT_LT(style.arrow_length, 12.0);
  EXPECT_GE(style.arrow_spacing_pixels, 100.0);
  EXPECT_LT(style.waypoint_dot_radius, 0.25 * style.lane_spacing_pixels);

  // Lanes closer than a few pixels: a hairline, fainter, no waypoint dots.
  const CoveragePlotData dense = surveyData({20000.0, 15000.0, 40.0, 5.0, 40.0});
  const CoveragePlotPathStyle dense_style = plot.pathStyle(dense);
  EXPECT_DOUBLE_EQ(CoveragePlotPathStyle::kHairlineWidth, dense_style.trajectory_width);
  EXPECT_LT(dense_style.path_opacity, 1.0);
  EXPECT_EQ(0.0, dense_style.waypoint_dot_radius);
}

TEST(CoveragePlotTest, ScaleBarIsARoundFifthOfTheBox) {
  for (double width = 0.37; width < 4e6; width *= 1.13) {
    const double length = CoveragePlot::scaleBarLength(width);
    const double mantissa = length / std::pow(10.0, std::floor(std::log10(length) + 1e-9));
    const bool round = std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
                       std::abs(mantissa - 5.0) < 1e-9;
    EXPECT_TRUE(round) << width << " m: " << length;
    EXPECT_GE(length, width / 10.0) << width;
    EXPECT_LE(length, width / 3.0) << width;
  }
  EXPECT_EQ("500 m", CoveragePlot::scaleBarLabel(500.0));
  EXPECT_EQ("2 km", CoveragePlot::scaleBarLabel(2000.0));
  EXPECT_EQ("1 km", CoveragePlot::scaleBarLabel(1000.0));
  EXPECT_EQ("20 km", CoveragePlot::scaleBarLabel(20000.0));
  EXPECT_EQ("5 m", CoveragePlot::scaleBarLabel(5.0));
  EXPECT_EQ("0.5 m", CoveragePlot::scaleBarLabel(0.5));
}

TEST(CoveragePlotTest, ScaleBarIsDrawnInTheBoxAtItsLength) {
  // A dark horizontal run as long as the bar (plus its end ticks' width) in some row of
  // the box; the scene has no other line of that length.
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  const CoveragePlotData data = scene();
  const CoveragePlotLayout layout = plot.layout(data);
  const double bar = CoveragePlot::scaleBarLength(layout.box_width / layout.pixels_per_metre) *
                     layout.pixels_per_metre;
  const std::string path = tempPng("scale_bar");
  plot.writePng(data, path);
  const PngImage image(path);
  ASSERT_TRUE(image.valid());
  bool found = false;
  for (int y = static_cast<int>(layout.box_top) + 1; y < layout.box_top + layout.box_height; ++y) {
    int run = 0;
    for (int x = static_cast<int>(layout.box_left) + 2; x < layout.box_left + layout.box_width;
         ++x) {
      const PlotColour c = image.colourAt(x, y);
      run = c.red + c.green + c.blue < 200 ? run + 1 : 0;
      if (std::abs(run - bar) <= 4.0) found = true;
    }
  }
  EXPECT_TRUE(found) << "no dark run of " << bar << " pixels";
}

/// Pixels of the box that differ between two renderings of `data`'s plot, one with
/// `north`, one without a north direction.
struct NorthArrowPixels {
  int count = 0;
  Point2 min = Point2::Constant(std::numeric_limits<double>::infinity());
  Point2 max = Point2::Constant(-std::numeric_limits<double>::infinity());
  /// Centroid of the dark pixels (needle and "N") within the differing pixels' bounds.
  Point2 dark_centroid = Point2::Zero();
};

NorthArrowPixels northArrowPixels(const CoveragePlotData& data, double north) {
  const CoveragePlot plot(CoveragePlotOptions{800, 600});
  CoveragePlotData with = data;
  with.north_direction = north;
  const std::string path_with = tempPng("north_with");
  const std::string path_without = tempPng("north_without");
  plot.writePng(with, path_with);
  plot.writePng(data, path_without);
  const PngImage a(path_with);
  const PngImage b(path_without);
  NorthArrowPixels result;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      if (!visiblyDifferent(a.colourAt(x, y), b.colourAt(x, y), 0)) continue;
      ++result.count;
      result.min = result.min.cwiseMin(Point2(x, y));
      result.max = result.max.cwiseMax(Point2(x, y));
    }
  }
  int dark = 0;
  for (int y = static_cast<int>(result.min.y()); y <= result.max.y(); ++y) {
    for (int x = static_cast<int>(result.min.x()); x <= result.max.x(); ++x) {
      const PlotColour c = a.colourAt(x, y);
      if (c.red + c.green + c.blue >= 150) continue;
      result.dark_centroid += Point2(x, y);
      ++dark;
    }
  }
  if (dark > 0) result.dark_centroid /= dark;
  return result;
}

TEST(CoveragePlotTest, NorthArrowOnlyWithANorthDirectionInACornerPointingNorth) {
  const CoveragePlotData data = scene();
  const CoveragePlotLayout layout = CoveragePlot(CoveragePlotOptions{800, 600}).layout(data);
  const double corner_side = 0.2 * std::min(layout.box_width, layout.box_height);
  for (const double north : {M_PI / 2 + 0.05, 0.0}) {
    const NorthArrowPixels pixels = northArrowPixels(data, north);
    ASSERT_GT(pixels.count, 100) << north;
    // All the differences in one corner of the box.
    const bool left = pixels.max.x() < layout.box_left + corner_side;
    const bool right = pixels.min.x() > layout.box_left + layout.box_width - corner_side;
    const bool top = pixels.max.y() < layout.box_top + corner_side;
    const bool bottom = pixels.min.y() > layout.box_top + layout.box_height - corner_side;
    EXPECT_TRUE((left || right) && (top || bottom)) << north;
    EXPECT_GE(pixels.min.x(), layout.box_left);
    EXPECT_GE(pixels.min.y(), layout.box_top);
    // The dark half of the needle and the "N" lie towards north (image y grows downwards).
    const Point2 centre = 0.5 * (pixels.min + pixels.max);
    const Point2 offset = pixels.dark_centroid - centre;
    const Point2 towards_north(std::cos(north), -std::sin(north));
    EXPECT_GT(offset.dot(towards_north), 2.0) << north;
  }
  CoveragePlotData bad = data;
  bad.north_direction = std::numeric_limits<double>::infinity();
  EXPECT_THROW(CoveragePlot().writePng(bad, tempPng("bad_north")), InvalidInputError);
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
