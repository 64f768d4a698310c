// SPDX-License-Identifier: MIT
#include <fmt/format.h>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/report.hpp"
#include "io/internal/check_table.hpp"
#include "io/internal/data_dir.hpp"
#include "io/internal/json_strict.hpp"
#include "io/report/figures.hpp"
#include "io/report/results_layout.hpp"
#include "io/report/sections.hpp"

namespace catena {
namespace {

using internal::json;

json read_results(const std::filesystem::path& results_json) {
  // The suite's report.json is about 10 MB (far more with shapes asked); a regular file is required
  // (not a FIFO or device).
  constexpr std::uintmax_t kMaxResultsBytes = std::uintmax_t(4) << 30;
  // A results JSON is about 8 levels deep (scenes, a scene, solvers, a solver, a plane, modes, a
  // mode, its shape): deeper is not one, and the report's walks are recursive.
  constexpr int kMaxDepth = 64;
  const std::string file = path_text(results_json);
  json document = internal::parse_json_strict(
      read_input_file(results_json, "results JSON", kMaxResultsBytes), file, kMaxDepth);
  if (!document.is_object() || !document.contains(internal::key::scenes))
    throw ParseError(fmt::format("{}: not a catena results JSON (no \"scenes\")", file));
  try {
    internal::expand_check_tables(document);  // the report reads checks as records
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(fmt::format("{}: malformed check table: {}", file, e.what()));
  }
  internal::check_results_layout(document, file);
  return document;
}

// The data dir given, else the one found from the executable (empty when none).
std::filesystem::path resolve_data_dir(const ReportOptions& options) {
  if (!options.data_dir.empty()) return options.data_dir;
  return internal::data_dir().value_or(std::filesystem::path());
}

void add_figures(internal::Document& out,
                 const std::filesystem::path& results_json,
                 const ReportOptions& options,
                 ReportFiles& files) {
  std::vector<internal::Image> images;
  const std::filesystem::path data = resolve_data_dir(options);
  if (!options.figures) {
    files.figures_note = "figures not drawn (--no-figures)";
  } else if (data.empty() && options.tools_dir.empty()) {
    files.figures_note =
        "figures not drawn: no data dir (share/catena) found next to the executable";
  } else {
    const internal::FigureInputs inputs{
        (options.tools_dir.empty() ? data : options.tools_dir) / "figures.py",
        data / "reference" / "published", data / "benchmarks" / "time-vs-error.csv",
        options.python};
    images = internal::draw_figures(results_json, inputs, options.out_dir / "figures",
                                    files.figures_note);
  }
  files.figures = static_cast<int>(images.size());
  out.push_back(internal::Heading{2, "Figures", "figures"});
  if (!files.figures_note.empty()) out.push_back(internal::Paragraph{files.figures_note});
  for (const auto& image : images) out.push_back(image);
}

}  // namespace

namespace {

// write_report once the document is read and its layout checked.
ReportFiles write_report_from(const std::filesystem::path& results_json,
                              const json& document,
                              const ReportOptions& options) {
  check_output_directory(options.out_dir);
  ReportFiles files;
  files.data_dir = options.out_dir / "data";
  internal::write_data_tables(document, files.data_dir);

  internal::Document report;
  internal::add_summary(report, document);
  internal::add_headline(report, document);
  internal::add_solvers(report, document);
  files.discrepancy_rows = internal::add_discrepancies(report, document);
  internal::add_failures(report, document);
  internal::add_stress_outcomes(report, document);
  internal::add_mutation(report, document);
  internal::add_model_error(report, document, files.data_dir);
  const std::filesystem::path data = resolve_data_dir(options);
  if (!data.empty()) {
    internal::add_time_to_accuracy(
        report, internal::read_time_to_accuracy(data / "benchmarks" / "time-vs-error.csv"));
  }
  add_figures(report, results_json, options, files);
  internal::add_scenes(report, document);

  files.markdown = options.out_dir / "report.md";
  files.html = options.out_dir / "report.html";
  write_file_atomically(files.markdown, internal::render_markdown(report, options.out_dir));
  write_file_atomically(files.html, internal::render_html(report, "Catena verification report"));
  return files;
}

}  // namespace

ReportFiles write_report(const std::filesystem::path& results_json, const ReportOptions& options) {
  const json document = read_results(results_json);
  try {
    return write_report_from(results_json, document, options);
  } catch (const nlohmann::json::exception& e) {
    // check_results_layout checks what the report reads without asking; a value of another type
    // than the one it is read as still ends here, as bad input rather than an internal error.
    throw ParseError(
        fmt::format("{}: a value of the wrong type ({}; not the layout `catena verify` "
                    "writes)",
                    path_text(results_json), e.what()));
  }
}

}  // namespace catena
