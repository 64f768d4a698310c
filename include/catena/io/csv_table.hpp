// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reading and writing the small CSV tables of verification/reference/published/ and
/// verification/comparisons/: '#' lines are provenance comments, the first other line is the
/// header, empty cells are missing values. A cell in double quotes may hold commas ("" is a quote
/// inside it); the writer quotes such cells.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace catena {

/// A CSV table held as text cells with typed accessors.
struct CsvTable {
  std::vector<std::string> comments;  ///< the '#' lines, without '# '
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  /// The file line (1-based) of each row, for messages; empty for a table built in memory.
  std::vector<int> row_lines = {};

  /// Index of `column`; throws ParseError naming the column when absent.
  std::size_t column_index(const std::string& column) const;
  /// The cell as a number; nullopt when empty. Throws ParseError when not a number.
  std::optional<double> number(std::size_t row, const std::string& column) const;
  /// The cell as text.
  const std::string& text(std::size_t row, const std::string& column) const;
};

/// Reads `path`. Throws ParseError (with file and line) when unreadable or ragged.
CsvTable read_csv_table(const std::filesystem::path& path);

/// Writes `table` with its comments as '# ' lines, atomically (catena/io/file_access.hpp). Throws
/// InvalidInput naming the path when the file cannot be written.
void write_csv_table(const std::filesystem::path& path, const CsvTable& table);

}  // namespace catena
