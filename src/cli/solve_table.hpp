// SPDX-License-Identifier: MIT
#pragma once
// The layout of `catena solve`'s tables: a row per mode (or forcing frequency, or tension), a
// column per solver with its relative error estimate beside it, the spread between the exact
// solvers and the verdict of the row's checks (docs/reference/solve-output.md). Wider than the
// terminal: the solvers that do not fit go into a second table with the same rows.

#include <optional>
#include <string>
#include <vector>

#include "cli/terminal_style.hpp"

namespace catena::cli {

struct TableCell {
  double value = 0.0;
  /// The solver's relative error estimate (< 0: none, printed "-").
  double estimate = -1.0;
  /// False when the estimate exceeds the solver's accuracy target: the value is shown (the solver
  /// returned it as a partial result) with its estimate marked "*".
  bool meets_target = true;
};

struct TableRow {
  std::string label;
  /// One per solver of the table (nullopt: that solver has no such row, printed "-").
  std::vector<std::optional<TableCell>> cells;
  /// One per extra column, already formatted.
  std::vector<std::string> extra;
  /// The worst verdict of the row's checks ("PASS", "FAIL", ...); empty: no check ("-").
  std::string verdict;
};

struct SolverTable {
  /// The line above the table ("in-plane modes"), indented like the table.
  std::string title;
  /// Header of the row labels ("mode"), and whether the labels are words (left-aligned).
  std::string label_header = "mode";
  bool labels_left = false;
  std::vector<std::string> solvers;
  /// Per solver: an exact solver, which enters the spread.
  std::vector<bool> exact;
  /// Unit of the solvers' values, in their headers ("fe [rad/s]"); empty: none.
  std::string unit;
  /// Significant digits of the values.
  int digits = 12;
  /// Headers of the extra columns (after the spread), e.g. "fe delta [1/s]".
  std::vector<std::string> extra_headers;
  std::vector<TableRow> rows;
};

/// True when a cell of the table misses its solver's accuracy target (marked "*").
bool misses_target(const SolverTable& table);

/// The relative spread of the exact solvers' values in `row`: (max - min) / max |value|; nullopt
/// with fewer than two values.
std::optional<double> exact_spread(const SolverTable& table, const TableRow& row);

/// The table's lines (no trailing newline on each), each at most `width` columns when one solver
/// fits: the first table holds the solvers that fit beside the spread, extra and check columns;
/// the others follow in tables of their own with the same row labels.
std::vector<std::string> render_table(const SolverTable& table,
                                      const TextStyle& style,
                                      const std::string& indent,
                                      std::size_t width = 120);

}  // namespace catena::cli
