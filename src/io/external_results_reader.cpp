// SPDX-License-Identifier: MIT
// Another program's results for `catena check`: CSV (with an optional long-format shapes CSV) or
// JSON, validated cell by cell so that every message names the file, the row and the column.
#include "catena/io/external_results_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "catena/core/error.hpp"
#include "catena/io/csv_table.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/csv_cells.hpp"
#include "io/internal/external_results_json.hpp"

namespace catena {
namespace {

const std::vector<std::string> kResultColumns = {"plane", "mode", "frequency_hz", "omega_rad_s",
                                                 "resolution"};
const std::vector<std::string> kShapeColumns = {"plane", "mode", "resolution", "station_s_m",
                                                "u",     "w",    "v",          "tension_n"};
const std::vector<std::string> kShapeComponents = {"u", "w", "v", "tension_n"};

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& word : words) out += (out.empty() ? "" : ", ") + word;
  return out;
}

// The frequency tables' cells: the shared ones, the plane and the mode number.
struct CsvCells : internal::CsvCells {
  Plane plane(std::size_t row) const {
    const std::string& cell = table.text(row, "plane");
    const auto plane = parse_plane(cell);
    if (!plane) {
      throw InvalidInput(
          fmt::format("{}: '{}' is not a plane (in-plane, inplane, out-of-plane, outofplane)",
                      where(row, "plane"), cell));
    }
    return *plane;
  }
  int mode(std::size_t row) const {
    return internal::mode_number(required(row, "mode"), where(row, "mode"));
  }
};

void check_columns(const CsvCells& cells,
                   const std::vector<std::string>& allowed,
                   const std::vector<std::string>& required) {
  for (const auto& column : cells.table.columns) {
    if (std::find(allowed.begin(), allowed.end(), column) == allowed.end()) {
      throw InvalidInput(fmt::format("{}: header: unknown column '{}' (accepted: {})", cells.file,
                                     column, joined(allowed)));
    }
  }
  for (const auto& column : required) {
    if (!cells.has(column))
      throw InvalidInput(fmt::format("{}: header: missing column '{}'", cells.file, column));
  }
  if (cells.table.rows.empty()) throw InvalidInput(fmt::format("{}: no data rows", cells.file));
}

std::vector<ExternalMode> read_results_csv(const std::filesystem::path& path) {
  const CsvTable table = read_csv_table(path);
  const CsvCells cells{{table, path_text(path)}};
  check_columns(cells, kResultColumns, {"plane", "mode"});
  const bool hz = cells.has("frequency_hz");
  if (hz == cells.has("omega_rad_s")) {
    throw InvalidInput(
        fmt::format("{}: header: give exactly one of the columns 'frequency_hz' and 'omega_rad_s'",
                    cells.file));
  }
  const std::string frequency = hz ? "frequency_hz" : "omega_rad_s";
  std::vector<ExternalMode> modes;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    ExternalMode mode;
    mode.origin = cells.row_name(row);
    mode.plane = cells.plane(row);
    mode.mode = cells.mode(row);
    mode.resolution = cells.number(row, "resolution");
    const double value = cells.required(row, frequency);
    if (value <= 0.0)
      throw InvalidInput(fmt::format("{}: {} must be > 0", cells.where(row, frequency), value));
    mode.omega_rad_s = hz ? 2.0 * kPi * value : value;
    modes.push_back(mode);
  }
  return modes;
}

using ModeKey = std::tuple<int, int, double>;  // plane, mode, resolution (-1: none)

ModeKey key_of(Plane plane, int mode, std::optional<double> resolution) {
  return {plane == Plane::InPlane ? 0 : 1, mode, resolution.value_or(-1.0)};
}

// One component of one shape: every station gives it or none does.
void read_component(const CsvCells& cells,
                    const std::vector<std::size_t>& rows,
                    const std::string& column,
                    Vector& out) {
  if (!cells.has(column)) return;
  std::vector<std::optional<double>> values;
  for (std::size_t row : rows) values.push_back(cells.number(row, column));
  const auto given =
      std::count_if(values.begin(), values.end(), [](const auto& v) { return v.has_value(); });
  if (given == 0) return;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!values[i])
      throw InvalidInput(fmt::format("{}: empty, but other stations of this mode give it",
                                     cells.where(rows[i], column)));
  }
  out.resize(static_cast<Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) out[static_cast<Index>(i)] = *values[i];
}

void attach_shapes_csv(const std::filesystem::path& path, std::vector<ExternalMode>& modes) {
  const CsvTable table = read_csv_table(path);
  const CsvCells cells{{table, path_text(path)}};
  check_columns(cells, kShapeColumns, {"plane", "mode", "station_s_m"});
  std::map<ModeKey, std::vector<std::size_t>> groups;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    groups[key_of(cells.plane(row), cells.mode(row), cells.number(row, "resolution"))].push_back(
        row);
  }
  for (const auto& [key, rows] : groups) {
    const auto result = std::find_if(modes.begin(), modes.end(), [&](const ExternalMode& m) {
      return key_of(m.plane, m.mode, m.resolution) == key;
    });
    if (result == modes.end()) {
      throw InvalidInput(fmt::format(
          "{}: a shape of a mode (plane, mode, resolution) that has no row in the results",
          cells.row_name(rows.front())));
    }
    ExternalShape shape;
    shape.s_m.resize(static_cast<Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
      shape.s_m[static_cast<Index>(i)] = cells.required(rows[i], "station_s_m");
    Vector* components[] = {&shape.u, &shape.w, &shape.v, &shape.tension_n};
    for (std::size_t c = 0; c < kShapeComponents.size(); ++c)
      read_component(cells, rows, kShapeComponents[c], *components[c]);
    result->shape = std::move(shape);
    result->origin += fmt::format(" (shape: {})", cells.row_name(rows.front()));
  }
}

}  // namespace

namespace internal {
int mode_number(double value, const std::string& where) {
  if (value < 1.0 || value > 1e6 || value != std::floor(value)) {
    throw InvalidInput(fmt::format("{}: mode = {}: must be a whole number >= 1", where, value));
  }
  return static_cast<int>(value);
}
}  // namespace internal

std::optional<Plane> parse_plane(const std::string& text) {
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "in-plane" || lower == "inplane") return Plane::InPlane;
  if (lower == "out-of-plane" || lower == "outofplane") return Plane::OutOfPlane;
  return std::nullopt;
}

std::vector<ExternalMode> read_external_results(const std::filesystem::path& results,
                                                const std::filesystem::path& shapes) {
  const bool json = results.extension() == ".json";
  if (json && !shapes.empty()) {
    throw InvalidInput(
        fmt::format("{}: a JSON results file carries its own shapes; --shapes is for CSV results",
                    path_text(shapes)));
  }
  std::vector<ExternalMode> modes =
      json ? internal::read_external_results_json(results) : read_results_csv(results);
  if (!shapes.empty()) attach_shapes_csv(shapes, modes);
  validate_external_results(modes);
  return modes;
}

std::vector<ExternalMode> parse_external_results_json(const std::string& text,
                                                      const std::string& origin) {
  std::vector<ExternalMode> modes = internal::parse_results_json_text(text, origin);
  validate_external_results(modes);
  return modes;
}

}  // namespace catena
