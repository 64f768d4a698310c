// SPDX-License-Identifier: MIT
#pragma once
// `catena check FILE... --scene S --channel NAME`: a free decay from another program against
// Catena's damped modes (docs/how-to/check-time-series.md). Called by check_command.cpp when the
// first file is a time series.

#include <string>
#include <vector>

namespace catena::cli {

struct TimeSeriesArguments {
  std::vector<std::string> files;
  std::string scene;
  std::string json;
  std::vector<std::string> channels;
  std::string window;  // "T0:T1", either side may be empty
  std::string plane;   // "" (from the names), "in-plane" or "out-of-plane"
  std::vector<double> resolutions;
  double min_frequency_hz = 0.0;
  double max_frequency_hz = 0.0;
  bool quiet = false;
};

/// Runs the check; returns the exit code (0 every compared mode agrees, 1 a disagreement, an
/// unmatched mode, a wrong limit or nothing verified, 3 no reference). Throws InvalidInput (exit
/// 2) for bad input.
int run_timeseries_check(const TimeSeriesArguments& arguments);

}  // namespace catena::cli
