// SPDX-License-Identifier: MIT
// The headline tables (checks by kind and by solver pair) and the source discrepancies, one row
// per published entry.
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "catena/solvers/solver_registry.hpp"
#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

const char* const kVerdicts[] = {"PASS", "FAIL", "WARN", "SOURCE", "SKIP"};

using VerdictCounts = std::map<std::string, std::map<std::string, int>>;

// "fe vs shooting" stays; "shooting vs Gale (1976) ..." becomes "shooting vs published"; a check
// of one solver (status, mode count, orthogonality) is that solver.
std::string pair_label(const json& check) {
  const std::string compare = check.value(key::compare, "");
  if (check.value(key::check, "") != "published") return compare;
  return compare.substr(0, compare.find(" vs ")) + " vs published";
}

void add_counts_table(Document& out, const std::string& first_column, const VerdictCounts& counts) {
  Table t{{first_column, "checks"}, {}, "headline"};
  for (const char* verdict : kVerdicts) t.header.push_back(verdict);
  for (const auto& [row_name, by_verdict] : counts) {
    int total = 0;
    for (const auto& [verdict, count] : by_verdict) total += count;
    std::vector<std::string> row = {row_name, std::to_string(total)};
    for (const char* verdict : kVerdicts) {
      const auto it = by_verdict.find(verdict);
      row.push_back(it == by_verdict.end() ? "0" : std::to_string(it->second));
    }
    t.rows.push_back(std::move(row));
  }
  add_table_or_none(out, std::move(t));
}

}  // namespace

void add_headline(Document& out, const json& document) {
  VerdictCounts by_kind, by_pair;
  for (const auto& scene : document[key::scenes]) {
    for (const auto& check : scene[key::checks]) {
      const std::string verdict = check.value(key::verdict, "?");
      ++by_kind[check.value(key::check, "?")][verdict];
      ++by_pair[pair_label(check)][verdict];
    }
  }
  out.push_back(Heading{2, "Checks by kind and by solver pair", "headline"});
  add_counts_table(out, "check", by_kind);
  add_counts_table(out, "compared", by_pair);
}

namespace {

// A solver's value for published entry `mode` in the entry's unit ("-" when it has none).
std::string solver_value(const json& scene,
                         const std::string& solver,
                         const json& entry,
                         int mode) {
  const json& solvers = scene[key::solvers];
  if (!solvers.contains(solver)) return "-";
  const json& output = solvers[solver];
  const std::string quantity = entry.value(key::quantity, "");
  if (quantity == "forced_max_tension") {
    const json& forced = list_or_empty(output, key::forced);
    if (mode < 0 || mode >= static_cast<int>(forced.size()) ||
        !forced[mode].value(key::diagnostic, "").empty())
      return "-";
    const double H = scene.contains(key::statics)
                         ? scene[key::statics].value(key::horizontal_force_n, 1.0)
                         : 1.0;
    return number_text(forced[mode].value(key::max_abs_tension_n, json(nullptr)).is_number()
                           ? json(forced[mode][key::max_abs_tension_n].get<double>() / H)
                           : json(nullptr),
                       "{:.8g}");
  }
  const char* plane = quantity == "inplane_frequency" ? key::inplane : key::outofplane;
  if (!output.contains(plane)) return "-";
  for (const auto& m : list_or_empty(output[plane], key::modes)) {
    if (m.value(key::index, 0) == mode)
      return number_text(mode_value(m, entry.value(key::unit, "rad/s")), "{:.8g}");
  }
  return "-";
}

// The diagnosis of a SOURCE check: what confirmed it (a second solver or a reviewed finding).
std::string diagnosis(const std::string& detail) {
  for (const char* marker : {"confirmed by", "reviewed finding"}) {
    const auto at = detail.find(marker);
    if (at != std::string::npos) return detail.substr(at);
  }
  return detail;
}

// One published entry's row when some check of it is SOURCE; empty otherwise.
std::vector<std::string> entry_row(const json& scene, const json& entry, int mode, double printed) {
  const std::string quantity = entry.value(key::quantity, "");
  const bool forced = quantity == "forced_max_tension";
  const std::string plane =
      forced ? "forced" : quantity.substr(0, quantity.find('_'));  // inplane, outofplane
  const std::string source = entry.value(key::source, "");
  std::vector<std::string> verdicts;
  std::string why;
  for (const auto& check : scene[key::checks]) {
    const std::string compare = check.value(key::compare, "");
    if (check.value(key::check, "") != "published" ||
        check.value(key::mode, -1) != (forced ? mode + 1 : mode))
      continue;
    std::string check_plane = check.value(key::plane, "");
    check_plane.erase(std::remove(check_plane.begin(), check_plane.end(), '-'), check_plane.end());
    if (check_plane != plane) continue;
    const auto vs = compare.find(" vs ");
    if (vs == std::string::npos || compare.substr(vs + 4) != source) continue;
    const std::string verdict = check.value(key::verdict, "");
    verdicts.push_back(compare.substr(0, vs) + " " + verdict);
    if (verdict == "SOURCE" && why.empty()) why = diagnosis(check.value(key::detail, ""));
  }
  if (why.empty()) return {};
  std::vector<std::string> row = {scene.value(key::name, ""), source,
                                  std::to_string(forced ? mode + 1 : mode),
                                  fmt::format("{:g}", printed)};
  for (const std::string& solver : solver_names(SolverKind::Exact))
    row.push_back(solver_value(scene, solver, entry, mode));
  std::string verdict_text;
  for (const auto& v : verdicts) verdict_text += (verdict_text.empty() ? "" : ", ") + v;
  row.push_back(verdict_text);
  row.push_back(why);
  return row;
}

}  // namespace

int add_discrepancies(Document& out, const json& document) {
  out.push_back(Heading{2, "Source discrepancies", "source-discrepancies"});
  out.push_back(Paragraph{
      "Published entries we believe wrong, one row per printed value: two of our independent "
      "solvers agree with each other and not with the printed value, or a reviewed finding "
      "(verification/findings.toml) explains the difference. Values in the table's unit; "
      "'verdicts' lists each solver compared with the entry."});
  // One column per exact solver, in registry order.
  Table t{{"scene", "source", "mode", "printed"}, {}, "discrepancies"};
  for (const std::string& solver : solver_names(SolverKind::Exact)) t.header.push_back(solver);
  t.header.push_back("verdicts");
  t.header.push_back("diagnosis");
  for (const auto& scene : document[key::scenes]) {
    for (const auto& entry : list_or_empty(scene, key::published)) {
      const json& modes = entry.at(key::modes);
      const json& values = entry.at(key::values);
      for (std::size_t k = 0; k < modes.size() && k < values.size(); ++k) {
        if (!values[k].is_number()) continue;
        auto row = entry_row(scene, entry, modes[k].get<int>(), values[k].get<double>());
        if (!row.empty()) t.rows.push_back(std::move(row));
      }
    }
  }
  const int rows = static_cast<int>(t.rows.size());
  add_table_or_none(out, std::move(t));
  return rows;
}

}  // namespace catena::internal
