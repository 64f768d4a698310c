// SPDX-License-Identifier: MIT
// The Markdown and HTML report of `catena check` (docs/how-to/check.md, "Report"), built with the
// report's document model (io/report/document.hpp) and the library's own SVG plots.
#include "catena/io/check_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "catena/core/version.hpp"
#include "catena/io/file_access.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "io/report/document.hpp"
#include "io/report/svg_plot.hpp"

namespace catena {
namespace {

using internal::Document;

constexpr double kRadPerSecondToHz = 1.0 / (2.0 * kPi);

std::string hz(double omega_rad_s) {
  return fmt::format("{:.10g}", omega_rad_s * kRadPerSecondToHz);
}
std::string sci(double value) { return fmt::format("{:.3e}", value); }
template <class T>
std::string maybe(const std::optional<T>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : std::string("-");
}
std::string estimate(double value) { return value < 0.0 ? std::string("none") : sci(value); }
std::string resolution_text(const std::optional<double>& resolution) {
  return maybe(resolution, "{:g}");
}

void add_header(Document& out, const ExternalCheck& check, const CheckSources& sources) {
  int failed = 0;
  for (const auto& mode : check.modes) failed += is_failure(mode.verdict) ? 1 : 0;
  out.push_back(internal::Heading{1, "Catena check: " + sources.results_file, "check"});
  out.push_back(internal::Paragraph{
      fmt::format("{} · {} · scene {} ({}){} · rtol {:g} · {} modes compared, {} beyond tolerance "
                  "or converging to a wrong "
                  "limit.",
                  provenance(), utc_timestamp(), sources.scene_name, sources.scene_file,
                  sources.shapes_file.empty() ? "" : " · shapes " + sources.shapes_file,
                  check.options.rtol, check.modes.size(), failed)});
}

void add_references(Document& out, const ExternalCheck& check) {
  out.push_back(internal::Heading{2, "Catena's reference", "reference"});
  // The cross-check column compares the solvers that may certify a reference (shooting vs fe).
  internal::Table table{{"plane", "solver", "modes", "largest estimate",
                         fmt::format("{}", fmt::join(reference_solvers(), " vs ")), "why"},
                        {},
                        "reference"};
  for (const auto& reference : check.references) {
    double largest = 0.0;
    for (const auto& mode : reference.modes)
      largest = std::max(largest, mode.relative_error_estimate);
    table.rows.push_back(
        {to_string(reference.plane), reference.solver, std::to_string(reference.modes.size()),
         sci(largest),
         reference.cross_check_relative < 0.0 ? "-" : sci(reference.cross_check_relative),
         reference.reason});
  }
  internal::add_table_or_none(out, std::move(table));
}

void add_mode_table(Document& out, const ExternalCheck& check) {
  out.push_back(internal::Heading{2, "Modes", "modes"});
  out.push_back(
      internal::Paragraph{"Other: the other program's finest result. Error: (other - Catena) / "
                          "Catena. Order, limit and bias: the "
                          "convergence study (three or more resolutions; docs/how-to/check.md). "
                          "Verdicts are defined in docs/how-to/check.md."});
  internal::Table table{
      {"plane", "mode", "Catena mode", "pairing", "other f [Hz]", "Catena f [Hz]",
       "Catena estimate", "error", "MAC", "order", "limit f [Hz]", "bias", "verdict"},
      {},
      "modes"};
  for (const auto& mode : check.modes) {
    if (mode.resolutions.empty()) {
      table.rows.push_back({to_string(mode.plane), std::to_string(mode.mode), "-", mode.pairing,
                            "-", "-", "-", "-", "-", "-", "-", "-", to_string(mode.verdict)});
      continue;
    }
    const auto& finest = mode.resolutions.back();
    const auto& study = mode.study;
    table.rows.push_back(
        {to_string(mode.plane), std::to_string(mode.mode), std::to_string(mode.reference_index),
         mode.pairing, hz(finest.omega_rad_s), hz(mode.reference_omega_rad_s),
         estimate(mode.reference_relative_estimate), sci(finest.relative_error),
         maybe(finest.mac, "{:.6f}"), study ? maybe(study->observed_order, "{:.3f}") : "-",
         study && study->limit_omega_rad_s ? hz(*study->limit_omega_rad_s) : "-",
         study ? maybe(study->bias_relative, "{:.3e}") : "-", to_string(mode.verdict)});
  }
  internal::add_table_or_none(out, std::move(table));
}

internal::LogLogPlot convergence_plot(const ModeComparison& mode, double rtol) {
  internal::LogLogPlot plot;
  plot.title =
      fmt::format("{} mode {}: {}", to_string(mode.plane), mode.mode, to_string(mode.verdict));
  plot.x_label = "resolution (the other program's mesh count)";
  plot.y_label = "|relative error| against Catena";
  internal::LogLogPlot::Series series{"other program", {}, {}};
  for (const auto& r : mode.resolutions) {
    series.x.push_back(r.resolution.value_or(0.0));
    // An exact match has no logarithm: drawn at the floor of double precision.
    series.y.push_back(std::max(std::abs(r.relative_error), 1e-16));
  }
  plot.series.push_back(series);
  plot.levels.push_back({fmt::format("rtol {:g}", rtol), rtol, "#d62728"});
  if (mode.study && mode.study->bias_relative) {
    plot.levels.push_back(
        {fmt::format("|bias of limit| {:.2e}", std::abs(*mode.study->bias_relative)),
         std::max(std::abs(*mode.study->bias_relative), 1e-16), "#9467bd"});
  }
  if (mode.reference_relative_estimate > 0.0) {
    plot.band_top = mode.reference_relative_estimate;
    plot.band_label = "Catena's estimate";
  }
  return plot;
}

void add_convergence(Document& out,
                     const ExternalCheck& check,
                     const std::filesystem::path& out_dir,
                     int& figures) {
  out.push_back(internal::Heading{2, "Convergence", "convergence"});
  bool any = false;
  for (const auto& mode : check.modes) {
    if (mode.resolutions.size() < 2 || !mode.resolutions.front().resolution) continue;
    any = true;
    const std::string name = fmt::format(
        "{}-mode-{}", mode.plane == Plane::InPlane ? "inplane" : "outofplane", mode.mode);
    out.push_back(
        internal::Heading{3, fmt::format("{} mode {}", to_string(mode.plane), mode.mode), name});
    internal::Table table{
        {"resolution", "other f [Hz]", "error", "MAC", "tension difference"}, {}, "convergence"};
    for (const auto& r : mode.resolutions) {
      table.rows.push_back({resolution_text(r.resolution), hz(r.omega_rad_s), sci(r.relative_error),
                            maybe(r.mac, "{:.6f}"), maybe(r.tension_relative, "{:.3e}")});
    }
    internal::add_table_or_none(out, std::move(table));
    if (mode.study) out.push_back(internal::Paragraph{"Study: " + mode.study->note + "."});
    const std::filesystem::path file = out_dir / "figures" / (name + ".svg");
    write_file_atomically(file, internal::render_svg(convergence_plot(mode, check.options.rtol)));
    out.push_back(internal::Image{
        file, fmt::format("{} mode {}: the other program's error against its resolution",
                          to_string(mode.plane), mode.mode)});
    ++figures;
  }
  if (!any) out.push_back(internal::Paragraph{"No mode has results at two or more resolutions."});
}

}  // namespace

CheckReportFiles write_check_report(const ExternalCheck& check,
                                    const CheckSources& sources,
                                    const std::filesystem::path& out_dir) {
  check_output_directory(out_dir);
  CheckReportFiles files;
  Document report;
  add_header(report, check, sources);
  add_references(report, check);
  add_mode_table(report, check);
  add_convergence(report, check, out_dir, files.figures);
  files.markdown = out_dir / "check.md";
  files.html = out_dir / "check.html";
  write_file_atomically(files.markdown, internal::render_markdown(report, out_dir));
  write_file_atomically(files.html,
                        internal::render_html(report, "Catena check: " + sources.results_file));
  return files;
}

}  // namespace catena
