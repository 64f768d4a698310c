// `catena verify`: every scene under a directory, on all cores, with a summary and report.json.
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/verification/scene_runner.hpp"
#include "catena/verification/suite.hpp"
#include "cli/commands.hpp"

namespace catena::cli {
namespace {

struct VerifyArguments {
  std::string scenes = "verification/scenes";
  std::string out = "build/report";
  std::string filter;
  int jobs = 0;
  bool quiet = false;
  std::string perturb;
  double time_limit_s = 0.0;
  const CLI::Option* time_limit = nullptr;
  TableArguments tables;
};

// "--perturb fe:inplane:2:1e-3" -> Perturbation.
std::optional<Perturbation> parse_perturbation(const std::string& text) {
  if (text.empty()) return std::nullopt;
  Perturbation p;
  char plane[32] = {0};
  char solver[32] = {0};
  if (std::sscanf(text.c_str(), "%31[^:]:%31[^:]:%d:%lf", solver, plane, &p.mode, &p.relative) != 4 ||
      (std::string(plane) != "inplane" && std::string(plane) != "outofplane") || !find_solver(solver)) {
    throw InvalidInput(fmt::format("--perturb {}: expected SOLVER:inplane|outofplane:MODE:RELATIVE", text));
  }
  p.solver = solver;
  p.plane = std::string(plane) == "inplane" ? Plane::InPlane : Plane::OutOfPlane;
  return p;
}

// Reads every scene file; collects every parse error before giving up, so one run shows them all.
std::vector<Scene> read_all(const std::vector<std::filesystem::path>& files, const std::string& filter) {
  std::vector<Scene> scenes;
  std::vector<std::string> errors;
  for (const auto& file : files) {
    try {
      for (auto& scene : read_scene_file(file)) {
        if (filter.empty() || scene.name.find(filter) != std::string::npos ||
            file.string().find(filter) != std::string::npos) {
          scenes.push_back(std::move(scene));
        }
      }
    } catch (const Error& error) {
      errors.push_back(error.what());
    }
  }
  if (!errors.empty()) {
    std::string message = fmt::format("{} scene file(s) could not be read:", errors.size());
    for (const auto& e : errors) message += "\n  " + e;
    throw InvalidInput(message);
  }
  return scenes;
}

std::string solver_column(const SceneResult& result) {
  std::string text;
  for (const auto& output : result.outputs) {
    const char* mark = "?";
    switch (output.summary.termination) {
      case Termination::Converged: mark = "ok"; break;
      case Termination::NoConvergence: mark = "partial"; break;
      case Termination::NumericalFailure: mark = "FAILED"; break;
      case Termination::NotApplicable: mark = "n/a"; break;
    }
    if (output.summary.termination == Termination::NotApplicable) continue;
    text += fmt::format("{}{}:{}", text.empty() ? "" : " ", output.solver, mark);
  }
  return text.empty() ? "statics only" : text;
}

int run_verify(const VerifyArguments& arguments) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Scene> scenes = read_all(list_scene_files(arguments.scenes), arguments.filter);
  if (scenes.empty()) throw InvalidInput(fmt::format("no scenes under {} match '{}'", arguments.scenes, arguments.filter));

  const int jobs = arguments.jobs > 0 ? arguments.jobs
                                      : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const bool progress = !arguments.quiet && isatty(STDERR_FILENO);
  SceneRunOptions run_options = run_options_with_tables(arguments.tables);
  run_options.perturbation = parse_perturbation(arguments.perturb);
  apply_time_limit(*arguments.time_limit, arguments.time_limit_s, run_options);
  const std::vector<SceneResult> results =
      run_scenes(scenes, jobs, run_options, [&](std::size_t done, std::size_t total, const std::string& name) {
        if (progress) fmt::print(stderr, "\r\033[K[{}/{}] {}", done, total, name);
      });
  if (progress) fmt::print(stderr, "\r\033[K");

  int failed_checks = 0, total_checks = 0, errors = 0, discrepancies = 0;
  for (const auto& result : results) {
    failed_checks += result.failed_checks();
    total_checks += static_cast<int>(result.checks.size());
    errors += !result.error.empty();
    for (const auto& check : result.checks) discrepancies += check.verdict == Verdict::SourceDiscrepancy;
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (!arguments.quiet) {
    fmt::print("{:<48} {:>8} {:>7} {:>9}  {}\n", "scene", "checks", "failed", "time [ms]", "solvers");
    for (const auto& result : results) {
      fmt::print("{:<48} {:>8} {:>7} {:>9.1f}  {}\n", result.scene.name, result.checks.size(),
                 result.failed_checks(), result.wall_time_s * 1e3,
                 result.error.empty() ? solver_column(result) : "ERROR: " + result.error);
    }
  }
  for (const auto& result : results) {
    for (const auto& check : result.checks) {
      if (check.verdict != Verdict::Fail) continue;
      fmt::print("FAIL {} / {} / {}{}: measured {:.3e} > tolerance {:.3e}: {}\n", result.scene.name,
                 check.check, check.compare, check.mode ? fmt::format(" mode {}", check.mode) : "",
                 check.measured, check.tolerance, check.detail);
    }
  }
  const auto report = std::filesystem::path(arguments.out) / "report.json";
  write_results_json(report, results);
  fmt::print("{} scenes, {} checks, {} failed, {} source discrepancies, {} scene errors; {:.1f} s on {} "
             "threads; wrote {}\n",
             results.size(), total_checks, failed_checks, discrepancies, errors, elapsed, jobs,
             report.string());
  for (const auto& result : results) {
    if (!result.error.empty()) fmt::print(stderr, "error: {}\n", result.error);
  }
  return exit_code_of(results);
}

}  // namespace

void add_verify_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<VerifyArguments>();
  CLI::App* command = app.add_subcommand(
      "verify",
      "Run the verification suite: every scene under --scenes, every applicable solver,\n"
      "cross-checked; prints a summary and writes <out>/report.json. Exit 1 if a check fails.");
  command->add_option("--scenes", arguments->scenes, "Directory of scene files (searched recursively)")
      ->capture_default_str();
  command->add_option("--out", arguments->out, "Directory for report.json")->capture_default_str();
  command->add_option("--filter", arguments->filter, "Only scenes whose name or file contains this text");
  command->add_option("--jobs,-j", arguments->jobs, "Worker threads (default: all cores)");
  command->add_flag("--quiet,-q", arguments->quiet, "Print only failures and the closing line");
  command->add_option("--perturb", arguments->perturb,
                      "Testing the harness: multiply one frequency of one solver by (1 + RELATIVE),\n"
                      "as SOLVER:inplane|outofplane:MODE:RELATIVE; the run must then fail");
  arguments->time_limit = add_time_limit_option(
      *command, arguments->time_limit_s, "for each scene, from the start of its statics");
  add_table_options(*command, arguments->tables);
  command->callback([arguments, &run] { run = [arguments] { return run_verify(*arguments); }; });
}

}  // namespace catena::cli
