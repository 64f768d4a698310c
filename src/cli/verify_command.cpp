// SPDX-License-Identifier: MIT
// `catena verify`: every scene under a directory, on all cores, with a summary and report.json.
#include <fmt/format.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/verification/independence.hpp"
#include "catena/verification/mutation.hpp"
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
  bool mutation = false;
  std::string perturb;
  double time_limit_s = 0.0;
  const CLI::Option* time_limit = nullptr;
  TableArguments tables;
};

// "--perturb fe:inplane:2:1e-3" -> Perturbation. Every part is checked whole: a mode that does
// not fit an int or a factor that changes nothing would perturb nothing, and the run meant to fail
// would pass.
std::optional<Perturbation> parse_perturbation(const std::string& text) {
  if (text.empty()) return std::nullopt;
  auto fail = [&](const std::string& why) {
    throw InvalidInput(
        fmt::format("--perturb {}: {} (expected SOLVER:inplane|outofplane:MODE:RELATIVE, MODE in "
                    "[1, {}], RELATIVE finite, non-zero and > -1)",
                    text, why, kMaxRequestModes));
  };
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == ':')
      parts.emplace_back();
    else
      parts.back().push_back(c);
  }
  if (parts.size() != 4) fail("expected 4 parts separated by ':'");
  Perturbation p;
  if (!find_solver(parts[0])) fail("unknown solver '" + parts[0] + "'");
  p.solver = parts[0];
  if (parts[1] != "inplane" && parts[1] != "outofplane")
    fail("plane must be inplane or outofplane");
  p.plane = parts[1] == "inplane" ? Plane::InPlane : Plane::OutOfPlane;
  long mode = 0;
  const auto [mode_end, mode_error] =
      std::from_chars(parts[2].data(), parts[2].data() + parts[2].size(), mode);
  if (mode_error != std::errc() || mode_end != parts[2].data() + parts[2].size() || mode < 1 ||
      mode > kMaxRequestModes) {
    fail("mode '" + parts[2] + "' out of range");
  }
  p.mode = static_cast<int>(mode);
  char* relative_end = nullptr;
  p.relative = std::strtod(parts[3].c_str(), &relative_end);
  if (parts[3].empty() || *relative_end != '\0' || !std::isfinite(p.relative) ||
      p.relative == 0.0 || p.relative <= -1.0) {
    fail("relative change '" + parts[3] + "' invalid");
  }
  return p;
}

// Before the solving: some scene must ask for that many modes in that plane.
void check_perturbation_requested(const Perturbation& p,
                                  const std::vector<Scene>& scenes,
                                  const std::string& text) {
  for (const auto& scene : scenes) {
    if ((p.plane == Plane::InPlane ? scene.request.inplane_modes
                                   : scene.request.outofplane_modes) >= p.mode)
      return;
  }
  throw InvalidInput(
      fmt::format("--perturb {}: no scene asks for {} {} modes, so nothing would be perturbed",
                  text, p.mode, p.plane == Plane::InPlane ? "in-plane" : "out-of-plane"));
}

// True when some scene gave the perturbed solver the perturbed mode (so it was changed).
bool perturbation_applied(const Perturbation& p, const std::vector<SceneResult>& results) {
  for (const auto& result : results) {
    for (const auto& output : result.outputs) {
      const auto& modal = p.plane == Plane::InPlane ? output.inplane : output.outofplane;
      if (output.solver != p.solver || !modal) continue;
      for (const auto& mode : modal->modes) {
        if (mode.index == p.mode) return true;
      }
    }
  }
  return false;
}

// The scenes read, and a result with the error for each file that could not be read: those are
// reported as scene errors while the others still run.
struct SceneFiles {
  std::vector<Scene> scenes;
  std::vector<SceneResult> unreadable;
};

SceneFiles read_all(const std::vector<std::filesystem::path>& files, const std::string& filter) {
  SceneFiles read;
  for (const auto& file : files) {
    const std::string file_text = path_text(file);
    try {
      for (auto& scene : read_scene_file(file)) {
        if (filter.empty() || scene.name.find(filter) != std::string::npos ||
            file_text.find(filter) != std::string::npos) {
          read.scenes.push_back(std::move(scene));
        }
      }
    } catch (const Error& error) {
      if (!filter.empty() && file_text.find(filter) == std::string::npos) continue;
      SceneResult result;
      result.scene.file = file;
      result.scene.name = path_text(file.stem());
      result.error = error.what();
      result.error_kind = SceneError::BadInput;
      read.unreadable.push_back(std::move(result));
    }
  }
  return read;
}

std::string solver_column(const SceneResult& result) {
  std::string text;
  for (const auto& output : result.outputs) {
    const char* mark = "?";
    switch (output.summary.termination) {
      case Termination::Converged:
        mark = "ok";
        break;
      case Termination::NoConvergence:
        mark = "partial";
        break;
      case Termination::NumericalFailure:
        mark = "FAILED";
        break;
      case Termination::NotApplicable:
        mark = "n/a";
        break;
    }
    if (output.summary.termination == Termination::NotApplicable) continue;
    text += fmt::format("{}{}:{}", text.empty() ? "" : " ", output.solver, mark);
  }
  return text.empty() ? "statics only" : text;
}

// One line per scene (unless quiet), then one line per failed check.
void print_table(const std::vector<SceneResult>& results, bool quiet) {
  if (!quiet) {
    fmt::print("{:<48} {:>8} {:>7} {:>9}  {}\n", "scene", "checks", "failed", "time [ms]",
               "solvers");
    for (const auto& result : results) {
      fmt::print("{:<48} {:>8} {:>7} {:>9.1f}  {}\n", result.scene.name, result.checks.size(),
                 result.failed_checks(), result.wall_time_s * 1e3,
                 result.error.empty() ? solver_column(result) : "ERROR: " + result.error);
    }
  }
  for (const auto& result : results) {
    for (const auto& check : result.checks) {
      if (check.verdict != Verdict::Fail) continue;
      fmt::print("FAIL {} / {} / {}{}: measured {:.3e} > tolerance {:.3e}: {}{}\n",
                 result.scene.name, check.check, check.compare,
                 check.mode ? fmt::format(" mode {}", check.mode) : "", check.measured,
                 check.tolerance, check.detail,
                 check.tolerance_reason.empty() ? "" : "; tolerance: " + check.tolerance_reason);
    }
  }
}

// The mutation score, by solver (all families and quantities), then the exact solvers' target.
void print_mutation(const MutationRun& run) {
  std::map<std::string, MutationTally> by_solver;
  for (const auto& [what, tally] : run.tallies()) {
    MutationTally& total = by_solver[std::get<0>(what)];
    total.made += tally.made;
    total.caught += tally.caught;
  }
  fmt::print("mutation score (docs/explanation/mutation.md):\n");
  for (const auto& [solver, tally] : by_solver) {
    fmt::print("  {:<11} {:>6} made, {:>6} caught, {:>6} uncaught ({:.1f}%)\n", solver, tally.made,
               tally.caught, tally.made - tally.caught,
               tally.made ? 100.0 * tally.caught / tally.made : 100.0);
  }
  const MutationTally exact = run.exact_with_witness();
  fmt::print(
      "  exact solvers where another exact solver ran: {} of {} caught, {} uncaught; {:.1f} s on "
      "{} threads\n",
      exact.caught, exact.made, exact.made - exact.caught, run.wall_time_s, run.threads);
  const MutationTally beyond = run.exact_beyond_estimate();
  fmt::print(
      "  of those, changes larger than the mutated value's own error estimate: {} of {} caught, {} "
      "uncaught\n",
      beyond.caught, beyond.made, beyond.made - beyond.caught);
}

// The mutation run over the solved results (nothing is re-solved), with its progress.
std::optional<MutationRun> mutation_run(const VerifyArguments& arguments,
                                        const std::vector<SceneResult>& results,
                                        const SceneRunOptions& options,
                                        int jobs,
                                        bool progress) {
  if (!arguments.mutation) return std::nullopt;
  MutationRun run = run_mutations(
      results, jobs, options, [&](std::size_t done, std::size_t total, const std::string& name) {
        if (progress) fmt::print(stderr, "\r\033[K[mutation {}/{}] {}", done, total, name);
      });
  if (progress) fmt::print(stderr, "\r\033[K");
  return run;
}

int run_verify(const VerifyArguments& arguments) {
  const auto start = std::chrono::steady_clock::now();
  const auto report = std::filesystem::path(arguments.out) / "report.json";
  check_output_file(report);  // a bad --out fails now, not after the solving
  std::vector<std::filesystem::path> inputs = list_scene_files(arguments.scenes);
  SceneFiles files = read_all(inputs, arguments.filter);
  inputs.insert(inputs.end(), {arguments.tables.tolerances, arguments.tables.findings});
  check_not_an_input(report, inputs, "--out");
  const std::vector<Scene>& scenes = files.scenes;
  if (scenes.empty() && files.unreadable.empty()) {
    throw InvalidInput(
        fmt::format("no scenes under {} match '{}'", arguments.scenes, arguments.filter));
  }

  const int jobs = arguments.jobs > 0
                       ? arguments.jobs
                       : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const bool progress = !arguments.quiet && isatty(STDERR_FILENO);
  SceneRunOptions run_options = run_options_with_tables(arguments.tables);
  run_options.perturbation = parse_perturbation(arguments.perturb);
  apply_time_limit(*arguments.time_limit, arguments.time_limit_s, run_options);
  if (run_options.perturbation)
    check_perturbation_requested(*run_options.perturbation, scenes, arguments.perturb);
  std::vector<SceneResult> results = run_scenes(
      scenes, jobs, run_options, [&](std::size_t done, std::size_t total, const std::string& name) {
        if (progress) fmt::print(stderr, "\r\033[K[{}/{}] {}", done, total, name);
      });
  if (progress) fmt::print(stderr, "\r\033[K");
  if (run_options.perturbation && !perturbation_applied(*run_options.perturbation, results)) {
    throw InvalidInput(
        fmt::format("--perturb {}: no scene gave solver {} that mode, so nothing was perturbed "
                    "and the run could not fail",
                    arguments.perturb, run_options.perturbation->solver));
  }
  const std::optional<MutationRun> mutation =
      mutation_run(arguments, results, run_options, jobs, progress);
  for (auto& result : files.unreadable) results.push_back(std::move(result));

  int failed_checks = 0, total_checks = 0, errors = 0, discrepancies = 0;
  for (const auto& result : results) {
    failed_checks += result.failed_checks();
    total_checks += static_cast<int>(result.checks.size());
    errors += !result.error.empty();
    for (const auto& check : result.checks)
      discrepancies += check.verdict == Verdict::SourceDiscrepancy;
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  print_table(results, arguments.quiet);
  write_results_json(report, results, mutation ? &*mutation : nullptr);
  if (mutation) print_mutation(*mutation);
  fmt::print(
      "{} scenes, {} checks, {} failed, {} source discrepancies, {} scene errors; {:.1f} s on {} "
      "threads; wrote {}\n",
      results.size(), total_checks, failed_checks, discrepancies, errors, elapsed, jobs,
      report.string());
  const IndependenceTally independence = tally_independence(results);
  fmt::print(
      "identity checks (two values from shared code): {}; pairs not compared (shared computation): "
      "{}\n",
      independence.identity_checks, independence.shared_not_compared);
  if (!files.unreadable.empty())
    fmt::print(stderr, "{} scene file(s) could not be read:\n", files.unreadable.size());
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
      "cross-checked; prints a summary and writes <out>/report.json. Exit 1 if a check fails.\n"
      "A *.toml entry that cannot be read (dangling symlink, FIFO, too large, bad TOML) is a\n"
      "scene error: the other scenes still run, the report is written, and the exit code is 2.");
  command
      ->add_option("--scenes", arguments->scenes, "Directory of scene files (searched recursively)")
      ->capture_default_str()
      ->check(non_empty_path());
  command
      ->add_option("--out", arguments->out,
                   std::string("Directory for report.json (checked to be writable before the\n"
                               "solving, created only when it is written); the file is written\n"
                               "whole or not at all.") +
                       kOutputPathHelp)
      ->capture_default_str()
      ->check(non_empty_path());
  command->add_option("--filter", arguments->filter,
                      "Only scenes whose name or file contains this text");
  command
      ->add_option("--jobs,-j", arguments->jobs,
                   "Worker threads, at least 1 (default: all cores, as many as the machine "
                   "reports;\nthe closing line says how many ran)")
      ->check(CLI::Validator(
          [](std::string& value) {
            // 0 and negatives used to mean "all cores" without saying so; a value that is not
            // an integer is left to CLI11's own conversion error.
            long jobs = 0;
            const auto [end, error] =
                std::from_chars(value.data(), value.data() + value.size(), jobs);
            const bool integer = error == std::errc() && end == value.data() + value.size();
            return integer && jobs < 1
                       ? std::string("must be at least 1 (omit -j/--jobs to use all cores)")
                       : std::string();
          },
          "", "at least 1"));
  command->add_flag("--quiet,-q", arguments->quiet, "Print only failures and the closing line");
  command->add_flag(
      "--mutation", arguments->mutation,
      "Also measure the mutation score: make one result at a time wrong (a frequency by\n"
      "10x the solver's accuracy target, a shape by a mode mix, a forced tension by 1e-4),\n"
      "re-run that scene's checks and count the mutations a check catches; printed and\n"
      "written to report.json (docs/explanation/mutation.md). Does not change the exit code");
  command->add_option(
      "--perturb", arguments->perturb,
      "Testing the harness: multiply one frequency of one solver by (1 + RELATIVE),\n"
      "as SOLVER:inplane|outofplane:MODE:RELATIVE; the run must then fail. Exit 2\n"
      "when no scene gives that solver that mode (nothing would be perturbed)");
  arguments->time_limit = add_time_limit_option(*command, arguments->time_limit_s,
                                                "for each scene, from the start of its statics");
  add_table_options(*command, arguments->tables);
  command->callback([arguments, &run] { run = [arguments] { return run_verify(*arguments); }; });
}

}  // namespace catena::cli
