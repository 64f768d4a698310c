// SPDX-License-Identifier: MIT
#pragma once
// Small log-log line plots drawn as SVG by the library itself (no Python needed), embedded in the
// HTML report like the matplotlib figures (document.hpp's Image, by file extension).

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

}  // namespace catena::internal
