#pragma once

#include <memory>
#include <string>
#include <vector>

#include "trajectory_generation_tools/plot/coverage_plot.h"

// cairo's own declarations of its opaque types, so that this header (shared by the plots
// of kc_plot) does not pull cairo.h into its includers.
typedef struct _cairo cairo_t;                  // NOLINT(modernize-use-using)
typedef struct _cairo_surface cairo_surface_t;  // NOLINT(modernize-use-using)

namespace kinematic_coverage::core {

/// Text: titles and labels, and the figures lines under a title.
inline constexpr PlotColour kTextColour{25, 25, 25};
inline constexpr PlotColour kSubtitleColour{70, 70, 70};
/// Outlines: the hull, axes boxes.
inline constexpr PlotColour kOutlineColour{45, 45, 45};

/// Sizes of a plot that scale with the image width.
struct PlotScale {
  double factor;  ///< of lengths: margins, line widths, markers
  double title;   ///< font sizes, pixels
  double subtitle;
  double tick;
  double label;
  double legend;
};

/// The sizes of an image `width` pixels wide: they grow with the square root of the width,
/// so that small images keep legible text and large ones give the extra room to the plot.
PlotScale plotScaleFor(int width);

/// How a text is placed horizontally on its anchor.
enum class TextAlign { kStart, kCentre, kEnd };

/// An RGB24 image surface with its drawing context, freed together.
class PlotCanvas {
 public:
  /// A white image of `width` x `height` pixels; throws std::runtime_error if cairo cannot
  /// allocate it (`what` names the plot in the message).
  PlotCanvas(int width, int height, const std::string& what);

  cairo_t* context() const { return context_.get(); }

  /// Writes the image to `path` as PNG; throws InvalidInputError naming the path when it
  /// cannot be written.
  void writePng(const std::string& path, const std::string& what) const;

 private:
  struct SurfaceDeleter {
    void operator()(cairo_surface_t* surface) const;
  };
  struct ContextDeleter {
    void operator()(cairo_t* context) const;
  };
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface_;
  std::unique_ptr<cairo_t, ContextDeleter> context_;
};

/// Sets the source colour.
void setColour(cairo_t* cr, const PlotColour& colour);

/// Sets the source colour with an opacity in [0, 1], for lines the heatmap shows through.
void setColour(cairo_t* cr, const PlotColour& colour, double opacity);

/// Selects the sans font at `size` pixels, bold or not.
void selectFont(cairo_t* cr, double size, bool bold);

/// Moves to where `text` starts so that it is aligned at (x, y) horizontally as
/// `horizontal` says and vertically centred on y.
void moveToText(cairo_t* cr, const std::string& text, double x, double y, TextAlign horizontal);

/// Shows `text` aligned at (x, y) as moveToText places it.
void showText(cairo_t* cr, const std::string& text, double x, double y, TextAlign horizontal);

/// The tick step of 1, 2 or 5 times a power of ten nearest (by ratio) to `range` divided
/// into `target_count` steps.
double niceStep(double range, double target_count);

/// Tick positions within [min, max], multiples of `step`.
std::vector<double> ticks(double min, double max, double step);

/// A tick's label with as many decimals as `step` needs.
std::string tickLabel(double value, double step);

}  // namespace kinematic_coverage::core
