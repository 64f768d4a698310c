// SPDX-License-Identifier: MIT
// `catena check` on a free decay: read the runs, check, print the table, write the JSON
// (docs/how-to/check-time-series.md).
#include "cli/check_timeseries.hpp"

#include <fmt/format.h>

#include <charconv>
#include <filesystem>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/timeseries_check_json.hpp"
#include "catena/io/timeseries_reader.hpp"
#include "catena/verification/timeseries_check.hpp"

namespace catena::cli {
namespace {

std::optional<double> window_side(const std::string& text, const std::string& window) {
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    throw InvalidInput(fmt::format(
        "--window {}: '{}' is not a time in seconds (give T0:T1, e.g. 20:600, or 20: for "
        "the rest of the record)",
        window, text));
  }
  return value;
}

TimeSeriesCheckOptions check_options(const TimeSeriesArguments& arguments,
                                     const TimeSeries& first) {
  TimeSeriesCheckOptions options;
  options.channels = arguments.channels;
  if (options.channels.empty()) {
    std::string names;
    for (std::size_t i = 0; i < std::min<std::size_t>(first.names.size(), 8); ++i)
      names += (i ? ", " : "") + first.names[i];
    throw InvalidInput(fmt::format(
        "--channel: which channel to identify? {} has {} channels: {}{} (e.g. a fairlead tension, "
        "FAIRTEN1, or node positions)",
        first.source, first.names.size(), names, first.names.size() > 8 ? ", ..." : ""));
  }
  if (!arguments.window.empty()) {
    const auto colon = arguments.window.find(':');
    if (colon == std::string::npos) {
      throw InvalidInput(
          fmt::format("--window {}: give T0:T1 in seconds (e.g. 20:600)", arguments.window));
    }
    options.window_start_s = window_side(arguments.window.substr(0, colon), arguments.window);
    options.window_end_s = window_side(arguments.window.substr(colon + 1), arguments.window);
  }
  if (arguments.plane == "in-plane" || arguments.plane == "inplane") {
    options.plane = Plane::InPlane;
  } else if (arguments.plane == "out-of-plane" || arguments.plane == "outofplane") {
    options.plane = Plane::OutOfPlane;
  } else if (!arguments.plane.empty()) {
    throw InvalidInput(
        fmt::format("--plane {}: must be in-plane or out-of-plane", arguments.plane));
  }
  options.resolutions = arguments.resolutions;
  options.min_frequency_hz = arguments.min_frequency_hz;
  options.max_frequency_hz = arguments.max_frequency_hz;
  return options;
}

std::string plus_minus(double value, double uncertainty, bool scientific) {
  return scientific ? fmt::format("{:.4e} ± {:.1e}", value, uncertainty)
                    : fmt::format("{:.7g} ± {:.1e}", value, uncertainty);
}

void print_check(const TimeSeriesCheck& check) {
  for (const auto& p : check.planes) {
    fmt::print("{}: channels {}; {}; model order {}, noise rms {:.3g}, step {:g} s\n", p.plane,
               fmt::join(p.channels, ", "), p.method, p.model_order, p.noise_rms,
               p.sample_interval_s);
    fmt::print("  reference {}{}\n", p.reference_solver,
               p.cross_check_relative >= 0.0
                   ? fmt::format(" (shooting and fe agree to {:.1e})", p.cross_check_relative)
                   : "");
  }
  fmt::print("window {:g}:{:g} s{}\n", check.window_start_s, check.window_end_s,
             check.runs > 1 ? fmt::format(", {} runs", check.runs) : "");
  fmt::print("{:>12} {:>4} {:>26} {:>22} {:>16} {:>10}  {}\n", "plane", "mode",
             "identified f [Hz] ± U", "zeta ± U", "catena f [Hz]", "catena zeta", "verdict");
  for (const auto& m : check.modes) {
    fmt::print("{:>12} {:>4} {:>26} {:>22} {:>16} {:>10}  {}\n", m.plane,
               m.mode > 0 ? std::to_string(m.mode) : "-",
               plus_minus(m.identified_frequency_hz, m.frequency_uncertainty_hz, false),
               plus_minus(m.identified_damping_ratio, m.damping_ratio_uncertainty, true),
               m.mode > 0 ? fmt::format("{:.10g}", m.catena_frequency_hz) : "-",
               m.mode > 0 ? fmt::format("{:.3e}", m.catena_damping_ratio) : "-", m.verdict);
    if (m.verdict != "agrees" && !m.note.empty()) fmt::print("{:>17} {}\n", "", m.note);
    if (m.study) {
      const auto& s = *m.study;
      fmt::print("{:>17} study over resolutions {}: order {}, bias {}: {} ({})\n", "",
                 fmt::join(s.resolutions, ", "),
                 s.study.observed_order ? fmt::format("{:.3f}", *s.study.observed_order) : "-",
                 s.study.bias_relative ? fmt::format("{:.3e}", *s.study.bias_relative) : "-",
                 s.verdict, s.study.note);
    }
  }
  for (const auto& m : check.not_present) {
    fmt::print("not present in the record: {} mode {} ({:.8g} Hz, zeta {:.3e})\n", m.plane, m.mode,
               m.catena_frequency_hz, m.catena_damping_ratio);
  }
  for (const auto& note : check.notes) fmt::print("note: {}\n", note);
  fmt::print("{} agree, {} disagree, {} not identifiable, {} unmatched\n", check.agrees,
             check.disagrees, check.not_identifiable, check.unmatched);
}

}  // namespace

int run_timeseries_check(const TimeSeriesArguments& arguments) {
  if (!arguments.json.empty()) {
    std::vector<std::filesystem::path> inputs(arguments.files.begin(), arguments.files.end());
    inputs.emplace_back(arguments.scene);
    check_not_an_input(arguments.json, inputs, "--json");
    check_output_file(arguments.json);
  }
  std::vector<TimeSeries> runs;
  for (const auto& file : arguments.files) runs.push_back(read_time_series(file));
  const TimeSeriesCheckOptions options = check_options(arguments, runs.front());
  std::vector<Scene> scenes = read_scene_file(arguments.scene);
  if (scenes.size() != 1) {
    throw InvalidInput(fmt::format("{}: a sweep of {} scenes; catena check takes one scene",
                                   arguments.scene, scenes.size()));
  }
  const TimeSeriesCheck check = check_time_series_runs(scenes.front(), runs, options);
  if (!check.error.empty()) {
    fmt::print(stderr, "error: {}: {}\n", arguments.scene, check.error);
    return 3;
  }
  if (!arguments.quiet) print_check(check);
  if (!arguments.json.empty()) {
    TimeSeriesSources sources{
        scenes.front().name, path_text(arguments.scene), {}, arguments.channels};
    for (const auto& file : arguments.files) sources.files.push_back(path_text(file));
    write_timeseries_check_json(arguments.json, check, sources);
  }
  return check.any_failure() ? 1 : 0;
}

}  // namespace catena::cli
