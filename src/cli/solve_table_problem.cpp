// SPDX-License-Identifier: MIT
#include "cli/solve_table_problem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace catena::cli {
namespace {

void print_cable(std::string& out, const Problem& problem) {
  const CableProperties& c = problem.cable;
  out += fmt::format(
      "  cable: L = {} m, W0 = {} N/m, EA = {} N, m = {} kg/m, ma = {} kg/m; a = ({}, {}) m, "
      "b = ({:.10g}, {:.10g}) m\n",
      c.length_m, c.weight_n_per_m,
      c.is_inextensible() ? "inf" : fmt::format("{:g}", c.axial_stiffness_n), c.mass_kg_per_m,
      c.added_mass_kg_per_m, problem.supports.a_m.x(), problem.supports.a_m.y(),
      problem.supports.b_m.x(), problem.supports.b_m.y());
}

void print_groups(std::string& out, const DimensionlessGroups& g) {
  out += fmt::format(
      "  groups: phi_a = {:.6g} deg, T0 = {:.10g} N, eps = {:.6g}, lambda^2 = {}, h = m/M = "
      "{:.6g}\n",
      g.chord_angle_rad * 180.0 / kPi, g.t0_n, g.eps,
      std::isfinite(g.lambda2) ? fmt::format("{:.6g}", g.lambda2) : std::string("inf"),
      g.mass_ratio);
  if (g.has_apex_parameterization) {
    out += fmt::format(
        "  Gale: a = H/W0 = {:.10g} m, xi1 = {:.6g}, xi2 = {:.6g}, sigma1 = {:.6g}, sigma2 = "
        "{:.6g}{}{}\n",
        g.catenary_parameter_m, g.xi1, g.xi2, g.sigma1, g.sigma2,
        g.height_over_span ? fmt::format(", h/b = {:.6g}", *g.height_over_span) : std::string(),
        g.sag_parameter ? fmt::format(", sag parameter = {:.6g}", *g.sag_parameter)
                        : std::string());
  }
}

// One row of the line's statics table at s (forces on the side of b; a point's jump shown).
void print_line_row(std::string& out,
                    const StaticSolution& statics,
                    const std::string& what,
                    double s) {
  const Vec2 r = statics.position_m(s);
  const double before = statics.vertical_force_before_n(s);
  const double after = statics.vertical_force_n(s);
  out += fmt::format(
      "    {:<12} {:>12.6g} {:>12.6g} {:>12.6g} {:>13.7g} {:>13.7g} {:>13.7g} {:>12.6g}\n", what, s,
      r.x(), r.y(), statics.horizontal_force_n(), after, statics.tension_n(s),
      statics.stretched_length_m(s));
  if (before != after)
    out +=
        fmt::format("    {:<12} (V jumps by the point's weight: {:.7g} N before it)\n", "", before);
}

// The statics table of a general line: both ends, every joint and every point in order of s.
void print_line_statics(std::string& out, const Problem& problem, const StaticSolution& statics) {
  const Line& line = problem.line;
  out += fmt::format(
      "  line: {} segments, {} points, L = {} m; a = ({}, {}) m, b = ({:.10g}, {:.10g}) m\n",
      line.segments.size(), line.points.size(), line.length_m(), problem.supports.a_m.x(),
      problem.supports.a_m.y(), problem.supports.b_m.x(), problem.supports.b_m.y());
  out += fmt::format("    {:<12} {:>12} {:>12} {:>12} {:>13} {:>13} {:>13} {:>12}\n", "where",
                     "s [m]", "x [m]", "z [m]", "H [N]", "V [N]", "T [N]", "stretched [m]");
  std::vector<std::pair<double, std::string>> rows{{0.0, "end a"}, {line.length_m(), "end b"}};
  for (std::size_t k = 1; k < line.segments.size(); ++k)
    rows.emplace_back(line.segment_start_m(k), fmt::format("joint {}", k));
  for (std::size_t i = 0; i < line.points.size(); ++i)
    rows.emplace_back(line.points[i].s_m, fmt::format("point {}", i));
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [s, what] : rows) print_line_row(out, statics, what, s);
  const double low = statics.lowest_point_s_m();
  out += fmt::format("  lowest point: s = {:.6g} m, x = {:.6g} m, z = {:.6g} m\n", low,
                     statics.position_m(low).x(), statics.position_m(low).y());
}

// The damping of a damped problem (docs/reference/scene-format.md, "Damping"): the cable's, each
// damped segment's and the seabed dashpot; nothing for an undamped one, whose output is unchanged.
void print_damping(std::string& out, const Problem& problem) {
  const auto section = [&out](const std::string& what, const SectionDamping& d) {
    if (d.is_zero()) return;
    out += fmt::format("  {}: c_t = {:g} N s/m per m, c_n = {:g} N s/m per m, c_a = {:g} N s\n",
                       what, d.tangential_n_s_per_m2, d.normal_n_s_per_m2, d.axial_n_s);
  };
  if (problem.is_uniform()) {
    section("damping", problem.cable.damping);
  } else {
    for (std::size_t k = 0; k < problem.line.segments.size(); ++k)
      section(fmt::format("damping of segment {}", k), problem.line.segments[k].damping);
  }
  if (problem.seabed && problem.seabed->damping_n_s_per_m2 > 0.0)
    out += fmt::format("  seabed damping: c_s = {:g} N s/m per m\n",
                       problem.seabed->damping_n_s_per_m2);
}

// The Morison drag and tangential added mass of each section that has them, and the water
// (docs/reference/scene-format.md, "Drag and dynamic tension in waves"); nothing without drag.
void print_hydrodynamics(std::string& out, const Problem& problem) {
  const auto section = [&out](const std::string& what, const MorisonDrag& drag, double ma_t) {
    if (drag.is_zero() && ma_t == 0.0) return;
    out += fmt::format("  {}: d = {:g} m, Cd = {:g}, CdAx = {:g}, ma_t = {:g} kg/m\n", what,
                       drag.diameter_m, drag.normal, drag.tangential, ma_t);
  };
  if (problem.is_uniform()) {
    section("drag", problem.cable.drag, problem.cable.added_mass_tangential_kg_per_m);
  } else {
    for (std::size_t k = 0; k < problem.line.segments.size(); ++k) {
      const LineSegment& segment = problem.line.segments[k];
      section(fmt::format("drag of segment {}", k), segment.drag,
              segment.added_mass_tangential_kg_per_m);
    }
  }
  if (problem.has_drag())
    out += fmt::format("  water: rho = {:g} kg/m^3, g = {:g} m/s^2\n",
                       problem.environment.water_density_kg_per_m3,
                       problem.environment.gravity_m_per_s2);
}

// The seabed in one line: its depth and the stretches resting on it, with the touchdown points.
std::string seabed_text(const StaticSolution& statics, double length_m) {
  std::string text = fmt::format("  seabed at z = {:g} m: ", statics.seabed().z_m);
  const auto intervals = statics.contact_intervals();
  if (intervals.empty()) return text + "the line does not touch it (grounded length 0)\n";
  std::vector<std::string> touchdowns;
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    const ContactInterval& c = intervals[i];
    text += fmt::format("{}s = {:.6g} to {:.6g} m on it", i ? ", " : "", c.s_begin_m, c.s_end_m);
    for (const double s : {c.s_begin_m, c.s_end_m})
      if (s > 0.0 && s < length_m) touchdowns.push_back(fmt::format("{:.6g}", s));
  }
  text += fmt::format(" (grounded length {:.6g} m)", statics.grounded_length_m());
  if (!touchdowns.empty()) {
    text += "; touchdown at s = ";
    for (std::size_t i = 0; i < touchdowns.size(); ++i) text += (i ? ", " : "") + touchdowns[i];
    text += " m";
  }
  return text + "\n";
}

}  // namespace

std::string statics_text(const SceneResult& result) {
  const StaticSolution& statics = *result.statics;
  const double length_m = result.scene.problem.is_uniform() ? result.scene.problem.cable.length_m
                                                            : result.scene.problem.line.length_m();
  std::string text = fmt::format(
      "  statics: H = {:.10g} N, T_A = {:.10g} N, T_B = {:.10g} N, closure {:.1e} m ({} Newton "
      "iterations)\n",
      statics.horizontal_force_n(), statics.tension_n(0.0), statics.tension_n(length_m),
      statics.closure_error_m, statics.iterations);
  if (statics.has_seabed()) text += seabed_text(statics, length_m);
  return text;
}

std::string problem_text(const SceneResult& result) {
  const Problem& problem = result.scene.problem;
  std::string out;
  if (problem.is_uniform()) {
    print_cable(out, problem);
    print_damping(out, problem);
    print_hydrodynamics(out, problem);
    if (result.groups) print_groups(out, *result.groups);
  } else {
    print_line_statics(out, problem, *result.statics);
    print_damping(out, problem);
    print_hydrodynamics(out, problem);
  }
  return out;
}

}  // namespace catena::cli
