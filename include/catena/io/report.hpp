// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The comparison report (`catena report`): from the results JSON of `catena verify`
/// (report.json), a Markdown report, a self-contained HTML report (figures embedded), and CSV data
/// (frequencies, published comparisons, checks). Figures are drawn by figures.py (matplotlib) from
/// the same JSON, run without a shell; the script, the published tables it overlays and the
/// benchmark baselines are read from the data dir (installed share/catena, found from the
/// executable; the build tree's otherwise). When Python or matplotlib is missing the report says
/// so and is written without figures.

#include <filesystem>
#include <string>

namespace catena {

struct ReportOptions {
  /// Directory for report.md, report.html, data/*.csv and figures/*.png.
  std::filesystem::path out_dir = "build/report";
  /// The data dir: figures.py, results_keys.py, reference/published/*.csv and
  /// the copy of benchmarks/results/time-vs-error.csv. Empty: found from the executable (see the
  /// file comment).
  std::filesystem::path data_dir;
  /// Directory of figures.py when it is not the data dir's (e.g. a source tree's
  /// verification/tools). Empty: the data dir.
  std::filesystem::path tools_dir;
  /// Draw figures (needs python3 with matplotlib).
  bool figures = true;
  /// Python interpreter for the figures (searched on PATH when it has no '/').
  std::string python = "python3";
};

/// What was written, for the CLI to print.
struct ReportFiles {
  std::filesystem::path markdown;
  std::filesystem::path html;
  std::filesystem::path data_dir;
  int figures = 0;
  /// Rows of the source-discrepancy table (one per published entry judged SOURCE).
  int discrepancy_rows = 0;
  /// Empty when figures were drawn; otherwise why not.
  std::string figures_note;
};

/// Writes the report from `results_json` (a file written by write_results_json). Throws
/// ParseError when the JSON cannot be read, InvalidInput when files cannot be written.
ReportFiles write_report(const std::filesystem::path& results_json, const ReportOptions& options);

}  // namespace catena
