// SPDX-License-Identifier: MIT
// `catena solve SCENE [--json FILE]`: one scene (or one sweep), every applicable solver.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_picture.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/verification/scene_runner.hpp"
#include "cli/commands.hpp"
#include "cli/terminal_progress.hpp"
#include "io/internal/dynamic_tension_text.hpp"

namespace catena::cli {
namespace {

struct SolveArguments {
  std::string scene;
  std::string json;
  std::vector<std::string> solvers;
  bool quiet = false;
  double time_limit_s = 0.0;
  const CLI::Option* time_limit = nullptr;
  TableArguments tables;
  PictureArguments picture;
};

// A damped line's modes: the damped frequency omega_d = Im lambda, the decay rate delta = -Re
// lambda and the damping ratio zeta, each with the solver's estimate; overdamped roots after them.
void print_damped_modes(const ModalResult& result) {
  fmt::print("    {:>4} {:>20} {:>16} {:>16} {:>12} {:>10} {:>10}\n", "mode", "omega_d [rad/s]",
             "f_d [Hz]", "delta [1/s]", "zeta", "rel.err", "delta err");
  // A missing estimate (-1; e.g. omega_d of an overdamped root, which is exactly 0) prints "-".
  const auto estimate = [](double value) {
    return value >= 0.0 ? fmt::format("{:.2e}", value) : std::string("-");
  };
  const auto row = [&](const Mode& mode, const std::string& label) {
    fmt::print("    {:>4} {:>20.12g} {:>16.10g} {:>16.10g} {:>12.6g} {:>10} {:>10}\n", label,
               mode.omega_rad_s, mode.frequency_hz, mode.decay_rate_1_s, mode.damping_ratio,
               estimate(mode.relative_error_estimate), estimate(mode.decay_rate_error_estimate));
  };
  for (const auto& mode : result.modes) row(mode, std::to_string(mode.index));
  for (const auto& mode : result.overdamped) row(mode, fmt::format("od{}", mode.index));
  if (!result.overdamped.empty())
    fmt::print("    (od: overdamped roots, lambda = -delta real, no oscillation)\n");
}

void print_modes(const ModalResult& result, const char* title, bool damped) {
  fmt::print("  {} ({}):\n", title, result.summary.message);
  if (damped) {
    print_damped_modes(result);
  } else {
    fmt::print("    {:>4} {:>20} {:>16} {:>14} {:>14} {:>10}\n", "mode", "omega [rad/s]", "f [Hz]",
               "kL/pi", "w/sqrt(g/a)", "rel.err");
    for (const auto& mode : result.modes) {
      fmt::print("    {:>4} {:>20.12g} {:>16.10g} {:>14.9g} {:>14} {:>10.2e}\n", mode.index,
                 mode.omega_rad_s, mode.frequency_hz, mode.k_l_over_pi,
                 mode.gale_ratio ? fmt::format("{:.9g}", *mode.gale_ratio) : std::string("-"),
                 mode.relative_error_estimate);
    }
  }
  if (result.proved_count_below_top >= 0) {
    fmt::print("    modes proved below the top frequency: {}\n", result.proved_count_below_top);
  }
}

void print_cable(const Problem& problem) {
  const CableProperties& c = problem.cable;
  fmt::print(
      "  cable: L = {} m, W0 = {} N/m, EA = {} N, m = {} kg/m, ma = {} kg/m; a = ({}, {}) m, "
      "b = ({:.10g}, {:.10g}) m\n",
      c.length_m, c.weight_n_per_m,
      c.is_inextensible() ? "inf" : fmt::format("{:g}", c.axial_stiffness_n), c.mass_kg_per_m,
      c.added_mass_kg_per_m, problem.supports.a_m.x(), problem.supports.a_m.y(),
      problem.supports.b_m.x(), problem.supports.b_m.y());
}

void print_groups(const DimensionlessGroups& g) {
  fmt::print(
      "  groups: phi_a = {:.6g} deg, T0 = {:.10g} N, eps = {:.6g}, lambda^2 = {}, h = m/M = "
      "{:.6g}\n",
      g.chord_angle_rad * 180.0 / kPi, g.t0_n, g.eps,
      std::isfinite(g.lambda2) ? fmt::format("{:.6g}", g.lambda2) : std::string("inf"),
      g.mass_ratio);
  if (g.has_apex_parameterization) {
    fmt::print(
        "  Gale: a = H/W0 = {:.10g} m, xi1 = {:.6g}, xi2 = {:.6g}, sigma1 = {:.6g}, sigma2 = "
        "{:.6g}{}{}\n",
        g.catenary_parameter_m, g.xi1, g.xi2, g.sigma1, g.sigma2,
        g.height_over_span ? fmt::format(", h/b = {:.6g}", *g.height_over_span) : std::string(),
        g.sag_parameter ? fmt::format(", sag parameter = {:.6g}", *g.sag_parameter)
                        : std::string());
  }
}

// One row of the line's statics table at s (forces on the side of b; a point's jump shown).
void print_line_row(const StaticSolution& statics, const std::string& what, double s) {
  const Vec2 r = statics.position_m(s);
  const double before = statics.vertical_force_before_n(s);
  const double after = statics.vertical_force_n(s);
  fmt::print("    {:<12} {:>12.6g} {:>12.6g} {:>12.6g} {:>13.7g} {:>13.7g} {:>13.7g} {:>12.6g}\n",
             what, s, r.x(), r.y(), statics.horizontal_force_n(), after, statics.tension_n(s),
             statics.stretched_length_m(s));
  if (before != after)
    fmt::print("    {:<12} (V jumps by the point's weight: {:.7g} N before it)\n", "", before);
}

// The statics table of a general line: both ends, every joint and every point in order of s.
void print_line_statics(const Problem& problem, const StaticSolution& statics) {
  const Line& line = problem.line;
  fmt::print("  line: {} segments, {} points, L = {} m; a = ({}, {}) m, b = ({:.10g}, {:.10g}) m\n",
             line.segments.size(), line.points.size(), line.length_m(), problem.supports.a_m.x(),
             problem.supports.a_m.y(), problem.supports.b_m.x(), problem.supports.b_m.y());
  fmt::print("  statics: {}\n", statics.brief_report());
  fmt::print("    {:<12} {:>12} {:>12} {:>12} {:>13} {:>13} {:>13} {:>12}\n", "where", "s [m]",
             "x [m]", "z [m]", "H [N]", "V [N]", "T [N]", "stretched [m]");
  std::vector<std::pair<double, std::string>> rows{{0.0, "end a"}, {line.length_m(), "end b"}};
  for (std::size_t k = 1; k < line.segments.size(); ++k)
    rows.emplace_back(line.segment_start_m(k), fmt::format("joint {}", k));
  for (std::size_t i = 0; i < line.points.size(); ++i)
    rows.emplace_back(line.points[i].s_m, fmt::format("point {}", i));
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [s, what] : rows) print_line_row(statics, what, s);
  const double low = statics.lowest_point_s_m();
  fmt::print("  lowest point: s = {:.6g} m, x = {:.6g} m, z = {:.6g} m\n", low,
             statics.position_m(low).x(), statics.position_m(low).y());
}

// The damping of a damped problem (docs/reference/scene-format.md, "Damping"): the cable's, each
// damped segment's and the seabed dashpot; nothing for an undamped one, whose output is unchanged.
void print_damping(const Problem& problem) {
  const auto section = [](const std::string& what, const SectionDamping& d) {
    if (d.is_zero()) return;
    fmt::print("  {}: c_t = {:g} N s/m per m, c_n = {:g} N s/m per m, c_a = {:g} N s\n", what,
               d.tangential_n_s_per_m2, d.normal_n_s_per_m2, d.axial_n_s);
  };
  if (problem.is_uniform()) {
    section("damping", problem.cable.damping);
  } else {
    for (std::size_t k = 0; k < problem.line.segments.size(); ++k)
      section(fmt::format("damping of segment {}", k), problem.line.segments[k].damping);
  }
  if (problem.seabed && problem.seabed->damping_n_s_per_m2 > 0.0)
    fmt::print("  seabed damping: c_s = {:g} N s/m per m\n", problem.seabed->damping_n_s_per_m2);
}

// The Morison drag and tangential added mass of each section that has them, and the water
// (docs/reference/scene-format.md, "Drag and dynamic tension in waves"); nothing without drag.
void print_hydrodynamics(const Problem& problem) {
  const auto section = [](const std::string& what, const MorisonDrag& drag, double ma_t) {
    if (drag.is_zero() && ma_t == 0.0) return;
    fmt::print("  {}: d = {:g} m, Cd = {:g}, CdAx = {:g}, ma_t = {:g} kg/m\n", what,
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
    fmt::print("  water: rho = {:g} kg/m^3, g = {:g} m/s^2\n",
               problem.environment.water_density_kg_per_m3, problem.environment.gravity_m_per_s2);
}

void print_result(const SceneResult& result) {
  const Scene& scene = result.scene;
  fmt::print("scene {} ({})\n", scene.name, path_text(scene.file));
  if (!result.error.empty()) {
    fmt::print("  error: {}\n", result.error);
    return;
  }
  if (scene.problem.is_uniform()) {
    print_cable(scene.problem);
    print_damping(scene.problem);
    print_hydrodynamics(scene.problem);
    fmt::print("  statics: {}\n", result.statics->brief_report());
    print_groups(*result.groups);
  } else {
    print_line_statics(scene.problem, *result.statics);
    print_damping(scene.problem);
    print_hydrodynamics(scene.problem);
  }
  for (const auto& output : result.outputs) {
    fmt::print("  solver {}\n", output.summary.brief_report());
    for (const auto& warning : output.summary.warnings) fmt::print("    warning: {}\n", warning);
    const bool damped = scene.problem.is_damped();
    if (output.inplane) print_modes(*output.inplane, "in-plane", damped);
    if (output.outofplane) print_modes(*output.outofplane, "out-of-plane", damped);
    for (const auto& response : output.forced) {
      fmt::print("    forced at {:.6g} rad/s: max |tau| = {:.6g} N{}\n", response.omega_rad_s,
                 response.max_abs_tension_n,
                 response.diagnostic.empty() ? std::string() : " (" + response.diagnostic + ")");
    }
    if (result.request.motion) {
      fmt::print("{}", internal::dynamic_tension_text(output.dynamic_tension,
                                                      result.request.motion->duration_s, "    "));
    }
  }
  for (const auto& check : result.checks) {
    if (check.verdict == Verdict::Fail || check.verdict == Verdict::SourceDiscrepancy) {
      fmt::print("  check {} [{}] {}: {}\n", check.check, to_string(check.verdict), check.compare,
                 check.detail);
    }
  }
}

}  // namespace

void add_solve_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<SolveArguments>();
  CLI::App* command = app.add_subcommand(
      "solve",
      "Solve one scene file: statics, dimensionless groups and every applicable solver.\n"
      "Prints a summary (with [request.motion], each solver's dynamic tension at the fairlead\n"
      "and the anchor: per period mean, amplitude, phase and max = mean + amplitude, or mean,\n"
      "std, Tz and the most probable max in the duration; and the fixed point's iterations and\n"
      "residual); --json writes the full results (layout in docs/reference/json-layout.md).\n"
      "On a terminal, long solves show their progress on stderr (\"shooting: in-plane modes "
      "37/600\").");
  command
      ->add_option("scene", arguments->scene,
                   "Scene file (TOML, a regular file of at most 1 MiB; format and limits in\n"
                   "docs/reference/scene-format.md)")
      ->required()
      ->check(non_empty_path());
  command
      ->add_option("--json", arguments->json,
                   std::string("Write the results as JSON to this file ('-' for stdout); checked "
                               "to be\nwritable before solving, written whole or not at all.") +
                       kOutputPathHelp)
      ->check(non_empty_path());
  command->add_option(
      "--solver", arguments->solvers,
      "Run only this solver (repeatable): fe, shooting, frobenius, asymptotic, airy");
  command->add_flag("--quiet,-q", arguments->quiet, "Print nothing but errors");
  arguments->time_limit = add_time_limit_option(
      *command, arguments->time_limit_s,
      "for each scene (a sweep file: each of its scenes), from the start of its statics");
  add_table_options(*command, arguments->tables);
  command
      ->add_option("--plot", arguments->picture.out,
                   "Draw each scene to this .svg (or .png, with matplotlib): profile, modes,\n"
                   "tension (docs/how-to/plot.md). A scene that asks for no shapes is solved a\n"
                   "second time for the picture, with shapes, by the exact solvers that ran and\n"
                   "without checks (its output, --json and exit status are those of the solve\n"
                   "as asked). A sweep: <stem>-<scene name>.svg per scene.")
      ->check(non_empty_path());
  add_picture_options(*command, arguments->picture);
  command->callback([arguments, &run] {
    run = [arguments] {
      for (const auto& name : arguments->solvers) {
        if (!find_solver(name))
          throw InvalidInput(fmt::format("--solver {}: unknown solver", name));
      }
      // A bad --json fails before the solving, not after it.
      if (!arguments->json.empty() && arguments->json != "-") {
        check_output_file(arguments->json);
        check_not_an_input(
            arguments->json,
            {arguments->scene, arguments->tables.tolerances, arguments->tables.findings}, "--json");
      }
      const bool plot = !arguments->picture.out.empty();
      const ScenePictureOptions picture = picture_options(arguments->picture);
      if (plot) {
        check_scene_picture_output(arguments->picture.out, "--plot", picture);
        check_not_an_input(arguments->picture.out, {arguments->scene}, "--plot");
      }
      const std::vector<Scene> scenes = read_scene_file(arguments->scene);
      std::vector<SceneResult> results;
      SceneRunOptions options = run_options_with_tables(arguments->tables);
      options.only_solvers = arguments->solvers;
      apply_time_limit(*arguments->time_limit, arguments->time_limit_s, options);
      TerminalProgress progress(!arguments->quiet);
      options.progress = [&progress](const std::string& solver, const std::string& part, long done,
                                     long total) { progress.update(solver, part, done, total); };
      for (const auto& scene : scenes) {
        results.push_back(run_scene(scene, options));
        progress.clear();
        if (!arguments->quiet && arguments->json != "-") print_result(results.back());
      }
      if (arguments->json == "-") {
        std::cout << results_to_json(results) << '\n';
      } else if (!arguments->json.empty()) {
        write_results_json(arguments->json, results);
        if (!arguments->quiet) fmt::print("wrote {}\n", arguments->json);
      }
      for (const auto& result : results) {
        if (!result.error.empty()) fmt::print(stderr, "error: {}\n", result.error);
      }
      if (!plot) return exit_code_of(results);
      return draw_results(results_with_shapes(scenes, results, options), arguments->picture.out,
                          picture, arguments->quiet || arguments->json == "-",
                          exit_code_of(results));
    };
  });
}

}  // namespace catena::cli
