// SPDX-License-Identifier: MIT
// The dynamic tension of a scene with a motion request in the report's scene section: per
// excitation and solver, the fairlead and anchor values (amplitude, or standard deviation and most
// probable maximum when irregular), the fixed point's iterations and residual, and the agreement
// the dynamic-tension checks measured at the fairlead (docs/reference/verdicts.md, "Dynamic
// tension"). A scene without a motion request gets none of it.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

// The JSON names of the dynamic tension (issue 30, docs/reference/json-layout.md): spelled here
// until io/results_keys.txt lists them with the writer's.
namespace dyn {
constexpr const char* dynamic_tension = "dynamic_tension";
constexpr const char* fairlead = "fairlead";
constexpr const char* anchor = "anchor";
constexpr const char* amplitude_n = "amplitude_n";
constexpr const char* std_n = "std_n";
constexpr const char* most_probable_max_n = "most_probable_max_n";
constexpr const char* period_s = "period_s";
constexpr const char* residual = "residual";
constexpr const char* converged = "converged";
}  // namespace dyn

// A solver's excitations: `dynamic_tension` is a list (one per period, or one irregular), or one
// object.
std::vector<const json*> excitations_of(const json& output) {
  std::vector<const json*> out;
  if (!output.is_object() || !output.contains(dyn::dynamic_tension)) return out;
  const json& value = output[dyn::dynamic_tension];
  if (value.is_array()) {
    for (const auto& item : value) out.push_back(&item);
  } else if (value.is_object()) {
    out.push_back(&value);
  }
  return out;
}

bool is_irregular(const json& excitation) {
  const json& end = excitation.value(dyn::fairlead, json());
  return end.is_object() && end.contains(dyn::std_n) && end[dyn::std_n].is_number() &&
         end[dyn::std_n].get<double>() >= 0.0;
}

std::string excitation_label(const json& excitation, std::size_t index) {
  if (is_irregular(excitation)) return "irregular";
  const json& period = excitation.value(dyn::period_s, json());
  return period.is_number() ? fmt::format("T = {:g} s", period.get<double>())
                            : fmt::format("excitation {}", index + 1);
}

// The value at one end: "amplitude" or "sigma (MPM max)".
std::string end_cell(const json& excitation, const char* end_key) {
  const json& end = excitation.value(end_key, json());
  if (!end.is_object()) return "-";
  if (!is_irregular(excitation)) return number_text(end.value(dyn::amplitude_n, json()), "{:.6g}");
  const json& mpm = end.value(dyn::most_probable_max_n, json());
  return mpm.is_number() ? fmt::format("{} (max {})", number_text(end[dyn::std_n], "{:.6g}"),
                                       number_text(mpm, "{:.6g}"))
                         : number_text(end[dyn::std_n], "{:.6g}");
}

std::string fixed_point_cell(const json& excitation) {
  const json& converged = excitation.value(dyn::converged, json());
  const std::string note = converged.is_boolean() && !converged.get<bool>() ? " NOT converged" : "";
  return fmt::format("{} / {}{}", number_text(excitation.value(key::iterations, json()), "{:g}"),
                     number_text(excitation.value(dyn::residual, json()), "{:.1e}"), note);
}

// The dynamic-tension checks at the fairlead of excitation `index` that involve `solver`:
// "vs <other> <measured> <verdict>", joined.
std::string agreement_cell(const json& scene, const std::string& solver, std::size_t index) {
  std::string out;
  for (const auto& check : list_or_empty(scene, key::checks)) {
    if (check.value(key::check, "") != "dynamic-tension" ||
        check.value(key::plane, "") != dyn::fairlead ||
        check.value(key::mode, 0) != static_cast<int>(index + 1))
      continue;
    const std::string compare = check.value(key::compare, "");
    const std::string a = solver + " vs ", b = " vs " + solver;
    std::string other;
    if (compare.rfind(a, 0) == 0) other = compare.substr(a.size());
    if (compare.size() > b.size() && compare.compare(compare.size() - b.size(), b.size(), b) == 0)
      other = compare.substr(0, compare.size() - b.size());
    if (other.empty()) continue;
    out += fmt::format("{}vs {} {} {}", out.empty() ? "" : "; ", other,
                       number_text(check.value(key::measured, json()), "{:.1e}"),
                       check.value(key::verdict, "?"));
  }
  return out.empty() ? "-" : out;
}

}  // namespace

void add_dynamic_tension_table(Document& out, const json& scene) {
  std::vector<std::pair<std::string, std::vector<const json*>>> solvers;
  std::size_t rows = 0;
  for (const auto& [solver, output] : scene[key::solvers].items()) {
    auto list = excitations_of(output);
    if (list.empty()) continue;
    rows = std::max(rows, list.size());
    solvers.emplace_back(solver, std::move(list));
  }
  if (solvers.empty()) return;
  Table t{{"excitation", "solver", "fairlead [N]", "anchor [N]", "iterations / residual",
           "agreement at the fairlead (relative)"},
          {},
          "dynamic-tension"};
  for (std::size_t i = 0; i < rows; ++i) {
    for (const auto& [solver, list] : solvers) {
      if (i >= list.size()) continue;
      const json& e = *list[i];
      t.rows.push_back({excitation_label(e, i), solver, end_cell(e, dyn::fairlead),
                        end_cell(e, dyn::anchor), fixed_point_cell(e),
                        agreement_cell(scene, solver, i)});
    }
  }
  out.push_back(Paragraph{
      "Dynamic tension with the drag linearised to its fixed point: the amplitude of the tension "
      "(regular motion), or its standard deviation with the most probable maximum in the "
      "request's duration (irregular), at the fairlead and the anchor."});
  out.push_back(t);
}

}  // namespace catena::internal
