// SPDX-License-Identifier: MIT
#include "io/report/report_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/io/csv_table.hpp"

namespace catena::internal {
namespace {

// A JSON value as one CSV cell: numbers to 17 digits (round trip), null as empty.
std::string cell(const json& value) {
  if (value.is_null()) return "";
  if (value.is_number()) return fmt::format("{:.17g}", value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

void add_frequencies(const json& scene, CsvTable& frequencies) {
  const std::string name = scene.value(key::name, "");
  for (const auto& [solver, output] : scene[key::solvers].items()) {
    for (const char* plane : {key::inplane, key::outofplane}) {
      if (!output.contains(plane)) continue;
      for (const auto& mode : output[plane][key::modes]) {
        frequencies.rows.push_back({name, solver, plane, cell(mode[key::index]),
                                    cell(mode[key::omega_rad_s]), cell(mode[key::frequency_hz]),
                                    cell(mode[key::k_l_over_pi]), cell(mode[key::gale_ratio]),
                                    cell(mode[key::relative_error_estimate])});
      }
    }
  }
}

void add_checks(const json& scene, CsvTable& checks, CsvTable& published) {
  const std::string name = scene.value(key::name, "");
  for (const auto& check : scene[key::checks]) {
    std::vector<std::string> row = {name,
                                    cell(check[key::check]),
                                    cell(check[key::compare]),
                                    cell(check[key::plane]),
                                    cell(check[key::mode]),
                                    cell(check[key::value_a]),
                                    cell(check[key::value_b]),
                                    cell(check[key::measured]),
                                    cell(check[key::tolerance]),
                                    cell(check[key::verdict]),
                                    cell(check[key::detail])};
    if (check.value(key::check, "") == "published") {
      published.rows.push_back(
          {name, row[2], row[3], row[4], row[5], row[6], row[7], row[8], row[9], row[10]});
    }
    checks.rows.push_back(std::move(row));
  }
}

}  // namespace

std::string number_text(const json& value, const char* format) {
  if (value.is_null() || !value.is_number()) return "-";
  return fmt::format(fmt::runtime(format), value.get<double>());
}

const json& list_or_empty(const json& object, const char* name) {
  static const json empty = json::array();
  return object.contains(name) ? object.at(name) : empty;
}

json mode_value(const json& mode, const std::string& unit) {
  if (unit == "gale") return mode.value(key::gale_ratio, json(nullptr));
  if (unit == "kL/pi") return mode.value(key::k_l_over_pi, json(nullptr));
  if (unit == "Hz") return mode.value(key::frequency_hz, json(nullptr));
  return mode.value(key::omega_rad_s, json(nullptr));
}

bool has_tag(const json& scene, const std::string& tag) {
  const auto tags = scene.value(key::tags, std::vector<std::string>{});
  return std::find(tags.begin(), tags.end(), tag) != tags.end();
}

void write_data_tables(const json& document, const std::filesystem::path& dir) {
  CsvTable frequencies{
      {"Every natural frequency every solver returned. Written by catena report from report.json."},
      {"scene", "solver", "plane", "mode", "omega_rad_s", "frequency_hz", "k_l_over_pi",
       "gale_ratio", "relative_error_estimate"},
      {}};
  CsvTable checks{{"Every check of the run. measured and tolerance: see each check kind in "
                   "verification/README.md."},
                  {"scene", "check", "compare", "plane", "mode", "value_a", "value_b", "measured",
                   "tolerance", "verdict", "detail"},
                  {}};
  CsvTable published{{"Our values beside the published ones (value_a = ours, value_b = printed, in "
                      "the table's unit)."},
                     {"scene", "compare", "plane", "mode", "ours", "printed", "abs_difference",
                      "tolerance", "verdict", "detail"},
                     {}};
  for (const auto& scene : document[key::scenes]) {
    add_frequencies(scene, frequencies);
    add_checks(scene, checks, published);
  }
  std::filesystem::create_directories(dir);
  write_csv_table(dir / "frequencies.csv", frequencies);
  write_csv_table(dir / "checks.csv", checks);
  write_csv_table(dir / "published.csv", published);
}

TimeToAccuracy read_time_to_accuracy(const std::filesystem::path& csv) {
  TimeToAccuracy result;
  if (!std::filesystem::exists(csv)) return result;
  const CsvTable table = read_csv_table(csv);
  if (!table.comments.empty()) result.description = table.comments.front();
  if (!result.description.empty() && result.description.back() == '.')
    result.description.pop_back();  // it is quoted inside a sentence
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const std::string& name = table.text(row, "scene");
    const std::string& solver = table.text(row, "solver");
    const double time_s = table.number(row, "time_s").value_or(std::nan(""));
    const double error = table.number(row, "max_rel_error").value_or(std::nan(""));
    if (std::find(result.cases.begin(), result.cases.end(), name) == result.cases.end())
      result.cases.push_back(name);
    for (double target : kAccuracyTargets) {
      if (!(error <= target)) continue;
      auto& slot = result.best_time_s[name][solver];
      if (!slot.count(target) || time_s < slot[target]) slot[target] = time_s;
    }
  }
  return result;
}

}  // namespace catena::internal
