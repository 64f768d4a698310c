// SPDX-License-Identifier: MIT
#include "catena/io/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"

namespace catena {
namespace {

// Cells of one line. A cell in double quotes may hold commas, and "" inside it is one quote
// (RFC 4180, without line breaks inside cells).
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

// A cell as written: quoted when it holds a comma, a quote or a line break.
std::string csv_cell(const std::string& cell) {
  if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
  std::string quoted = "\"";
  for (char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

}  // namespace

std::size_t CsvTable::column_index(const std::string& column) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == column) return i;
  }
  throw ParseError(fmt::format("CSV table has no column '{}'", column));
}

std::optional<double> CsvTable::number(std::size_t row, const std::string& column) const {
  const std::string& cell = text(row, column);
  if (cell.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size()) {
    throw ParseError(
        fmt::format("CSV cell '{}' in column '{}', row {} is not a number", cell, column, row + 1));
  }
  return value;
}

const std::string& CsvTable::text(std::size_t row, const std::string& column) const {
  return rows.at(row).at(column_index(column));
}

CsvTable read_csv_table(const std::filesystem::path& path) {
  // Our largest table (verification/baseline/published.csv) is under 1 MB.
  std::string text = read_input_file(path, "CSV file", 64 * kMaxInputFileBytes);
  // A UTF-8 byte order mark (spreadsheets write one) is not part of the first column's name.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  std::istringstream in(text);
  CsvTable table;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;
    if (line[0] == '#') {
      table.comments.push_back(trim(line.substr(1)));
      continue;
    }
    std::vector<std::string> cells = split_cells(line);
    for (auto& cell : cells) cell = trim(cell);
    if (table.columns.empty()) {
      // A name given twice would make every lookup read the first of them only.
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (std::find(cells.begin(), cells.begin() + static_cast<long>(i), cells[i]) !=
            cells.begin() + static_cast<long>(i))
          throw ParseError(fmt::format("{}:{}: column '{}' appears twice in the header",
                                       path_text(path), line_number, cells[i]));
      }
      table.columns = cells;
      continue;
    }
    if (cells.size() != table.columns.size()) {
      throw ParseError(fmt::format("{}:{}: {} cells, header has {}", path_text(path), line_number,
                                   cells.size(), table.columns.size()));
    }
    table.rows.push_back(std::move(cells));
    table.row_lines.push_back(line_number);
  }
  if (table.columns.empty()) throw ParseError(fmt::format("{}: no header line", path_text(path)));
  return table;
}

void write_csv_table(const std::filesystem::path& path, const CsvTable& table) {
  std::ostringstream out;
  for (const auto& comment : table.comments) out << "# " << comment << '\n';
  auto write_row = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << csv_cell(cells[i]);
    out << '\n';
  };
  write_row(table.columns);
  for (const auto& row : table.rows) write_row(row);
  write_file_atomically(path, out.str());
}

}  // namespace catena
