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

// A legend row at (x, y): a short line in the series' style, then its label.
std::string legend_line(double x,
                        double y,
                        const std::string& colour,
                        const std::string& label,
                        double width,
                        const std::string& dash) {
  return fmt::format(
      "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"{}\"{}/>"
      "<text x=\"{}\" y=\"{}\">{}</text>\n",
      x, y, x + 22, y, colour, width,
      dash.empty() ? std::string() : fmt::format(" stroke-dasharray=\"{}\"", dash), x + 28, y + 4,
      html_escape(label));
}

std::string legend_entry(int row,
                         const std::string& colour,
                         const std::string& label,
                         const std::string& style) {
  return legend_line(kWidth - kRight + 12, kTop + 14 + 18 * row, colour, label,
                     style == "band" ? 8 : 2, style == "dashed" ? "5,3" : "");
}

std::string svg_open(double width, double height) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      width, height);
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
  std::string out = svg_open(kWidth, kHeight);
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

// ---- Figures of stacked panels with linear axes (the scene picture) ----
namespace {

constexpr double kFigureWidth = 960.0;
constexpr double kFrameLeft = 80.0;
constexpr double kFrameWidth = 560.0;
constexpr double kLegendLeft = kFrameLeft + kFrameWidth + 16.0;
constexpr double kLegendRow = 16.0;
constexpr double kPanelTitle = 26.0;  // above the frame
constexpr double kPanelAxis = 48.0;   // below the frame: tick labels and the axis label
constexpr double kTitleLine = 18.0;
constexpr std::size_t kNoteColumns = 140;  // about 6.5 px a character at 12 px: within 960 px

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about `count` ticks over `range`.
double tick_step(double range, double count) {
  const double raw = range / std::max(count, 1.0);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double factor : {1.0, 2.0, 5.0}) {
    if (factor * decade >= raw) return factor * decade;
  }
  return 10.0 * decade;
}

struct Axis {
  double low = INFINITY;
  double high = -INFINITY;
  void add(double value) {
    if (!std::isfinite(value)) return;
    low = std::min(low, value);
    high = std::max(high, value);
  }
  // A margin of 4 % on each side; a single value gets +-1 around it (or +-1 % of its size).
  void pad() {
    if (!std::isfinite(low)) low = high = 0.0;
    const double margin = high > low ? 0.04 * (high - low) : std::max(1.0, 0.01 * std::abs(low));
    low -= margin;
    high += margin;
  }
  // Widens the range about its middle to `span`.
  void widen_to(double span) {
    const double middle = 0.5 * (low + high);
    low = middle - 0.5 * span;
    high = middle + 0.5 * span;
  }
};

struct PanelFrame {
  Axis x;
  Axis y;
  double left = kFrameLeft, top = 0.0, width = kFrameWidth, height = 0.0;
  double px(double value) const { return left + (value - x.low) / (x.high - x.low) * width; }
  double py(double value) const {
    return top + height - (value - y.low) / (y.high - y.low) * height;
  }
};

PanelFrame frame_of(const LinearPanel& panel, double top) {
  PanelFrame f;
  f.top = top;
  f.height = panel.height;
  for (const auto& s : panel.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      f.x.add(s.x[i]);
      f.y.add(s.y[i]);
    }
  }
  for (const auto& m : panel.markers) {
    if (!std::isfinite(m.x) || !std::isfinite(m.y)) continue;
    f.x.add(m.x);
    f.y.add(m.y);
  }
  for (const auto& level : panel.levels) f.y.add(level.y);
  f.x.pad();
  f.y.pad();
  if (panel.equal_axes) {  // one metre is as long across as up
    const double per_px = std::max((f.x.high - f.x.low) / f.width, (f.y.high - f.y.low) / f.height);
    f.x.widen_to(per_px * f.width);
    f.y.widen_to(per_px * f.height);
  }
  return f;
}

std::string panel_axes(const PanelFrame& f, const LinearPanel& panel) {
  const double x0 = f.left, x1 = f.left + f.width, y0 = f.top + f.height, y1 = f.top;
  std::string out = fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333\"/>\n", x0,
      y1, f.width, f.height);
  const double dx = tick_step(f.x.high - f.x.low, f.width / 90.0);
  for (double v = std::ceil(f.x.low / dx) * dx; v <= f.x.high; v += dx) {
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#e4e4e4\"/>"
        "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4:g}</text>\n",
        f.px(v), y0, y1, y0 + 15, std::abs(v) < 1e-9 * dx ? 0.0 : v);
  }
  const double dy = tick_step(f.y.high - f.y.low, f.height / 45.0);
  for (double v = std::ceil(f.y.low / dy) * dy; v <= f.y.high; v += dy) {
    out += fmt::format(
        "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#e4e4e4\"/>"
        "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:g}</text>\n",
        x0, f.py(v), x1, x0 - 5, f.py(v) + 4, std::abs(v) < 1e-9 * dy ? 0.0 : v);
  }
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (x0 + x1) / 2,
                     y0 + 36, html_escape(panel.x_label));
  out += fmt::format(
      "<text transform=\"translate(18,{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      (y0 + y1) / 2, html_escape(panel.y_label));
  out += fmt::format("<text x=\"{}\" y=\"{}\" font-weight=\"bold\">{}</text>\n", x0, y1 - 8,
                     html_escape(panel.title));
  return out;
}

// A polyline per finite run of points (a non-finite value breaks the line).
std::string panel_series(const PanelFrame& f, const LinearPanel::Series& s) {
  std::string out;
  std::string points;
  const auto flush = [&] {
    if (!points.empty()) {
      out += fmt::format(
          "<polyline class=\"{}\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{}/>"
          "\n",
          s.role, points, s.colour, s.width,
          s.dash.empty() ? std::string() : fmt::format(" stroke-dasharray=\"{}\"", s.dash));
    }
    points.clear();
  };
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
      points += fmt::format("{:.2f},{:.2f} ", f.px(s.x[i]), f.py(s.y[i]));
    } else {
      flush();
    }
  }
  flush();
  return out;
}

std::string marker_shape(double x, double y, const LinearPanel::Marker& m) {
  constexpr double r = 5.0;
  const std::string style =
      fmt::format("class=\"{}\" fill=\"{}\" stroke=\"#222\"", m.role, m.colour);
  if (m.shape == "square")
    return fmt::format("<rect {} x=\"{:.2f}\" y=\"{:.2f}\" width=\"{}\" height=\"{}\"/>", style,
                       x - r, y - r, 2 * r, 2 * r);
  if (m.shape == "triangle-up" || m.shape == "triangle-down" || m.shape == "diamond") {
    const double s = m.shape == "triangle-down" ? -1.0 : 1.0;
    const std::string points =
        m.shape == "diamond"
            ? fmt::format("{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}", x, y - r,
                          x + r, y, x, y + r, x - r, y)
            : fmt::format("{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}", x, y - s * r, x + r,
                          y + s * r, x - r, y + s * r);
    return fmt::format("<polygon {} points=\"{}\"/>", style, points);
  }
  return fmt::format("<circle {} cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{}\"/>", style, x, y, r);
}

// The panel's legend, right of its frame; returns the rows used.
int panel_legend(const LinearPanel& panel, double top, std::string& out) {
  int row = 0;
  const auto y = [&] { return top + 10 + kLegendRow * row; };
  for (const auto& level : panel.levels)
    out += legend_line(kLegendLeft, y(), level.colour, level.label, 2, level.dash), ++row;
  for (const auto& s : panel.series) {
    if (!s.in_legend) continue;
    out += legend_line(kLegendLeft, y(), s.colour, s.label, s.width, s.dash), ++row;
  }
  for (const auto& m : panel.markers) {
    LinearPanel::Marker sample = m;
    sample.role = "legend";  // not a drawn point of the data
    out += marker_shape(kLegendLeft + 11, y(), sample);
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", kLegendLeft + 28, y() + 4,
                       html_escape(m.label));
    ++row;
  }
  return row;
}

// The panel's drawing from `top`; returns its height with its title and axis labels.
double render_panel(const LinearPanel& panel, double top, std::string& out) {
  const PanelFrame f = frame_of(panel, top + kPanelTitle);
  out += fmt::format(
      "<g class=\"panel\" id=\"panel-{}\" data-x-range=\"{:.17g} {:.17g}\" "
      "data-y-range=\"{:.17g} {:.17g}\" data-frame=\"{} {} {} {}\">\n",
      panel.id, f.x.low, f.x.high, f.y.low, f.y.high, f.left, f.top, f.left + f.width,
      f.top + f.height);
  out += panel_axes(f, panel);
  for (const auto& level : panel.levels) {
    out += fmt::format(
        "<line class=\"{}\" x1=\"{}\" y1=\"{:.2f}\" x2=\"{}\" y2=\"{:.2f}\" stroke=\"{}\" "
        "stroke-width=\"2\"{}/>\n",
        level.role, f.left, f.py(level.y), f.left + f.width, f.py(level.y), level.colour,
        level.dash.empty() ? std::string() : fmt::format(" stroke-dasharray=\"{}\"", level.dash));
  }
  for (const auto& s : panel.series) out += panel_series(f, s);
  for (const auto& m : panel.markers) {
    if (std::isfinite(m.x) && std::isfinite(m.y))
      out += marker_shape(f.px(m.x), f.py(m.y), m) + "\n";
  }
  const int rows = panel_legend(panel, f.top, out);
  out += "</g>\n";
  return kPanelTitle + std::max(panel.height, kLegendRow * rows + 10.0) + kPanelAxis;
}

// `text` in lines of at most `columns` characters, broken at spaces (SVG text does not wrap).
std::vector<std::string> wrapped(const std::string& text, std::size_t columns) {
  std::vector<std::string> lines{""};
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t space = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, space - start);
    if (!lines.back().empty() && lines.back().size() + 1 + word.size() > columns)
      lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + word;
    start = space + 1;
  }
  return lines;
}

}  // namespace

std::string render_svg(const LinearFigure& figure) {
  std::string body;
  double y = 8.0;
  for (std::size_t i = 0; i < figure.title.size(); ++i) {
    y += kTitleLine;
    body += fmt::format("<text x=\"{}\" y=\"{}\"{}>{}</text>\n", 12, y,
                        i == 0 ? " font-weight=\"bold\" font-size=\"15\"" : "",
                        html_escape(figure.title[i]));
  }
  y += 6.0;
  for (const auto& panel : figure.panels) y += render_panel(panel, y, body);
  for (const auto& note : figure.notes) {
    for (const std::string& line : wrapped(note, kNoteColumns)) {
      y += kTitleLine;
      body +=
          fmt::format("<text x=\"12\" y=\"{}\" fill=\"#444\">{}</text>\n", y, html_escape(line));
    }
  }
  return svg_open(kFigureWidth, std::ceil(y + 12.0)) + body + "</svg>\n";
}

}  // namespace catena::internal
