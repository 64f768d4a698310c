// SPDX-License-Identifier: MIT
// `catena check RESULTS --scene SCENE`: another program's modal results against Catena's certified
// reference for the same scene (docs/how-to/check.md).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/check_report.hpp"
#include "catena/io/external_results_reader.hpp"
#include "catena/io/external_tension_reader.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tension_check_json.hpp"
#include "catena/io/timeseries_reader.hpp"
#include "catena/verification/scene_check.hpp"
#include "catena/verification/scene_tension_check.hpp"
#include "cli/check_timeseries.hpp"
#include "cli/commands.hpp"

namespace catena::cli {
namespace {

struct CheckArguments {
  // Every positional file; a modal or tension results file is the only one (`results`).
  std::vector<std::string> files;
  std::string results;
  std::string shapes;
  std::string scene;
  std::string json;
  std::string out;
  double rtol = 1e-3;
  bool quiet = false;
  // The time-series check's own options (cli/check_timeseries.hpp).
  TimeSeriesArguments series;
};

Scene read_one_scene(const std::string& path) {
  std::vector<Scene> scenes = read_scene_file(path);
  if (scenes.size() != 1) {
    throw InvalidInput(
        fmt::format("{}: a sweep of {} scenes; catena check takes one scene", path, scenes.size()));
  }
  return scenes.front();
}

// A study's order or bias, marked "?" when the study was judged untrustworthy (its note, printed
// under the table, says why): the number is what the fit gave, not a result to rely on.
std::string study_number(const std::optional<ConvergenceStudy>& study,
                         std::optional<double> ConvergenceStudy::*field,
                         bool scientific) {
  if (!study || !((*study).*field)) return "-";
  const double value = *((*study).*field);
  return (scientific ? fmt::format("{:.3e}", value) : fmt::format("{:.3f}", value)) +
         (study->trustworthy ? "" : "?");
}

void print_check(const ExternalCheck& check) {
  for (const auto& reference : check.references) {
    fmt::print("reference {}: {}\n", to_string(reference.plane), reference.reason);
    if (reference.cross_check_relative >= 0.0) {
      fmt::print("  shooting and fe agree to {:.2e} (largest relative difference)\n",
                 reference.cross_check_relative);
    }
  }
  fmt::print("{:>12} {:>4} {:>6} {:>16} {:>16} {:>10} {:>10} {:>8} {:>8} {:>10}  {}\n", "plane",
             "mode", "catena", "other f [Hz]", "catena f [Hz]", "estimate", "error", "MAC", "order",
             "bias", "verdict");
  std::vector<std::string> untrusted;
  for (const auto& mode : check.modes) {
    const bool any = !mode.resolutions.empty();
    const auto& study = mode.study;
    fmt::print(
        "{:>12} {:>4} {:>6} {:>16} {:>16.10g} {:>10.2e} {:>10} {:>8} {:>8} {:>10}  {}\n",
        to_string(mode.plane), mode.mode, mode.reference_index,
        any ? fmt::format("{:.10g}", mode.resolutions.back().omega_rad_s / (2 * kPi)) : "-",
        mode.reference_omega_rad_s / (2 * kPi), mode.reference_relative_estimate,
        any ? fmt::format("{:.3e}", mode.resolutions.back().relative_error) : "-",
        any && mode.resolutions.back().mac ? fmt::format("{:.6f}", *mode.resolutions.back().mac)
                                           : "-",
        study_number(study, &ConvergenceStudy::observed_order, false),
        study_number(study, &ConvergenceStudy::bias_relative, true), to_string(mode.verdict));
    if (mode.pairing.find(';') != std::string::npos) fmt::print("{:>12} {}\n", "", mode.pairing);
    if (study && !study->trustworthy && (study->observed_order || study->bias_relative)) {
      untrusted.push_back(
          fmt::format("{} mode {}: {}", to_string(mode.plane), mode.mode, study->note));
    }
  }
  if (!untrusted.empty())
    fmt::print("? not trusted (the convergence study does not support it):\n");
  for (const auto& line : untrusted) fmt::print("  {}\n", line);
}

void print_tension_check(const TensionCheck& check) {
  const TensionReference& reference = check.reference;
  fmt::print("reference {}: {}\n", reference.solver, reference.reason);
  if (reference.cross_check_relative >= 0.0) {
    fmt::print("  shooting and fe agree to {:.2e} (largest difference / largest tension)\n",
               reference.cross_check_relative);
  }
  fmt::print("{}{}{}\n", to_string(check.quantity),
             check.period_s > 0.0 ? fmt::format(", period {:g} s", check.period_s) : "",
             check.resolution ? fmt::format(", finest resolution {:g}", *check.resolution) : "");
  fmt::print("{:>12} {:>14} {:>14} {:>10} {:>10} {:>11} {:>10} {:>10}  {}\n", "s [m]", "other [N]",
             "catena [N]", "catena +-", "other +-", "difference", "relative", "allowed", "status");
  for (const auto& c : check.stations) {
    fmt::print("{:>12.6g} {:>14.8g} {:>14.8g} {:>10.2e} {:>10.2e} {:>11.3e} {:>10} {:>10.2e}  {}\n",
               c.s_m, c.other_n, c.catena_n, c.catena_uncertainty_n, c.other_uncertainty_n,
               c.difference_n, c.relative_error ? fmt::format("{:.3e}", *c.relative_error) : "-",
               c.allowed_n, c.within ? "within" : "DISAGREES");
  }
  if (check.fairlead) {
    fmt::print("fairlead: other {:.8g} N, catena {:.8g} N, difference {:.3e} N ({})\n",
               check.fairlead->other_n, check.fairlead->catena_n, check.fairlead->difference_n,
               check.fairlead->within ? "within" : "disagrees");
  } else {
    fmt::print("fairlead: the file has no station at s = L\n");
  }
  for (const auto& s : check.studies) {
    fmt::print("study at {}: order {}, limit {} N, bias {}: {} ({})\n", s.label,
               s.study.observed_order ? fmt::format("{:.3f}", *s.study.observed_order) : "-",
               s.study.limit_omega_rad_s ? fmt::format("{:.8g}", *s.study.limit_omega_rad_s) : "-",
               s.study.bias_relative ? fmt::format("{:.3e}", *s.study.bias_relative) : "-",
               to_string(s.verdict), s.study.note);
  }
  fmt::print("largest difference / largest tension {:.3e}; verdict: {}\n",
             check.max_relative_difference, to_string(check.verdict));
}

ExternalCheckOptions check_options(const CheckArguments& arguments) {
  ExternalCheckOptions options;
  options.rtol = arguments.rtol;
  if (!(options.rtol > 0.0 && options.rtol < 1.0))
    throw InvalidInput(fmt::format("--rtol {}: must be in (0, 1)", options.rtol));
  return options;
}

// Another program's dynamic tension (docs/how-to/check-dynamic-tension.md).
int run_tension_check(const CheckArguments& arguments) {
  const ExternalCheckOptions options = check_options(arguments);
  if (!arguments.shapes.empty())
    throw InvalidInput("--shapes is for mode shapes; a tension file carries no shapes");
  if (!arguments.out.empty()) {
    throw InvalidInput(
        "--out writes the modal check report; for a tension file use --json (the report pages "
        "for tensions are not written yet)");
  }
  if (!arguments.json.empty()) check_output_file(arguments.json);
  const ExternalTension tension = read_external_tension(arguments.results);
  const Scene scene = read_one_scene(arguments.scene);
  const SceneTensionCheck checked = check_scene_tension(tension, scene, options);
  if (!checked.check) {
    fmt::print(stderr, "error: {}: {}\n", arguments.scene, checked.error);
    return 3;
  }
  if (!arguments.quiet) print_tension_check(*checked.check);
  if (!arguments.json.empty()) {
    write_tension_check_json(
        arguments.json, *checked.check,
        {scene.name, path_text(arguments.scene), path_text(arguments.results), ""});
  }
  return checked.check->any_failure() ? 1 : 0;
}

// Before any work: no output of this run may replace one of its inputs (`--json R`, a results
// file named check.md in --out).
void check_outputs_spare_inputs(const CheckArguments& arguments) {
  const std::vector<std::filesystem::path> inputs{arguments.results, arguments.shapes,
                                                  arguments.scene};
  if (!arguments.json.empty()) check_not_an_input(arguments.json, inputs, "--json");
  if (arguments.out.empty()) return;
  for (const char* name : {"check.md", "check.html"})
    check_not_an_input(std::filesystem::path(arguments.out) / name, inputs, "--out");
}

// The time-series check takes several files and its own options; the results checks one file and
// none of those options: each refuses the other's, naming the option.
int run_time_series_branch(const CheckArguments& arguments) {
  if (!arguments.shapes.empty() || !arguments.out.empty()) {
    throw InvalidInput(fmt::format("{} is a time series: --shapes and --out are for modal results",
                                   arguments.files.front()));
  }
  TimeSeriesArguments series = arguments.series;
  series.files = arguments.files;
  series.scene = arguments.scene;
  series.json = arguments.json;
  series.quiet = arguments.quiet;
  return run_timeseries_check(series);
}

void refuse_time_series_options(const CheckArguments& arguments) {
  const TimeSeriesArguments& s = arguments.series;
  const char* given = !s.channels.empty()      ? "--channel"
                      : !s.window.empty()      ? "--window"
                      : !s.plane.empty()       ? "--plane"
                      : !s.resolutions.empty() ? "--resolution"
                      : s.min_frequency_hz != 0.0 || s.max_frequency_hz != 0.0
                          ? "--min/max-frequency"
                          : nullptr;
  if (given) {
    throw InvalidInput(fmt::format(
        "{} is for a time series (a MoorDyn output file or a CSV with a time column); {} is a "
        "results file",
        given, arguments.files.front()));
  }
  if (arguments.files.size() != 1) {
    throw InvalidInput(fmt::format(
        "{} files given: a results file is checked alone (several files are runs of a time "
        "series; {} is not one)",
        arguments.files.size(), arguments.files.front()));
  }
}

int run_check(CheckArguments arguments) {
  if (looks_like_time_series(arguments.files.front())) return run_time_series_branch(arguments);
  refuse_time_series_options(arguments);
  arguments.results = arguments.files.front();
  check_outputs_spare_inputs(arguments);
  if (is_tension_results_file(arguments.results)) return run_tension_check(arguments);
  const ExternalCheckOptions options = check_options(arguments);
  if (!arguments.json.empty()) check_output_file(arguments.json);
  if (!arguments.out.empty()) check_output_directory(arguments.out);
  const std::vector<ExternalMode> results =
      read_external_results(arguments.results, arguments.shapes);
  const Scene scene = read_one_scene(arguments.scene);
  const SceneCheck checked = check_scene(results, scene, options);
  if (!checked.check) {
    fmt::print(stderr, "error: {}: {}\n", arguments.scene, checked.error);
    return 3;
  }
  const ExternalCheck& check = *checked.check;
  const CheckSources sources{scene.name, path_text(arguments.scene), path_text(arguments.results),
                             arguments.shapes.empty() ? "" : path_text(arguments.shapes)};
  if (!arguments.quiet) print_check(check);
  if (!arguments.json.empty()) write_check_json(arguments.json, check, sources);
  if (!arguments.out.empty()) {
    const CheckReportFiles files = write_check_report(check, sources, arguments.out);
    if (!arguments.quiet)
      fmt::print("wrote {} and {} ({} figures)\n", files.markdown.string(), files.html.string(),
                 files.figures);
  }
  return check.any_failure() ? 1 : 0;
}

// The options of the time-series check (docs/how-to/check-time-series.md).
void add_time_series_options(CLI::App& command, TimeSeriesArguments& series) {
  command
      .add_option(
          "--channel", series.channels,
          "Time series: a channel to identify, by its name in the file (repeat for several; the\n"
          "channels of one plane are identified together). A fairlead tension (FAIRTEN1, "
          "Seg<N>Te)\n"
          "sees the in-plane modes; node positions x, z (L1N5PX, Node5pz) the in-plane modes and "
          "y\n"
          "(L1N5PY) the out-of-plane modes, for a line in the x-z plane")
      ->allow_extra_args(false);
  command.add_option(
      "--window", series.window,
      "Time series: T0:T1 [s], the free decay: from the release (after any transient, e.g. a\n"
      "ramp or the first second after the release) to the end; either side may be empty\n"
      "(20: = from 20 s to the end). It must span two periods of Catena's lowest mode.\n"
      "Default: the whole record");
  command.add_option("--plane", series.plane,
                     "Time series: in-plane or out-of-plane, the plane every channel sees,\n"
                     "overriding the names (needed for CSV columns whose name does not say, or\n"
                     "a line that does not lie in the x-z plane)");
  command
      .add_option("--resolution", series.resolutions,
                  "Time series, several runs: each run's mesh count (e.g. MoorDyn's NumSegs;\n"
                  "larger = finer), one per file in order. Default: a line file's own\n"
                  "segment count (several: --resolution 20,40,80)")
      ->allow_extra_args(false)
      ->delimiter(',');
  command.add_option("--min-frequency", series.min_frequency_hz,
                     "Time series: identify modes above this frequency [Hz] (0: no bound)");
  command.add_option(
      "--max-frequency", series.max_frequency_hz,
      "Time series: identify modes below this frequency [Hz] (default: 1.5x Catena's\n"
      "6th mode of the channel's plane, at most 0.8 Nyquist)");
}

}  // namespace

void add_check_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<CheckArguments>();
  CLI::App* command = app.add_subcommand(
      "check",
      "Check another program's natural frequencies (and mode shapes) against Catena's certified\n"
      "reference for the same scene: shooting or Richardson-extrapolated fe, whichever converged\n"
      "with the smaller error estimate (docs/how-to/check.md).\n"
      "Per mode: the other value, Catena's value and estimate, the relative error and a verdict\n"
      "against --rtol; MAC when shapes are given; with three or more resolutions the observed "
      "order,\n"
      "the extrapolated limit and its bias (\"converged\", \"converges, not yet within "
      "tolerance\",\n"
      "\"converges to a wrong limit\").\n"
      "Exit 0 every mode within tolerance, 1 a mode beyond it (or converging to a wrong limit),\n"
      "2 bad input (the message names file, row and column), 3 no reference could be computed.\n"
      "A CSV with a tension_std_n or tension_amplitude_n column is another program's dynamic\n"
      "tension along the line for the scene's [request.motion]: per station the difference to\n"
      "Catena's, against rtol + both uncertainties (docs/how-to/check-dynamic-tension.md).\n"
      "A time series (a MoorDyn output file, or a CSV with a time column; told by content) is a\n"
      "free decay: the modes in --channel over --window are identified and compared with\n"
      "Catena's damped modes (docs/how-to/check-time-series.md); several files are runs at\n"
      "different resolutions (e.g. NumSegs), with a convergence study per mode.");
  command
      ->add_option(
          "files", arguments->files,
          "The other program's results: CSV with a header row, columns plane (in-plane,\n"
          "inplane, out-of-plane, outofplane; any case), mode (1-based within its plane),\n"
          "frequency_hz [Hz] or omega_rad_s [rad/s], optional resolution (mesh count, e.g.\n"
          "number of segments: larger = finer); or a .json file with the same fields and\n"
          "optional shapes (docs/how-to/check.md); or a CSV of dynamic tension along the\n"
          "line: s_m (or node with nodes), tension_std_n or tension_amplitude_n, optional\n"
          "period_s, resolution, tension_uncertainty_n (docs/how-to/check-dynamic-tension.md);\n"
          "or time series of a free decay: MoorDyn output files (<deck>.out, Line<k>.out) or\n"
          "CSV with a time column, one file per run (docs/how-to/check-time-series.md)")
      ->required()
      ->check(non_empty_path());
  command
      ->add_option("--scene", arguments->scene,
                   "The scene the other program solved (TOML, docs/reference/scene-format.md)")
      ->required()
      ->check(non_empty_path());
  command->add_option(
      "--shapes", arguments->shapes,
      "Mode shapes of CSV results, long format, one row per station: plane, mode,\n"
      "[resolution], station_s_m (unstretched arc length from end A [m]), and any of u, w\n"
      "(in-plane tangential and normal), v (out-of-plane) [any scale], tension_n [N]");
  command->add_option("--rtol", arguments->rtol, "Relative tolerance on frequencies")
      ->capture_default_str();
  command
      ->add_option("--json", arguments->json,
                   std::string("Write every number of the comparison as JSON to this file.") +
                       kOutputPathHelp)
      ->check(non_empty_path());
  command
      ->add_option(
          "--out", arguments->out,
          "Write check.md, check.html (self-contained) and figures/*.svg (one convergence\n"
          "plot per mode with two or more resolutions) to this directory (created when the\n"
          "check is written; nothing is created when the inputs are refused)")
      ->check(non_empty_path());
  command->add_flag("--quiet,-q", arguments->quiet, "Print nothing but errors");
  add_time_series_options(*command, arguments->series);
  command->callback([arguments, &run] { run = [arguments] { return run_check(*arguments); }; });
}

}  // namespace catena::cli
