// SPDX-License-Identifier: MIT
#include "cli/solve_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace catena::cli {
namespace {

constexpr std::size_t kGap = 2;  // spaces between columns

// One column: its header and its cells (one per row), right-aligned to the widest.
struct Column {
  std::string header;
  std::vector<std::string> cells;
  bool verdict = false;  // coloured by its text
  bool left = false;     // left-aligned (the row labels)

  std::size_t width() const {
    std::size_t w = header.size();
    for (const auto& cell : cells) w = std::max(w, cell.size());
    return w;
  }
};

std::string estimate_text(double estimate) {
  return estimate >= 0.0 ? fmt::format("{:.0e}", estimate) : std::string("-");
}

// A solver's two columns: its values to the table's digits and its estimates.
std::vector<Column> solver_columns(const SolverTable& table, std::size_t k) {
  Column value{
      table.unit.empty() ? table.solvers[k] : fmt::format("{} [{}]", table.solvers[k], table.unit),
      {}};
  Column estimate{"est", {}};
  for (const auto& row : table.rows) {
    const auto& cell = row.cells[k];
    value.cells.push_back(cell ? fmt::format("{:.{}g}", cell->value, table.digits) : "-");
    estimate.cells.push_back(cell ? estimate_text(cell->estimate) + (cell->meets_target ? "" : "*")
                                  : "-");
  }
  return {value, estimate};
}

// Spread, extra and check columns: they follow the first table's solvers.
std::vector<Column> tail_columns(const SolverTable& table) {
  std::vector<Column> tail;
  const long exact = std::count(table.exact.begin(), table.exact.end(), true);
  if (exact >= 2) {
    Column spread{"spread", {}};
    for (const auto& row : table.rows) {
      const auto value = exact_spread(table, row);
      spread.cells.push_back(value ? fmt::format("{:.0e}", *value) : "-");
    }
    tail.push_back(spread);
  }
  for (std::size_t e = 0; e < table.extra_headers.size(); ++e) {
    Column extra{table.extra_headers[e], {}};
    for (const auto& row : table.rows) extra.cells.push_back(row.extra.at(e));
    tail.push_back(extra);
  }
  Column check{"check", {}, true};
  for (const auto& row : table.rows) check.cells.push_back(row.verdict.empty() ? "-" : row.verdict);
  tail.push_back(check);
  return tail;
}

// `text` padded to `width`, after the gap that separates it from the column before.
std::string cell(const Column& column, const std::string& text, std::size_t width, bool gap) {
  return column.left ? fmt::format("{}{:<{}}", gap ? "  " : "", text, width)
                     : fmt::format("{}{:>{}}", gap ? "  " : "", text, width);
}

std::size_t columns_width(const std::vector<Column>& columns) {
  std::size_t total = 0;
  for (const auto& column : columns) total += kGap + column.width();
  return total;
}

void append_lines(std::vector<std::string>& lines,
                  const std::vector<Column>& columns,
                  const TextStyle& style,
                  const std::string& indent) {
  std::vector<std::size_t> widths;
  for (const auto& column : columns) widths.push_back(column.width());
  std::string header = indent;
  for (std::size_t c = 0; c < columns.size(); ++c)
    header += cell(columns[c], columns[c].header, widths[c], c > 0);
  lines.push_back(header);
  for (std::size_t r = 0; r < columns.front().cells.size(); ++r) {
    std::string line = indent;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string& text = columns[c].cells[r];
      const std::string padded = cell(columns[c], text, widths[c], c > 0);
      line += columns[c].verdict ? style.verdict(padded, text) : padded;
    }
    lines.push_back(line);
  }
}

}  // namespace

bool misses_target(const SolverTable& table) {
  for (const auto& row : table.rows)
    for (const auto& cell : row.cells)
      if (cell && !cell->meets_target) return true;
  return false;
}

std::optional<double> exact_spread(const SolverTable& table, const TableRow& row) {
  double low = INFINITY, high = -INFINITY, scale = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < row.cells.size(); ++k) {
    if (!table.exact[k] || !row.cells[k]) continue;
    const double v = row.cells[k]->value;
    low = std::min(low, v);
    high = std::max(high, v);
    scale = std::max(scale, std::abs(v));
    ++count;
  }
  if (count < 2) return std::nullopt;
  return scale > 0.0 ? (high - low) / scale : 0.0;
}

std::vector<std::string> render_table(const SolverTable& table,
                                      const TextStyle& style,
                                      const std::string& indent,
                                      std::size_t width) {
  Column labels{table.label_header, {}, false, table.labels_left};
  for (const auto& row : table.rows) labels.cells.push_back(row.label);
  const std::vector<Column> tail = tail_columns(table);
  std::vector<std::string> lines;
  if (!table.title.empty()) lines.push_back(indent + table.title);
  // Greedy: solvers in order until the next one would pass the width (at least one per table).
  std::size_t k = 0;
  bool first = true;
  while (first || k < table.solvers.size()) {
    std::vector<Column> columns{labels};
    const std::size_t reserved = first ? columns_width(tail) : 0;
    std::size_t used = indent.size() + labels.width() + reserved;
    const std::size_t start = k;
    for (; k < table.solvers.size(); ++k) {
      const std::vector<Column> pair = solver_columns(table, k);
      if (k > start && used + columns_width(pair) > width) break;
      used += columns_width(pair);
      columns.insert(columns.end(), pair.begin(), pair.end());
    }
    if (first) columns.insert(columns.end(), tail.begin(), tail.end());
    if (!first) lines.push_back(indent + "(continued)");
    append_lines(lines, columns, style, indent);
    first = false;
  }
  return lines;
}

}  // namespace catena::cli
