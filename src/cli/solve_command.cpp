// SPDX-License-Identifier: MIT
// `catena solve SCENE [--json FILE]`: one scene (or one sweep), every applicable solver.
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_picture.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/verification/certified_reference.hpp"
#include "catena/verification/scene_runner.hpp"
#include "cli/commands.hpp"
#include "cli/solve_table.hpp"
#include "cli/solve_table_notes.hpp"
#include "cli/solve_table_problem.hpp"
#include "cli/solve_table_rows.hpp"
#include "cli/solve_units.hpp"
#include "cli/terminal_progress.hpp"
#include "cli/terminal_style.hpp"

namespace catena::cli {
namespace {

struct SolveArguments {
  std::string scene;
  std::string json;
  std::vector<std::string> solvers;
  bool quiet = false;
  bool verbose = false;
  std::string units = "rad/s";
  double time_limit_s = 0.0;
  const CLI::Option* time_limit = nullptr;
  TableArguments tables;
  PictureArguments picture;
};

// True when --json writes to this process's stdout ("-", /dev/stdout, the file stdout is
// redirected to): then --quiet prints nothing else there, so that stdout holds the JSON alone.
bool json_on_stdout(const std::string& json) {
  if (json == "-") return true;
  struct stat file {};
  struct stat out {};
  return !json.empty() && ::stat(json.c_str(), &file) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
         file.st_dev == out.st_dev && file.st_ino == out.st_ino;
}

struct PrintOptions {
  FrequencyUnit unit = FrequencyUnit::RadPerSecond;
  bool verbose = false;
  TextStyle style;
};

// The certified reference of each plane with modes (catena/verification/certified_reference.hpp:
// the exact solver that converged with the smaller error estimate), empty for a plane without.
std::array<std::string, 2> references(const SceneResult& result) {
  std::array<std::string, 2> names;
  for (const Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    std::string why;
    const auto reference = certified_reference(result.outputs, plane, why);
    if (reference) names[plane == Plane::InPlane ? 0 : 1] = reference->solver;
  }
  return names;
}

// The scene's verdict in one line: FAIL when a check failed (exit 1), the count of each verdict
// (as in --json's checks), and the reference solver of the modes.
std::string verdict_line(const SceneResult& result, const TextStyle& style) {
  if (!result.error.empty())
    return fmt::format("verdict: {}, {}: not solved (the error is on stderr)\n",
                       style.verdict("ERROR", "FAIL"), result.scene.name);
  std::map<Verdict, int> counts;
  for (const auto& check : result.checks) ++counts[check.verdict];
  const bool failed = counts[Verdict::Fail] > 0;
  std::string text = fmt::format("verdict: {}, {}: {} checks: {} PASS, {} FAIL",
                                 style.verdict(failed ? "FAIL" : "PASS", failed ? "FAIL" : "PASS"),
                                 result.scene.name, result.checks.size(), counts[Verdict::Pass],
                                 counts[Verdict::Fail]);
  for (const Verdict verdict : {Verdict::SourceDiscrepancy, Verdict::Warn, Verdict::Skipped})
    if (counts[verdict] > 0) text += fmt::format(", {} {}", counts[verdict], to_string(verdict));
  const auto names = references(result);
  if (!names[0].empty() && (names[0] == names[1] || names[1].empty()))
    text += fmt::format("; reference: {}", names[0]);
  else if (!names[1].empty())
    text += fmt::format("; reference: {} in-plane, {} out-of-plane",
                        names[0].empty() ? "none" : names[0], names[1]);
  return text + "\n";
}

void print_table(const std::optional<SolverTable>& table, const TextStyle& style) {
  if (!table) return;
  for (const auto& line : render_table(*table, style, "  ")) fmt::print("{}\n", line);
}

void print_result(const SceneResult& result, const PrintOptions& options) {
  const Scene& scene = result.scene;
  fmt::print("scene {} ({})\n", scene.name, path_text(scene.file));
  if (!result.error.empty()) {
    fmt::print("  error: {}\n{}", result.error, verdict_line(result, options.style));
    return;
  }
  if (options.verbose) fmt::print("{}", problem_text(result));
  fmt::print("{}", statics_text(result));
  const FrequencyUnit unit = usable_unit(result, options.unit);
  if (unit != options.unit)
    fmt::print(  // only Gale's ratio can be missing (solve_units.hpp)
        "  (--units gale: Gale's ratio is defined for one uniform cable only; rad/s shown)\n");
  const auto names = references(result);
  bool tables = false, missed = false;
  for (const Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const auto table = modal_table(result, plane, unit, names[plane == Plane::InPlane ? 0 : 1]);
    tables = tables || table;
    missed = missed || (table && misses_target(*table));
    print_table(table, options.style);
  }
  const auto forced = forced_table(result);
  const auto tension = dynamic_tension_table(result);
  print_table(forced, options.style);
  print_table(tension, options.style);
  if (tables || forced || tension)
    fmt::print(
        "  est: relative error estimate{}; spread: (max - min) / max over the exact solvers\n",
        missed ? " (*: beyond the solver's target)" : "");
  fmt::print("{}", solver_notes(result, options.verbose));
  if (options.verbose) fmt::print("{}", solver_details(result));
  fmt::print("{}{}", check_notes(result, options.verbose), verdict_line(result, options.style));
}

}  // namespace

void add_solve_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<SolveArguments>();
  CLI::App* command = app.add_subcommand(
      "solve",
      "Solve one scene file (or sweep) with every applicable solver and check them against each\n"
      "other. Prints per scene: the statics in a line or two; per plane a table with a row per\n"
      "mode and, per solver, its frequency (12 significant digits, unit in the header) and its\n"
      "relative error estimate (est), the relative spread between the exact solvers and the\n"
      "verdict of the mode's checks (the ones `catena verify` runs); forced responses and dynamic\n"
      "tension in tables of their own; one line per solver that declined or failed (why); the\n"
      "failed checks; and a last line with the verdict (checks passed and failed) and the\n"
      "reference solver. Tables wider than 120 columns continue below with the other solvers.\n"
      "--json writes every value (layout in docs/reference/json-layout.md; the text is described\n"
      "in docs/reference/solve-output.md). On a terminal, FAIL and WARN are coloured (not in a\n"
      "pipe, nor with NO_COLOR set or TERM=dumb), and long solves show their progress on stderr.");
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
  command->add_flag("--quiet,-q", arguments->quiet,
                    "Print only each scene's verdict line (and errors, on stderr)");
  command->add_flag("--verbose,-v", arguments->verbose,
                    "Also print the problem (cable or line, damping, drag, dimensionless groups,\n"
                    "the statics at every joint and point) and every long message once: each\n"
                    "solver's resolution and time, its summaries, warnings and notes, and every\n"
                    "check that is not PASS");
  command->add_option(
      "--units", arguments->units,
      "Unit of the frequencies in the tables: rad/s (omega, the default), hz\n"
      "(f = omega / 2 pi), kl-pi (kL/pi = omega L sqrt((m + ma) / T0) / pi: a taut\n"
      "string's modes are 1, 2, 3, ...) or gale (omega / sqrt(g/a), g = W0/m, a = "
      "H/W0:\nGale 1976's tables; uniform cables only, rad/s otherwise). --json "
      "always has all four.");
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
      if (arguments->quiet && arguments->verbose)
        throw InvalidInput("--quiet and --verbose: choose one");
      PrintOptions print;
      print.unit = parse_frequency_unit(arguments->units);
      print.verbose = arguments->verbose;
      print.style = style_for(stdout);
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
      const bool quiet_json = arguments->quiet && json_on_stdout(arguments->json);
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
        if (arguments->json == "-") continue;  // stdout holds the JSON alone
        if (arguments->quiet) {
          if (!quiet_json) fmt::print("{}", verdict_line(results.back(), print.style));
        } else {
          print_result(results.back(), print);
        }
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
