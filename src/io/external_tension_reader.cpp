// SPDX-License-Identifier: MIT
// Another program's dynamic tension along a line for `catena check`: CSV, checked cell by cell so
// that every message names the file, the row and the column (docs/how-to/check-dynamic-tension.md).
#include "catena/io/external_tension_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/csv_cells.hpp"

namespace catena {
namespace {

const std::vector<std::string> kColumns = {"s_m",
                                           "node",
                                           "nodes",
                                           "tension_std_n",
                                           "tension_amplitude_n",
                                           "period_s",
                                           "resolution",
                                           "tension_uncertainty_n"};
// The largest node count taken as a whole number: no line has a billion segments.
constexpr double kMostNodes = 1e9;

// The tension table's cells: the shared ones and whole numbers (node, nodes).
struct Cells : internal::CsvCells {
  int whole(std::size_t row, const std::string& column) const {
    const double value = required(row, column);
    if (value != std::floor(value) || std::abs(value) > kMostNodes)
      throw InvalidInput(fmt::format("{}: {} is not a whole number", where(row, column), value));
    return static_cast<int>(value);
  }
};

void check_header(const Cells& cells) {
  for (const auto& column : cells.table.columns) {
    if (std::find(kColumns.begin(), kColumns.end(), column) == kColumns.end()) {
      std::string accepted;
      for (const auto& c : kColumns) accepted += (accepted.empty() ? "" : ", ") + c;
      throw InvalidInput(fmt::format("{}: header: unknown column '{}' (accepted: {})", cells.file,
                                     column, accepted));
    }
  }
  const auto header = [&](const std::string& what) {
    return InvalidInput(fmt::format("{}: header: {}", cells.file, what));
  };
  if (cells.has("s_m") && cells.has("node"))
    throw header("columns 's_m' and 'node' both given: give one (node with nodes)");
  if (!cells.has("s_m") && !cells.has("node"))
    throw header("missing column 's_m' (or 'node' with 'nodes')");
  if (cells.has("node") && !cells.has("nodes"))
    throw header("column 'node' without column 'nodes' (s = node L / (nodes - 1))");
  if (cells.has("nodes") && !cells.has("node"))
    throw header("column 'nodes' without column 'node'");
  const bool std_n = cells.has("tension_std_n");
  if (std_n == cells.has("tension_amplitude_n"))
    throw header(std_n ? "columns 'tension_std_n' and 'tension_amplitude_n' both given: give one"
                       : "missing column 'tension_std_n' or 'tension_amplitude_n'");
  if (std_n && cells.has("period_s"))
    throw header("column 'period_s' with 'tension_std_n': an irregular motion has no period");
  if (cells.table.rows.empty()) throw InvalidInput(fmt::format("{}: no data rows", cells.file));
}

ExternalTensionStation read_row(const Cells& cells, std::size_t row, const std::string& tension) {
  ExternalTensionStation station;
  station.origin = cells.row_name(row);
  if (cells.has("s_m")) {
    station.s_m = cells.required(row, "s_m");
  } else {
    station.node = cells.whole(row, "node");
    station.nodes = cells.whole(row, "nodes");
  }
  station.tension_n = cells.required(row, tension);
  if (station.tension_n < 0.0) {
    throw InvalidInput(
        fmt::format("{}: {} must be >= 0 [N]", cells.where(row, tension), station.tension_n));
  }
  station.resolution = cells.number(row, "resolution");
  station.uncertainty_n = cells.number(row, "tension_uncertainty_n");
  return station;
}

}  // namespace

bool is_tension_results_file(const std::filesystem::path& path) {
  if (path.extension() == ".json") return false;
  try {
    const CsvTable table = read_csv_table(path);
    const auto has = [&](const char* c) {
      return std::find(table.columns.begin(), table.columns.end(), c) != table.columns.end();
    };
    return has("tension_std_n") || has("tension_amplitude_n");
  } catch (const Error&) {
    return false;
  }
}

ExternalTension external_tension_from_table(const CsvTable& table, const std::string& file) {
  const Cells cells{{table, file}};
  check_header(cells);
  ExternalTension tension;
  tension.origin = file;
  tension.quantity =
      cells.has("tension_std_n") ? TensionQuantity::StandardDeviation : TensionQuantity::Amplitude;
  const std::string column = to_string(tension.quantity);
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    tension.stations.push_back(read_row(cells, row, column));
    if (!cells.has("period_s")) continue;
    const double period = cells.required(row, "period_s");
    if (!(period > 0.0))
      throw InvalidInput(
          fmt::format("{}: {} must be > 0 [s]", cells.where(row, "period_s"), period));
    if (tension.period_s && period != *tension.period_s) {
      throw InvalidInput(
          fmt::format("{}: {} s differs from row 1's {} s: one file holds one excitation",
                      cells.where(row, "period_s"), period, *tension.period_s));
    }
    tension.period_s = period;
  }
  return tension;
}

ExternalTension read_external_tension(const std::filesystem::path& path) {
  return external_tension_from_table(read_csv_table(path), path_text(path));
}

}  // namespace catena
