// SPDX-License-Identifier: MIT
#pragma once
// The report's figures: figures.py (matplotlib) run on the results JSON through run_process (no
// shell), its index.json read back.

#include <filesystem>
#include <string>
#include <vector>

#include "io/report/document.hpp"

namespace catena::internal {

/// Where figures.py and its inputs are.
struct FigureInputs {
  std::filesystem::path script;         ///< figures.py
  std::filesystem::path published_dir;  ///< transcribed published tables (CSV)
  std::filesystem::path time_vs_error;  ///< benchmark baseline (CSV)
  std::string python;                   ///< interpreter
};

/// Runs the script into `figures_dir`; returns the images it drew in report order, or none with
/// `note` saying why (script missing, interpreter failed, no index).
std::vector<Image> draw_figures(const std::filesystem::path& results_json,
                                const FigureInputs& inputs,
                                const std::filesystem::path& figures_dir,
                                std::string& note);

}  // namespace catena::internal
