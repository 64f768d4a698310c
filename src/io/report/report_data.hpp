// SPDX-License-Identifier: MIT
#pragma once
// The report's inputs and CSV outputs: the results JSON read back (by the key names of
// io/results_keys.txt), the data/*.csv tables written beside the report, and the benchmark
// baseline of time against error.

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/internal/results_keys.hpp"

namespace catena::internal {

using nlohmann::json;

/// `value` as a number in `format` ("{:.6g}"), or "-" when null or not a number.
std::string number_text(const json& value, const char* format = "{:.6g}");
/// object[key] by reference (json::value() would copy), or an empty array.
const json& list_or_empty(const json& object, const char* key);
/// A mode's frequency in `unit` ("gale", "kL/pi", "Hz", else rad/s), null when it has none.
json mode_value(const json& mode, const std::string& unit);
/// True when the scene carries `tag`.
bool has_tag(const json& scene, const std::string& tag);

/// Writes frequencies.csv, checks.csv and published.csv under `dir`.
void write_data_tables(const json& document, const std::filesystem::path& dir);

/// Fastest wall time [s] for each case, solver and error target (1e-3, 1e-6, 1e-9), from
/// the data dir's copy of benchmarks/results/time-vs-error.csv; cases in file order.
struct TimeToAccuracy {
  /// The file's first comment line: what is timed and the reference of the error.
  std::string description;
  std::vector<std::string> cases;
  std::map<std::string, std::map<std::string, std::map<double, double>>> best_time_s;
};
/// Empty when the file is absent; ParseError when it is malformed.
TimeToAccuracy read_time_to_accuracy(const std::filesystem::path& csv);
inline constexpr double kAccuracyTargets[] = {1e-3, 1e-6, 1e-9};

}  // namespace catena::internal
