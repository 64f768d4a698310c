// SPDX-License-Identifier: MIT
#include "io/plot/picture_data.hpp"

#include <cmath>

namespace catena::internal {
namespace {

using json = nlohmann::json;

json finite_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json numbers_json(const std::vector<double>& values) {
  json out = json::array();
  for (double value : values) out.push_back(finite_or_null(value));
  return out;
}

json panel_json(const LinearPanel& panel) {
  json series = json::array(), markers = json::array(), levels = json::array();
  for (const auto& s : panel.series) {
    series.push_back({{"label", s.label},
                      {"x", numbers_json(s.x)},
                      {"y", numbers_json(s.y)},
                      {"colour", s.colour},
                      {"dash", s.dash},
                      {"width", s.width},
                      {"role", s.role},
                      {"in_legend", s.in_legend}});
  }
  for (const auto& m : panel.markers) {
    markers.push_back({{"label", m.label},
                       {"x", finite_or_null(m.x)},
                       {"y", finite_or_null(m.y)},
                       {"shape", m.shape},
                       {"colour", m.colour},
                       {"role", m.role}});
  }
  for (const auto& level : panel.levels) {
    levels.push_back({{"label", level.label},
                      {"y", finite_or_null(level.y)},
                      {"colour", level.colour},
                      {"dash", level.dash},
                      {"role", level.role}});
  }
  return {{"id", panel.id},
          {"title", panel.title},
          {"x_label", panel.x_label},
          {"y_label", panel.y_label},
          {"equal_axes", panel.equal_axes},
          {"series", series},
          {"markers", markers},
          {"levels", levels}};
}

}  // namespace

json figure_json(const LinearFigure& figure) {
  json panels = json::array();
  for (const auto& panel : figure.panels) panels.push_back(panel_json(panel));
  return {{"title", figure.title}, {"notes", figure.notes}, {"panels", panels}};
}

}  // namespace catena::internal
