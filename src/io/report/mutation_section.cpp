// SPDX-License-Identifier: MIT
// The mutation score of `catena verify --mutation` (docs/explanation/mutation.md): by solver and
// scene family, by solver and quantity, and every uncaught mutation.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

#include "catena/solvers/solver_registry.hpp"
#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

struct Tally {
  int made = 0, caught = 0;
};

std::string percent(const Tally& t) {
  return t.made ? fmt::format("{:.1f}%", 100.0 * t.caught / t.made) : "-";
}

void add_tally_table(Document& out,
                     const std::string& second,
                     const std::map<std::pair<std::string, std::string>, Tally>& tallies) {
  Table t{{"solver", second, "made", "caught", "uncaught", "caught [%]"}, {}, "mutation"};
  for (const auto& [what, tally] : tallies) {
    t.rows.push_back({what.first, what.second, std::to_string(tally.made),
                      std::to_string(tally.caught), std::to_string(tally.made - tally.caught),
                      percent(tally)});
  }
  add_table_or_none(out, std::move(t));
}

std::string joined_numbers(const json& list, const char* format) {
  std::string text;
  for (const auto& x : list) text += (text.empty() ? "" : ", ") + number_text(x, format);
  return text;
}

// The mutated values' own estimates: "-" for a value without one (negative, or null).
std::string joined_estimates(const json& list) {
  std::string text;
  for (const auto& x : list) {
    const bool none = !x.is_number() || x.get<double>() < 0.0;
    text += (text.empty() ? "" : ", ") + (none ? std::string("-") : number_text(x, "{:.2g}"));
  }
  return text;
}

void add_uncaught(Document& out, const json& uncaught) {
  out.push_back(Heading{3, "Uncaught mutations", "mutation-uncaught"});
  Table t{
      {"scene", "solver", "quantity", "plane", "modes", "sizes", "own estimates", "exact witness"},
      {},
      "uncaught"};
  for (const auto& u : uncaught) {
    t.rows.push_back({u.value(key::scene, ""), u.value(key::solver, ""), u.value(key::quantity, ""),
                      u.value(key::plane, ""), joined_numbers(list_or_empty(u, key::modes), "{:g}"),
                      joined_numbers(list_or_empty(u, key::sizes), "{:.2g}"),
                      joined_estimates(list_or_empty(u, key::estimates)),
                      u.value(key::exact_witness, false) ? "yes" : "no"});
  }
  add_table_or_none(out, std::move(t));
}

// "fe 1e-06, frobenius 1e-11, shooting 1.1e-09": the targets the run wrote, by solver name.
std::string default_targets_text(const json& mutation) {
  std::string text;
  const json targets = mutation.value(key::default_accuracy_targets, json::object());
  for (const auto& [solver, target] : targets.items()) {
    if (!target.is_number()) continue;
    text += fmt::format("{}{} {:g}", text.empty() ? "" : ", ", solver, target.get<double>());
  }
  return text.empty() ? "none recorded" : text;
}

}  // namespace

void add_mutation(Document& out, const json& document) {
  if (!document.contains(key::mutation)) return;
  const json& m = document[key::mutation];
  out.push_back(Heading{2, "Mutation score", "mutation"});
  const json& exact = m[key::exact_with_witness];
  const Tally target{exact.value(key::made, 0), exact.value(key::caught, 0)};
  const json beyond_json = m.value(key::exact_beyond_estimate, json::object());
  const Tally beyond{beyond_json.value(key::made, 0), beyond_json.value(key::caught, 0)};
  out.push_back(Paragraph{fmt::format(
      "One result at a time made wrong, then the scene's checks re-run on the mutated results "
      "(nothing re-solved): "
      "a frequency by {:g} x its solver's accuracy target (the exact solvers' at their default "
      "knobs: {}, a scene's knobs may set another; {} their model-error estimate), a "
      "mode shape by a mix with its neighbour so that 1 - MAC is {:g} x the "
      "widest MAC tolerance, a forced max |tension| by {:g} relative. Caught: some check of the "
      "scene went to FAIL "
      "(docs/explanation/mutation.md). Exact solvers ({}) where another exact "
      "solver ran: {} of {} caught "
      "({}); of those, the changes larger than the mutated value's own error estimate (beyond what "
      "its solver "
      "claims): {} of {} caught ({}). {:.1f} s on {} threads.",
      m.value(key::frequency_factor, 0.0), default_targets_text(m),
      fmt::join(solver_names(SolverKind::Model), " and "), m.value(key::shape_factor, 0.0),
      m.value(key::forced_tension_relative, 0.0), fmt::join(solver_names(SolverKind::Exact), ", "),
      target.caught, target.made, percent(target), beyond.caught, beyond.made, percent(beyond),
      m.value(key::wall_time_s, 0.0), m.value(key::threads, 0))});
  std::map<std::pair<std::string, std::string>, Tally> by_family, by_quantity;
  for (const auto& t : list_or_empty(m, key::tallies)) {
    for (auto* table : {&by_family, &by_quantity}) {
      Tally& tally = (*table)[{t.value(key::solver, ""),
                               t.value(table == &by_family ? key::family : key::quantity, "")}];
      tally.made += t.value(key::made, 0);
      tally.caught += t.value(key::caught, 0);
    }
  }
  add_tally_table(out, "family", by_family);
  add_tally_table(out, "quantity", by_quantity);
  add_uncaught(out, list_or_empty(m, key::uncaught));
}

}  // namespace catena::internal
