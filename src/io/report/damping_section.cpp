// SPDX-License-Identifier: MIT
// The damping of a damped scene in the report's scene section: the damping ratio and decay rate of
// each mode by solver, and the overdamped roots (docs/reference/verdicts.md, "Reading the report").
// An undamped scene gets none of it, so its section reads as before.
#include <fmt/format.h>

#include <algorithm>

#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

bool has_damping(const json& section) {
  return section.is_object() && section.contains(key::damping);
}

bool problem_is_damped(const json& problem) {
  if (!problem.is_object()) return false;
  if (problem.contains(key::cable) && has_damping(problem[key::cable])) return true;
  if (problem.contains(key::line)) {
    for (const auto& segment : list_or_empty(problem[key::line], key::segments))
      if (has_damping(segment)) return true;
  }
  return problem.contains(key::seabed) && problem[key::seabed].contains(key::damping_n_s_per_m2);
}

bool has_decaying_mode(const json& scene) {
  for (const auto& [solver, output] : scene[key::solvers].items()) {
    for (const char* plane : {key::inplane, key::outofplane}) {
      if (!output.contains(plane)) continue;
      if (!list_or_empty(output[plane], key::overdamped).empty()) return true;
      for (const auto& mode : list_or_empty(output[plane], key::modes)) {
        const json& delta = mode.value(key::decay_rate_1_s, json());
        if (delta.is_number() && delta.get<double>() > 0.0) return true;
      }
    }
  }
  return false;
}

// "zeta (delta)" of one mode: the damping ratio and the decay rate [1/s].
std::string damping_cell(const json& mode) {
  return fmt::format("{} ({})", number_text(mode.value(key::damping_ratio, json()), "{:.6g}"),
                     number_text(mode.value(key::decay_rate_1_s, json()), "{:.6g}"));
}

// One plane's list `list_key` (modes or overdamped roots): a row per index, a column per solver.
void add_list_table(Document& out,
                    const json& scene,
                    const char* plane,
                    const char* list_key,
                    const std::string& title) {
  std::vector<std::string> solvers;
  std::size_t rows = 0;
  for (const auto& [solver, output] : scene[key::solvers].items()) {
    if (!output.contains(plane) || list_or_empty(output[plane], list_key).empty()) continue;
    solvers.push_back(solver);
    rows = std::max(rows, output[plane][list_key].size());
  }
  if (solvers.empty()) return;
  Table t{{title}, {}, "damping"};
  for (const auto& s : solvers) t.header.push_back(s + " zeta (delta [1/s])");
  for (std::size_t i = 0; i < rows; ++i) {
    std::vector<std::string> row = {std::to_string(i + 1)};
    for (const auto& s : solvers) {
      const json& list = scene[key::solvers][s][plane][list_key];
      row.push_back(i < list.size() ? damping_cell(list[i]) : "-");
    }
    t.rows.push_back(row);
  }
  out.push_back(t);
}

}  // namespace

bool is_damped_scene(const json& scene) {
  return problem_is_damped(scene.value(key::problem, json())) || has_decaying_mode(scene);
}

void add_damping_tables(Document& out, const json& scene) {
  if (!is_damped_scene(scene)) return;
  const std::size_t before = out.size();
  for (const char* plane : {key::inplane, key::outofplane}) {
    const std::string name = std::string(plane) == key::inplane ? "in-plane" : "out-of-plane";
    add_list_table(out, scene, plane, key::modes, name + " damped mode");
    add_list_table(out, scene, plane, key::overdamped, name + " overdamped root");
  }
  out.insert(out.begin() + static_cast<std::ptrdiff_t>(before),
             Paragraph{out.size() == before
                           ? "Damped scene: no solver returned its damped modes (each solver's "
                             "status says why)."
                           : "Damped scene: the frequencies above are the damped frequencies "
                             "omega_d = Im lambda; the damping ratio zeta = delta / |lambda| and "
                             "the decay rate delta = -Re lambda of each mode by solver below "
                             "(overdamped roots: real lambda = -delta, listed apart)."});
}

}  // namespace catena::internal
