// SPDX-License-Identifier: MIT
#include "catena/io/tolerance_reader.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/builtin_tables.hpp"
#include "io/internal/toml_json.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena {
namespace {

bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0.0; }

// A tolerance that grows with the solvers' own error estimates lets a solver widen every check it
// takes part in; the key is refused by name rather than as merely unknown
// (docs/reference/verdicts.md).
void refuse_estimate_factor(const internal::TableReader& item) {
  if (item.has("estimate_factor")) {
    throw InvalidInput(
        fmt::format("{}: no longer accepted: a tolerance may not grow with a solver's "
                    "self-reported error estimate; "
                    "write a fixed `max` (and, for an asymptotic model, model_parameter, "
                    "model_order and constant)",
                    item.where("estimate_factor")));
  }
}

// model_parameter, model_order and constant come together; strain_constant may come alone.
void read_model_term(internal::TableReader& item, ToleranceRule& rule) {
  rule.model_parameter = item.string("model_parameter", "");
  const bool has_order = item.has("model_order"), has_constant = item.has("constant");
  if (rule.model_parameter.empty() && !has_order && !has_constant) {
    rule.strain_constant = item.number("strain_constant", 0.0);
  } else {
    if (!is_model_parameter(rule.model_parameter)) {
      throw InvalidInput(
          fmt::format("{} = \"{}\": must be \"eps\" (model_parameter, model_order and constant "
                      "come together)",
                      item.where("model_parameter"), rule.model_parameter));
    }
    rule.model_order = static_cast<int>(item.read_integer("model_order", 1, 10));
    rule.constant = item.number("constant");
    rule.strain_constant = item.number("strain_constant", 0.0);
    if (!(rule.constant > 0.0) || !std::isfinite(rule.constant)) {
      throw InvalidInput(fmt::format("{}: must be finite and > 0", item.where("constant")));
    }
  }
  if (!finite_non_negative(rule.strain_constant)) {
    throw InvalidInput(fmt::format("{}: must be finite and >= 0", item.where("strain_constant")));
  }
}

ToleranceRule read_rule(internal::TableReader& item) {
  refuse_estimate_factor(item);
  ToleranceRule rule;
  rule.check = item.string("check");
  rule.compare = item.strings("compare");
  if (rule.compare.size() != 2) {
    throw ParseError(
        fmt::format("{}: expected two names, got {}", item.where("compare"), rule.compare.size()));
  }
  rule.scene_pattern = item.string("scene", "*");
  rule.tag = item.string("tag", "");
  rule.max = item.number("max", 0.0);
  read_model_term(item, rule);
  const std::string beyond = item.string("beyond", "fail");
  if (beyond != "fail" && beyond != "warn") {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be \"fail\" or \"warn\"", item.where("beyond"), beyond));
  }
  rule.warn_only = beyond == "warn";
  rule.reason = item.string("reason");
  item.finish();
  if (rule.check.empty() || rule.reason.empty()) {
    throw ParseError(fmt::format("{}: check and reason must not be empty", item.where("check")));
  }
  if (!(rule.max > 0.0) || !std::isfinite(rule.max)) {
    throw InvalidInput(fmt::format("{}: max must be finite and > 0", item.where("max")));
  }
  return rule;
}

SolverAccuracy read_solver(internal::TableReader& item) {
  SolverAccuracy solver;
  solver.name = item.string("name");
  const std::string family = item.string("family");
  if (family != "exact" && family != "model") {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be \"exact\" or \"model\"", item.where("family"), family));
  }
  solver.exact = family == "exact";
  solver.accuracy = item.number("accuracy");
  solver.accuracy_knob = item.string("accuracy_knob", "");
  solver.reason = item.string("reason");
  item.finish();
  if (!(solver.accuracy > 0.0) || !std::isfinite(solver.accuracy)) {
    throw InvalidInput(fmt::format("{}: must be finite and > 0", item.where("accuracy")));
  }
  if (solver.name.empty() || solver.reason.empty()) {
    throw ParseError(fmt::format("{}: name and reason must not be empty", item.where("name")));
  }
  return solver;
}

// The table from its TOML document (parsed from text, or rebuilt from the built-in JSON).
ToleranceTable read_tolerance_document(const toml::value& document, const std::string& origin) {
  internal::TableReader root(document, origin, "");
  std::vector<ToleranceRule> rules;
  for (internal::TableReader& item : root.table_array("tolerance"))
    rules.push_back(read_rule(item));
  std::vector<SolverAccuracy> solvers;
  for (internal::TableReader& item : root.table_array("solver"))
    solvers.push_back(read_solver(item));
  root.finish();
  // Said here, naming the file: the run would otherwise stop at SceneRunOptions::validate(),
  // whose message speaks to a programmer.
  if (rules.empty()) {
    throw ParseError(fmt::format(
        "{}: no [[tolerance]] tables: a tolerance file gives the agreement expected of each check "
        "(as verification/tolerances.toml does), and without any no check could run",
        origin));
  }
  return ToleranceTable(std::move(rules), std::move(solvers));
}

}  // namespace

ToleranceTable parse_tolerance_table(const std::string& text, const std::string& origin) {
  return read_tolerance_document(internal::parse_toml(text, origin), origin);
}

ToleranceTable read_tolerance_file(const std::filesystem::path& path) {
  return parse_tolerance_table(read_input_file(path, "tolerance file"), path_text(path));
}

ToleranceTable builtin_tolerance_table() {
  return read_tolerance_document(
      internal::toml_from_json(nlohmann::json::parse(internal::kBuiltinTolerancesJson)),
      "verification/tolerances.toml (built in)");
}

}  // namespace catena
