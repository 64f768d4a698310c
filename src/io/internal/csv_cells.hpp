// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The cells of one CSV table of another program's results, read so that every message names the
/// file, the row (with its line) and the column: shared by the frequency and the tension readers
/// of `catena check` (external_results_reader.cpp, external_tension_reader.cpp).

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "catena/core/error.hpp"
#include "catena/io/csv_table.hpp"

namespace catena::internal {

struct CsvCells {
  const CsvTable& table;
  std::string file;

  std::string row_name(std::size_t row) const {
    return table.row_lines.empty()
               ? fmt::format("{} row {}", file, row + 1)
               : fmt::format("{} row {} (line {})", file, row + 1, table.row_lines.at(row));
  }
  std::string where(std::size_t row, const std::string& column) const {
    return fmt::format("{}, column '{}'", row_name(row), column);
  }
  bool has(const std::string& column) const {
    return std::find(table.columns.begin(), table.columns.end(), column) != table.columns.end();
  }
  // nullopt for an absent column or an empty cell; InvalidInput for anything but a finite number
  // (NaN and infinities included).
  std::optional<double> number(std::size_t row, const std::string& column) const {
    if (!has(column)) return std::nullopt;
    const std::string& cell = table.text(row, column);
    if (cell.empty()) return std::nullopt;
    double value = 0.0;
    const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    if (error != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value))
      throw InvalidInput(fmt::format("{}: '{}' is not a finite number", where(row, column), cell));
    return value;
  }
  double required(std::size_t row, const std::string& column) const {
    const auto value = number(row, column);
    if (!value) throw InvalidInput(fmt::format("{}: empty", where(row, column)));
    return *value;
  }
};

}  // namespace catena::internal
