// SPDX-License-Identifier: MIT
// Reading another program's time series: a MoorDyn output file or a CSV with a time column, told
// apart by the header's content (docs/how-to/check-time-series.md, "Files").
#include "catena/io/timeseries_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "core/internal/ascii_lower.hpp"

namespace catena {
namespace {

struct Line {
  int number = 0;  // 1-based
  std::string_view text;
};

std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  int number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back({++number, line});
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

bool is_blank(std::string_view line) {
  return std::all_of(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c); });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

// MoorDyn pads with spaces (v2, setw) or separates with tabs (v1): any run of blanks splits.
std::vector<std::string_view> split_blanks(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) cells.push_back(line.substr(start, i - start));
  }
  return cells;
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

// A CSV column name split into the name and a trailing unit: "tension [N]", "x (m)", "time_s".
// Only the bracketed forms give a unit for any column; "_s" is recognised for the time column only
// (a channel "node_x" must not lose its "_x").
std::pair<std::string, std::string> split_unit(std::string_view cell) {
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const std::size_t at = cell.rfind(open);
    if (at != std::string_view::npos && !cell.empty() && cell.back() == close) {
      return {std::string(trim(cell.substr(0, at))),
              std::string(trim(cell.substr(at + 1, cell.size() - at - 2)))};
    }
  }
  return {std::string(cell), ""};
}

// The time column's unit when `cell` names it ("time", "Time [s]", "time_s", "TIME(s)"), nullopt
// when it is another column.
std::optional<std::string> time_column_unit(std::string_view cell) {
  auto [name, unit] = split_unit(cell);
  const std::string key = internal::ascii_lower(name);
  if (key == "time") return unit;
  if (key.size() > 5 && key.compare(0, 5, "time_") == 0 && unit.empty()) return name.substr(5);
  return std::nullopt;
}

// std::from_chars reads "nan", "inf" and "-nan" (MoorDyn's output of an unstable run) but not a
// leading '+'.
std::optional<double> parse_number(std::string_view cell) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size()) return std::nullopt;
  return value;
}

struct Layout {
  std::string format;
  std::size_t time_column = 0;
  std::vector<std::string> header;  // every column, the time included
  std::vector<std::string> units;   // every column
  std::size_t first_data = 0;       // index into the lines
};

std::size_t next_nonblank(const std::vector<Line>& lines, std::size_t i) {
  while (i < lines.size() && is_blank(lines[i].text)) ++i;
  return i;
}

// MoorDyn: "Time" first, an optional row of units in parentheses.
Layout moordyn_layout(const std::vector<Line>& lines, std::size_t header, const std::string& src) {
  Layout layout;
  layout.format = "moordyn";
  for (const auto cell : split_blanks(lines[header].text)) layout.header.emplace_back(cell);
  layout.units.assign(layout.header.size(), "");
  std::size_t next = next_nonblank(lines, header + 1);
  if (next < lines.size()) {
    const auto cells = split_blanks(lines[next].text);
    // MoorDyn-C v2's main file writes the time's unit in parentheses and the channels' bare
    // ("(s)  N  m": source/MoorDyn2.cpp of FloatingArrayDesign/MoorDyn v2.7), its line files and
    // MoorDyn-F every unit in parentheses: a row starting with "(s)" whose cells are not numbers.
    const auto bracketed = [](std::string_view c) {
      return c.size() >= 2 && c.front() == '(' && c.back() == ')';
    };
    const bool units = !cells.empty() && bracketed(cells.front()) &&
                       std::none_of(cells.begin(), cells.end(),
                                    [](auto c) { return parse_number(c).has_value(); });
    if (units) {
      if (cells.size() != layout.header.size()) {
        throw InvalidInput(fmt::format("{} line {}: the units row has {} cells, the header {}", src,
                                       lines[next].number, cells.size(), layout.header.size()));
      }
      for (std::size_t j = 0; j < cells.size(); ++j)
        layout.units[j] =
            std::string(bracketed(cells[j]) ? cells[j].substr(1, cells[j].size() - 2) : cells[j]);
      next = next_nonblank(lines, next + 1);
    }
  }
  if (!layout.units[0].empty() && layout.units[0] != "s") {
    throw InvalidInput(fmt::format("{} line {}: the time unit is '{}'; catena reads seconds (s)",
                                   src, lines[header].number, layout.units[0]));
  }
  layout.first_data = next;
  return layout;
}

Layout csv_layout(const std::vector<Line>& lines, std::size_t header, const std::string& src) {
  Layout layout;
  layout.format = "csv";
  const auto cells = split_commas(lines[header].text);
  std::optional<std::size_t> time;
  for (std::size_t j = 0; j < cells.size(); ++j) {
    const auto unit = time_column_unit(cells[j]);
    if (unit && time) {
      throw InvalidInput(fmt::format("{} line {}: two time columns, '{}' and '{}'", src,
                                     lines[header].number, cells[*time], cells[j]));
    }
    if (unit) {
      time = j;
      if (!unit->empty() && *unit != "s") {
        throw InvalidInput(
            fmt::format("{} line {}, column '{}': the time unit is '{}'; catena "
                        "reads seconds (s)",
                        src, lines[header].number, cells[j], *unit));
      }
    }
    layout.header.emplace_back(cells[j]);
    layout.units.push_back(unit ? "s" : split_unit(cells[j]).second);
  }
  if (!time) {
    throw InvalidInput(fmt::format(
        "{} line {}: no time column: a CSV time series needs a column named 'time' (any case, "
        "optionally 'time_s' or 'time [s]'); a MoorDyn file starts with 'Time'",
        src, lines[header].number));
  }
  layout.time_column = *time;
  layout.first_data = next_nonblank(lines, header + 1);
  return layout;
}

Layout detect_layout(const std::vector<Line>& lines, const std::string& source) {
  const std::size_t header = next_nonblank(lines, 0);
  if (header == lines.size()) throw InvalidInput(source + ": empty: no header row, no data rows");
  const std::string_view text = lines[header].text;
  const auto blank_cells = split_blanks(text);
  if (text.find(',') == std::string_view::npos && !blank_cells.empty() &&
      internal::ascii_lower(blank_cells.front()) == "time")
    return moordyn_layout(lines, header, source);
  if (text.find(',') != std::string_view::npos) return csv_layout(lines, header, source);
  throw InvalidInput(fmt::format(
      "{} line {}: not a time series: a MoorDyn output file starts with a header row whose first "
      "name is 'Time'; a CSV needs a header with a 'time' column",
      source, lines[header].number));
}

std::vector<std::string_view> data_cells(const Layout& layout, std::string_view text) {
  return layout.format == "csv" ? split_commas(text) : split_blanks(text);
}

// Reads the data rows into `series`, checking each row as it goes.
void read_rows(const std::vector<Line>& lines, const Layout& layout, TimeSeries& series) {
  std::vector<std::vector<double>> columns(layout.header.size());
  std::vector<double> time;
  for (std::size_t i = layout.first_data; i < lines.size(); ++i) {
    if (is_blank(lines[i].text)) continue;
    const int number = lines[i].number;
    const auto cells = data_cells(layout, lines[i].text);
    if (cells.size() != layout.header.size()) {
      throw InvalidInput(fmt::format("{} line {}: {} cells, the header has {} (a ragged row)",
                                     series.source, number, cells.size(), layout.header.size()));
    }
    for (std::size_t j = 0; j < cells.size(); ++j) {
      const auto value = parse_number(cells[j]);
      if (!value) {
        throw InvalidInput(fmt::format("{} line {}, column '{}': '{}' is not a number",
                                       series.source, number, layout.header[j], cells[j]));
      }
      if (j == layout.time_column) {
        if (!std::isfinite(*value)) {
          throw InvalidInput(fmt::format("{} line {}, column '{}': the time is {}", series.source,
                                         number, layout.header[j], cells[j]));
        }
        if (!time.empty() && !(*value > time.back())) {
          throw InvalidInput(fmt::format(
              "{} line {}: time {} s is not after the previous row's {} s (line {}): the time "
              "column must increase strictly (a restarted or appended run?)",
              series.source, number, *value, time.back(), series.line_numbers.back()));
        }
        time.push_back(*value);
      } else {
        columns[j].push_back(*value);
      }
    }
    series.line_numbers.push_back(number);
  }
  if (time.empty()) {
    throw InvalidInput(fmt::format("{}: no data rows after the header{}", series.source,
                                   layout.format == "moordyn" ? " and units rows" : ""));
  }
  series.time_s = Eigen::Map<const Vector>(time.data(), static_cast<Index>(time.size()));
  for (std::size_t j = 0; j < layout.header.size(); ++j) {
    if (j == layout.time_column) continue;
    series.names.push_back(layout.header[j]);
    series.units.push_back(layout.units[j]);
    series.columns.push_back(
        Eigen::Map<const Vector>(columns[j].data(), static_cast<Index>(columns[j].size())));
  }
}

// A MoorDyn line file's segment count: its highest node (Node0 ... NodeN) or segment (Seg1 ...
// SegN) number.
std::optional<int> line_file_segments(const std::vector<std::string>& names) {
  int highest_node = -1, highest_segment = 0;
  for (const std::string& name : names) {
    const std::string key = internal::ascii_lower(name);
    const bool node = key.rfind("node", 0) == 0;
    const bool segment = key.rfind("seg", 0) == 0;
    if (!node && !segment) return std::nullopt;
    const std::size_t digits = node ? 4 : 3;
    int number = 0;
    const auto [end, error] = std::from_chars(key.data() + digits, key.data() + key.size(), number);
    if (error != std::errc() || end == key.data() + digits) return std::nullopt;
    (node ? highest_node : highest_segment) =
        std::max(node ? highest_node : highest_segment, number);
  }
  const int n = std::max(highest_node, highest_segment);
  return n >= 1 ? std::optional<int>(n) : std::nullopt;
}

}  // namespace

TimeSeries parse_time_series_text(const std::string& text, const std::string& source) {
  const std::vector<Line> lines = split_lines(text);
  const Layout layout = detect_layout(lines, source);
  TimeSeries series;
  series.source = source;
  series.format = layout.format;
  read_rows(lines, layout, series);
  if (series.names.empty())
    throw InvalidInput(fmt::format("{}: no channel: the file has a time column only", source));
  if (series.format == "moordyn") series.num_segments = line_file_segments(series.names);
  return series;
}

TimeSeries read_time_series(const std::filesystem::path& file) {
  return parse_time_series_text(read_input_file(file, "time series", kMaxTimeSeriesFileBytes),
                                path_text(file));
}

bool looks_like_time_series(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return false;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && is_blank(line)) {
  }
  if (!in && line.empty()) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.find(',') == std::string::npos) {
    const auto cells = split_blanks(line);
    return !cells.empty() && internal::ascii_lower(cells.front()) == "time";
  }
  // A results or tension CSV of `catena check` never has a time column.
  const auto cells = split_commas(line);
  return std::any_of(cells.begin(), cells.end(),
                     [](std::string_view c) { return time_column_unit(c).has_value(); });
}

}  // namespace catena
