// SPDX-License-Identifier: MIT
#pragma once
// Line plots drawn as SVG by the library itself (no Python needed): small log-log plots embedded in
// the HTML report like the matplotlib figures (document.hpp's Image, by file extension), and
// figures of stacked panels with linear axes (the scene picture, io/plot/scene_picture.hpp). One
// writer: both share the legend and the document frame.

#include <optional>
#include <string>
#include <vector>

namespace catena::internal {

struct LogLogPlot {
  struct Series {
    std::string label;
    std::vector<double> x;
    std::vector<double> y;  ///< values <= 0 are not drawn
    std::string colour = "#1f77b4";
  };
  struct Level {  ///< a horizontal line across the plot
    std::string label;
    double y = 0.0;
    std::string colour = "#555";
  };
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Series> series;
  std::vector<Level> levels;
  /// A shaded horizontal band from the bottom of the plot up to `band_top` (e.g. the reference's
  /// own error estimate: errors inside it cannot be resolved).
  std::optional<double> band_top;
  std::string band_label;
};

/// The plot as a standalone SVG document (decade ticks, legend).
std::string render_svg(const LogLogPlot& plot);

/// One panel with linear axes. `role` becomes the SVG element's class (e.g. "segment", "mode",
/// "seabed"), so that a reader or a test can find what each element stands for.
struct LinearPanel {
  struct Series {
    std::string label;
    std::vector<double> x;
    std::vector<double> y;  ///< a non-finite point breaks the path
    std::string colour = "#1f77b4";
    std::string dash;  ///< SVG stroke-dasharray ("6,3"); empty: solid
    double width = 2.0;
    std::string role;
    bool in_legend = true;
  };
  struct Marker {
    std::string label;
    double x = 0.0;
    double y = 0.0;
    std::string shape = "circle";  ///< circle, square, triangle-up, triangle-down, diamond
    std::string colour = "#333";
    std::string role;
  };
  struct Level {  ///< a horizontal line across the panel (the seabed, the water surface)
    std::string label;
    double y = 0.0;
    std::string colour = "#555";
    std::string dash = "6,3";
    std::string role;
  };
  std::string id;  ///< names the panel (the SVG group's id is "panel-<id>")
  std::string title;
  std::string x_label;
  std::string y_label;
  /// Equal scales on both axes (a profile to scale): the ranges are widened to fill the frame.
  bool equal_axes = false;
  double height = 220.0;  ///< of the frame [px]; the legend may make the panel taller
  std::vector<Series> series;
  std::vector<Marker> markers;
  std::vector<Level> levels;
};

/// Panels stacked from top to bottom under a title, with notes at the bottom.
struct LinearFigure {
  std::vector<std::string> title;  ///< the first line bold, the others plain
  std::vector<LinearPanel> panels;
  std::vector<std::string> notes;
};

/// The figure as a standalone SVG document. Each panel is a group with class "panel" carrying its
/// transform as data: data-x-range="x_low x_high", data-y-range="y_low y_high" (data units) and
/// data-frame="left top right bottom" (px), so the drawing can be read back in data units.
std::string render_svg(const LinearFigure& figure);

}  // namespace catena::internal
