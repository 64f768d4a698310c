// `catena solve SCENE [--json FILE]`: one scene (or one sweep), every applicable solver.
#include <cmath>
#include <fmt/format.h>
#include <iostream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/verification/scene_runner.hpp"
#include "cli/commands.hpp"
#include "cli/terminal_progress.hpp"

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
};

void print_modes(const ModalResult& result, const char* title) {
  fmt::print("  {} ({}):\n", title, result.summary.message);
  fmt::print("    {:>4} {:>20} {:>16} {:>14} {:>14} {:>10}\n", "mode", "omega [rad/s]", "f [Hz]",
             "kL/pi", "w/sqrt(g/a)", "rel.err");
  for (const auto& mode : result.modes) {
    fmt::print("    {:>4} {:>20.12g} {:>16.10g} {:>14.9g} {:>14} {:>10.2e}\n", mode.index,
               mode.omega_rad_s, mode.frequency_hz, mode.k_l_over_pi,
               mode.gale_ratio ? fmt::format("{:.9g}", *mode.gale_ratio) : std::string("-"),
               mode.relative_error_estimate);
  }
  if (result.proved_count_below_top >= 0) {
    fmt::print("    modes proved below the top frequency: {}\n", result.proved_count_below_top);
  }
}

void print_result(const SceneResult& result) {
  const Scene& scene = result.scene;
  fmt::print("scene {} ({})\n", scene.name, path_text(scene.file));
  if (!result.error.empty()) {
    fmt::print("  error: {}\n", result.error);
    return;
  }
  const CableProperties& c = scene.problem.cable;
  fmt::print("  cable: L = {} m, W0 = {} N/m, EA = {} N, m = {} kg/m, ma = {} kg/m; a = ({}, {}) m, "
             "b = ({:.10g}, {:.10g}) m\n",
             c.length_m, c.weight_n_per_m, c.is_inextensible() ? "inf" : fmt::format("{:g}", c.axial_stiffness_n),
             c.mass_kg_per_m, c.added_mass_kg_per_m, scene.problem.supports.a_m.x(),
             scene.problem.supports.a_m.y(), scene.problem.supports.b_m.x(), scene.problem.supports.b_m.y());
  fmt::print("  statics: {}\n", result.statics->brief_report());
  const DimensionlessGroups& g = *result.groups;
  fmt::print("  groups: phi_a = {:.6g} deg, T0 = {:.10g} N, eps = {:.6g}, lambda^2 = {}, h = m/M = {:.6g}\n",
             g.chord_angle_rad * 180.0 / kPi, g.t0_n, g.eps,
             std::isfinite(g.lambda2) ? fmt::format("{:.6g}", g.lambda2) : std::string("inf"), g.mass_ratio);
  if (g.has_apex_parameterization) {
    fmt::print("  Gale: a = H/W0 = {:.10g} m, xi1 = {:.6g}, xi2 = {:.6g}, sigma1 = {:.6g}, sigma2 = {:.6g}{}{}\n",
               g.catenary_parameter_m, g.xi1, g.xi2, g.sigma1, g.sigma2,
               g.height_over_span ? fmt::format(", h/b = {:.6g}", *g.height_over_span) : std::string(),
               g.sag_parameter ? fmt::format(", sag parameter = {:.6g}", *g.sag_parameter) : std::string());
  }
  for (const auto& output : result.outputs) {
    fmt::print("  solver {}\n", output.summary.brief_report());
    for (const auto& warning : output.summary.warnings) fmt::print("    warning: {}\n", warning);
    if (output.inplane) print_modes(*output.inplane, "in-plane");
    if (output.outofplane) print_modes(*output.outofplane, "out-of-plane");
    for (const auto& response : output.forced) {
      fmt::print("    forced at {:.6g} rad/s: max |tau| = {:.6g} N{}\n", response.omega_rad_s,
                 response.max_abs_tension_n,
                 response.diagnostic.empty() ? std::string() : " (" + response.diagnostic + ")");
    }
  }
  for (const auto& check : result.checks) {
    if (check.verdict == Verdict::Fail || check.verdict == Verdict::SourceDiscrepancy) {
      fmt::print("  check {} [{}] {}: {}\n", check.check, to_string(check.verdict), check.compare, check.detail);
    }
  }
}

}  // namespace

void add_solve_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<SolveArguments>();
  CLI::App* command = app.add_subcommand(
      "solve",
      "Solve one scene file: statics, dimensionless groups and every applicable solver.\n"
      "Prints a summary; --json writes the full results (layout in docs/json-layout.md).\n"
      "On a terminal, long solves show their progress on stderr (\"shooting: in-plane modes 37/600\").");
  command->add_option("scene", arguments->scene,
                      "Scene file (TOML, a regular file of at most 1 MiB; format and limits in\n"
                      "docs/scene-format.md)")
      ->required();
  command->add_option("--json", arguments->json, "Write the results as JSON to this file ('-' for stdout); checked to be\n"
                      "writable before solving, written whole or not at all");
  command->add_option("--solver", arguments->solvers,
                      "Run only this solver (repeatable): fe, shooting, frobenius, asymptotic, airy");
  command->add_flag("--quiet,-q", arguments->quiet, "Print nothing but errors");
  arguments->time_limit = add_time_limit_option(
      *command, arguments->time_limit_s,
      "for each scene (a sweep file: each of its scenes), from the start of its statics");
  add_table_options(*command, arguments->tables);
  command->callback([arguments, &run] {
    run = [arguments] {
      for (const auto& name : arguments->solvers) {
        if (!find_solver(name)) throw InvalidInput(fmt::format("--solver {}: unknown solver", name));
      }
      // A bad --json fails before the solving, not after it.
      if (!arguments->json.empty() && arguments->json != "-") check_output_file(arguments->json);
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
      return exit_code_of(results);
    };
  });
}

}  // namespace catena::cli
