#pragma once
/// \file
/// The comparison report (`catena report`): from the results JSON of `catena verify`
/// (report.json), a Markdown report, a self-contained HTML report (figures embedded), and CSV data
/// (frequencies, published comparisons, checks). Figures are drawn by
/// verification/tools/figures.py (matplotlib) from the same JSON; when Python or matplotlib is
/// missing the report says so and is written without them.

#include <filesystem>
#include <string>

namespace catena {

struct ReportOptions {
  /// Directory for report.md, report.html, data/*.csv and figures/*.png.
  std::filesystem::path out_dir = "build/report";
  /// Directory holding figures.py and the published tables' folder (../reference/published).
  std::filesystem::path tools_dir;
  /// Draw figures (needs python3 with matplotlib).
  bool figures = true;
  /// Python interpreter for the figures.
  std::string python = "python3";
};

/// What was written, for the CLI to print.
struct ReportFiles {
  std::filesystem::path markdown;
  std::filesystem::path html;
  std::filesystem::path data_dir;
  int figures = 0;
  /// Empty when figures were drawn; otherwise why not.
  std::string figures_note;
};

/// Writes the report from `results_json` (a file written by write_results_json). Throws
/// ParseError when the JSON cannot be read, Error when files cannot be written.
ReportFiles write_report(const std::filesystem::path& results_json, const ReportOptions& options);

}  // namespace catena
