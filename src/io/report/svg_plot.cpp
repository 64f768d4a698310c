// SPDX-License-Identifier: MIT
#include "io/report/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/report/document.hpp"

namespace catena::internal {
namespace {

constexpr double kWidth = 600.0;
constexpr double kHeight = 380.0;
constexpr double kLeft = 70.0;
constexpr double kRight = 190.0;  // room for the legend
constexpr double kTop = 30.0;
constexpr double kBottom = 50.0;

struct Range {
  double low = INFINITY;  // log10
  double high = -INFINITY;
  void add(double value) {
    if (value > 0.0 && std::isfinite(value)) {
      low = std::min(low, std::log10(value));
      high = std::max(high, std::log10(value));
    }
  }
  // Whole decades around the data (one decade when the data are a single value).
  void round_out() {
    if (!std::isfinite(low)) low = high = 0.0;
    low = std::floor(low);
    high = std::max(std::ceil(high), low + 1.0);
  }
};

struct Frame {
  Range x;
  Range y;
  double px(double value) const {
    return kLeft + (std::log10(value) - x.low) / (x.high - x.low) * (kWidth - kLeft - kRight);
  }
  double py(double value) const {
    return kHeight - kBottom -
           (std::log10(value) - y.low) / (y.high - y.low) * (kHeight - kTop - kBottom);
  }
};

std::string axes(const Frame& f, const LogLogPlot& plot) {
  const double x0 = kLeft, x1 = kWidth - kRight, y0 = kHeight - kBottom, y1 = kTop;
  std::string out = fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333\"/>\n", x0,
      y1, x1 - x0, y0 - y1);
  for (double d = f.x.low; d <= f.x.high + 0.5; d += 1.0) {
    const double x = f.px(std::pow(10.0, d));
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/>"
        "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">1e{4}</text>\n",
        x, y0, y1, y0 + 16, static_cast<int>(d));
  }
  for (double d = f.y.low; d <= f.y.high + 0.5; d += 1.0) {
    const double y = f.py(std::pow(10.0, d));
    out += fmt::format(
        "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">1e{5}</text>\n",
        x0, y, x1, x0 - 6, y + 4, static_cast<int>(d));
  }
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (x0 + x1) / 2,
                     kHeight - 12, html_escape(plot.x_label));
  out += fmt::format(
      "<text transform=\"translate(16,{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      (y0 + y1) / 2, html_escape(plot.y_label));
  out +=
      fmt::format("<text x=\"{}\" y=\"18\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>\n",
                  (x0 + x1) / 2, html_escape(plot.title));
  return out;
}

std::string legend_entry(int row,
                         const std::string& colour,
                         const std::string& label,
                         const std::string& style) {
  const double x = kWidth - kRight + 12, y = kTop + 14 + 18 * row;
  return fmt::format(
      "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"{}\"{}/>"
      "<text x=\"{}\" y=\"{}\">{}</text>\n",
      x, y, x + 22, y, colour, style == "band" ? 8 : 2,
      style == "dashed" ? " stroke-dasharray=\"5,3\"" : "", x + 28, y + 4, html_escape(label));
}

std::string series_path(const Frame& f, const LogLogPlot::Series& s) {
  std::string points;
  std::string markers;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!(s.x[i] > 0.0 && s.y[i] > 0.0)) continue;
    points += fmt::format("{:.1f},{:.1f} ", f.px(s.x[i]), f.py(s.y[i]));
    markers += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"/>",
                           f.px(s.x[i]), f.py(s.y[i]), s.colour);
  }
  return fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>{}\n",
                     points, s.colour, markers);
}

}  // namespace

std::string render_svg(const LogLogPlot& plot) {
  Frame f;
  for (const auto& s : plot.series) {
    for (double x : s.x) f.x.add(x);
    for (double y : s.y) f.y.add(y);
  }
  for (const auto& level : plot.levels) f.y.add(level.y);
  if (plot.band_top) f.y.add(*plot.band_top);
  f.x.round_out();
  f.y.round_out();
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      kWidth, kHeight);
  int row = 0;
  if (plot.band_top && *plot.band_top > 0.0) {
    const double top = f.py(*plot.band_top);
    out += fmt::format(
        "<rect x=\"{}\" y=\"{:.1f}\" width=\"{}\" height=\"{:.1f}\" fill=\"#2ca02c\" "
        "opacity=\"0.25\"/>\n",
        kLeft, top, kWidth - kLeft - kRight, kHeight - kBottom - top);
    out += legend_entry(row++, "#2ca02c", plot.band_label, "band");
  }
  out += axes(f, plot);
  for (const auto& level : plot.levels) {
    if (!(level.y > 0.0)) continue;
    out += fmt::format(
        "<line x1=\"{0}\" y1=\"{2:.1f}\" x2=\"{1}\" y2=\"{2:.1f}\" stroke=\"{3}\" "
        "stroke-dasharray=\"5,3\"/>\n",
        kLeft, kWidth - kRight, f.py(level.y), level.colour);
    out += legend_entry(row++, level.colour, level.label, "dashed");
  }
  for (const auto& s : plot.series) {
    out += series_path(f, s);
    out += legend_entry(row++, s.colour, s.label, "solid");
  }
  return out + "</svg>\n";
}

}  // namespace catena::internal
