// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The output of `catena check` (docs/how-to/check.md): the comparison as JSON (every number: per
/// mode the other program's values, Catena's value and estimate, relative errors, MAC, the observed
/// order, the extrapolated limit and its bias), and a report in Markdown and self-contained HTML
/// with one convergence plot per mode (SVG: the other program's |relative error| against its
/// resolution, log-log, with Catena's own error estimate as a band and --rtol as a line). Files are
/// written whole or not at all (catena/io/file_access.hpp).

#include <filesystem>
#include <string>

#include "catena/verification/external_check.hpp"

namespace catena {

/// Where the comparison came from, for the provenance lines.
struct CheckSources {
  std::string scene_name;
  std::string scene_file;
  std::string results_file;
  std::string shapes_file;  ///< empty when none
};

/// The comparison as a JSON document (layout in docs/how-to/check.md, "JSON"); no NaN (null
/// instead).
std::string check_to_json(const ExternalCheck& check, const CheckSources& sources);

/// Writes check_to_json to `path` atomically; InvalidInput naming the path when it cannot.
void write_check_json(const std::filesystem::path& path,
                      const ExternalCheck& check,
                      const CheckSources& sources);

/// What write_check_report wrote.
struct CheckReportFiles {
  std::filesystem::path markdown;
  std::filesystem::path html;
  int figures = 0;
};

/// Writes `out_dir`/check.md, check.html and figures/<plane>-mode-<k>.svg (one per mode with two
/// or more resolutions). InvalidInput naming the path when a file cannot be written.
CheckReportFiles write_check_report(const ExternalCheck& check,
                                    const CheckSources& sources,
                                    const std::filesystem::path& out_dir);

}  // namespace catena
