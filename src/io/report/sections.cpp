// SPDX-License-Identifier: MIT
#include "io/report/sections.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace catena::internal {
namespace {

int count_checks(const json& scene, const std::string& verdict) {
  int count = 0;
  for (const auto& check : scene[key::checks]) count += check.value(key::verdict, "") == verdict;
  return count;
}

struct SolverStats {
  int run = 0, converged = 0, declined = 0, failed = 0;
  double time_s = 0.0, max_estimate = 0.0;
  std::vector<double> times_s;
};

void add_to_stats(const json& summary, SolverStats& s) {
  const std::string termination = summary.value(key::termination, "");
  if (termination == "not-applicable") {
    ++s.declined;
    return;
  }
  ++s.run;
  s.converged += termination == "converged";
  s.failed += termination == "numerical-failure";
  const double t = summary.value(key::wall_time_s, 0.0);
  s.time_s += t;
  s.times_s.push_back(t);
  if (summary[key::max_error_estimate].is_number()) {
    s.max_estimate = std::max(s.max_estimate, summary[key::max_error_estimate].get<double>());
  }
}

// The unit a scene's frequencies read best in: its published unit, Gale's ratio for Gale
// scenes, kL/pi for taut-inclined ones, rad/s otherwise.
std::string display_unit(const json& scene) {
  for (const auto& p : list_or_empty(scene, key::published)) {
    if (p.value(key::quantity, "") != "forced_max_tension") return p.value(key::unit, "rad/s");
  }
  if (has_tag(scene, "gale")) return "gale";
  if (has_tag(scene, "taut-inclined")) return "kL/pi";
  return "rad/s";
}

std::string scene_info(const json& scene) {
  std::string info = scene.value(key::description, "");
  if (scene.contains(key::groups)) {
    const json& g = scene[key::groups];
    info +=
        fmt::format(" — eps = {}, phi_a = {} deg, lambda^2 = {}, h = {}", number_text(g[key::eps]),
                    number_text(g[key::chord_angle_deg]),
                    g[key::lambda2].is_null() ? std::string("inf") : number_text(g[key::lambda2]),
                    number_text(g[key::mass_ratio]));
    if (g.contains(key::gale)) {
      info += fmt::format(", Gale xi = ({}, {})", number_text(g[key::gale][key::xi1], "{:.4f}"),
                          number_text(g[key::gale][key::xi2], "{:.4f}"));
    }
  }
  if (!scene[key::error].is_null()) info += " — ERROR: " + scene[key::error].get<std::string>();
  return info + fmt::format(" — {} checks, {} failed.", scene[key::checks].size(),
                            count_checks(scene, "FAIL"));
}

// The published value of `mode` in `entry`, or "-".
std::string published_cell(const json& entry, std::size_t mode) {
  for (std::size_t k = 0; k < entry.at(key::modes).size(); ++k) {
    if (entry.at(key::modes)[k].get<int>() == static_cast<int>(mode)) {
      return number_text(entry.at(key::values)[k], "{:g}");
    }
  }
  return "-";
}

// One plane's frequencies: a column per solver and per published source, a row per mode.
void add_frequency_table(Document& out,
                         const json& scene,
                         const char* plane,
                         const std::string& unit) {
  std::vector<std::string> solvers;
  std::size_t modes = 0;
  for (const auto& [solver, output] : scene[key::solvers].items()) {
    if (!output.contains(plane)) continue;
    solvers.push_back(solver);
    modes = std::max(modes, output[plane][key::modes].size());
  }
  std::vector<const json*> published;
  for (const auto& p : list_or_empty(scene, key::published)) {
    if (p.value(key::quantity, "") == std::string(plane) + "_frequency") published.push_back(&p);
  }
  if (solvers.empty() && published.empty()) return;
  const std::string title = std::string(plane) == key::inplane ? "in-plane" : "out-of-plane";
  Table t{{title + " mode [" + unit + "]"}, {}, "frequencies"};
  for (const auto& s : solvers) t.header.push_back(s);
  for (const auto* p : published) {
    t.header.push_back(p->value(key::source, "published"));
    const json& listed = p->at(key::modes);
    modes =
        std::max(modes, static_cast<std::size_t>(*std::max_element(listed.begin(), listed.end())));
  }
  for (std::size_t i = 0; i < modes; ++i) {
    std::vector<std::string> row = {std::to_string(i + 1)};
    for (const auto& s : solvers) {
      const json& list = scene[key::solvers][s][plane][key::modes];
      row.push_back(i < list.size() ? number_text(mode_value(list[i], unit), "{:.8g}") : "-");
    }
    for (const auto* p : published) row.push_back(published_cell(*p, i + 1));
    t.rows.push_back(row);
  }
  out.push_back(t);
}

// Forced response maxima max|tau|/H per forcing frequency, a column per solver.
void add_forced_table(Document& out, const json& scene) {
  std::vector<std::string> solvers;
  for (const auto& [solver, output] : scene[key::solvers].items()) {
    if (output.contains(key::forced)) solvers.push_back(solver);
  }
  if (solvers.empty()) return;
  Table t{{"forcing [rad/s]"}, {}, "forced"};
  // A damped response is complex: its max |tau| is the largest modulus along the line.
  const char* column = is_damped_scene(scene) ? " max|tau|/H (modulus)" : " max|tau|/H";
  for (const auto& s : solvers) t.header.push_back(s + column);
  const json& first = scene[key::solvers][solvers[0]][key::forced];
  const double H = scene[key::statics].value(key::horizontal_force_n, 1.0);
  for (std::size_t i = 0; i < first.size(); ++i) {
    std::vector<std::string> row = {number_text(first[i][key::omega_rad_s])};
    for (const auto& s : solvers) {
      const json& list = scene[key::solvers][s][key::forced];
      if (i >= list.size()) {
        row.push_back("-");
        continue;
      }
      const std::string diagnostic = list[i].value(key::diagnostic, "");
      row.push_back(diagnostic.empty()
                        ? fmt::format("{:.6g}", list[i].value(key::max_abs_tension_n, 0.0) / H)
                        : diagnostic);
    }
    t.rows.push_back(row);
  }
  out.push_back(t);
}

}  // namespace

void add_summary(Document& out, const json& document) {
  std::map<std::string, int> verdicts;
  int total = 0;
  for (const auto& scene : document[key::scenes]) {
    for (const auto& check : scene[key::checks]) ++verdicts[check.value(key::verdict, "?")];
  }
  for (const auto& [verdict, count] : verdicts) total += count;
  const json& meta = document[key::catena];
  out.push_back(Heading{1, "Catena verification report", "top"});
  out.push_back(Paragraph{fmt::format(
      "catena {} (git {}) · {} · {} · {} · {} scenes, {} checks, {} failed, {} source "
      "discrepancies",
      meta.value(key::version, "?"), meta.value(key::git, "?"), meta.value(key::compiler, "?"),
      meta.value(key::build_type, "?"), meta.value(key::generated_utc, "?"),
      document[key::scenes].size(), total, verdicts["FAIL"], verdicts["SOURCE"])});
  Table t{{"verdict", "checks", "meaning"}, {}, "summary"};
  const std::map<std::string, std::string> meaning = {
      {"PASS", "within tolerance"},
      {"FAIL", "beyond tolerance: a defect of ours"},
      {"SOURCE", "a published value contradicted by our agreeing solvers (or a reviewed finding)"},
      {"WARN", "beyond tolerance for a documented reason"},
      {"SKIP", "not evaluated (reason given)"}};
  for (const auto& [verdict, text] : meaning)
    t.rows.push_back({verdict, std::to_string(verdicts[verdict]), text});
  out.push_back(t);
}

void add_solvers(Document& out, const json& document) {
  out.push_back(Heading{2, "Solvers", "solvers"});
  std::map<std::string, SolverStats> stats;
  for (const auto& scene : document[key::scenes]) {
    for (const auto& [solver, output] : scene[key::solvers].items())
      add_to_stats(output[key::summary], stats[solver]);
  }
  Table t{{"solver", "scenes run", "converged", "failed", "declined (not applicable)",
           "median time [ms]", "total time [s]", "largest error estimate"},
          {},
          "solvers"};
  for (auto& [solver, s] : stats) {
    std::sort(s.times_s.begin(), s.times_s.end());
    const double median = s.times_s.empty() ? 0.0 : s.times_s[s.times_s.size() / 2];
    t.rows.push_back({solver, std::to_string(s.run), std::to_string(s.converged),
                      std::to_string(s.failed), std::to_string(s.declined),
                      fmt::format("{:.3g}", median * 1e3), fmt::format("{:.3g}", s.time_s),
                      fmt::format("{:.2e}", s.max_estimate)});
  }
  out.push_back(t);
}

void add_failures(Document& out, const json& document) {
  out.push_back(Heading{2, "Failures and warnings", "failures"});
  Table t{
      {"scene", "check", "compared", "plane", "mode", "measured", "tolerance", "verdict", "detail"},
      {},
      "failures"};
  for (const auto& scene : document[key::scenes]) {
    const std::string name = scene.value(key::name, "");
    if (!scene[key::error].is_null()) {
      t.rows.push_back(
          {name, "scene", "-", "-", "-", "-", "-", "FAIL", scene[key::error].get<std::string>()});
    }
    for (const auto& check : scene[key::checks]) {
      const std::string verdict = check.value(key::verdict, "");
      if (verdict != "FAIL" && verdict != "WARN") continue;
      t.rows.push_back({name, check.value(key::check, ""), check.value(key::compare, ""),
                        check.value(key::plane, ""), std::to_string(check.value(key::mode, 0)),
                        number_text(check[key::measured], "{:.3e}"),
                        number_text(check[key::tolerance], "{:.3e}"), verdict,
                        check.value(key::detail, "")});
    }
  }
  add_table_or_none(out, std::move(t));
}

void add_stress_outcomes(Document& out, const json& document) {
  Table t{{"stress scene", "solver", "outcome", "failed checks", "message"}, {}, "stress"};
  for (const auto& scene : document[key::scenes]) {
    if (!has_tag(scene, "stress")) continue;
    for (const auto& [solver, output] : scene[key::solvers].items()) {
      int failed = 0;
      for (const auto& check : scene[key::checks]) {
        failed += check.value(key::verdict, "") == "FAIL" &&
                  check.value(key::compare, "").find(solver) != std::string::npos;
      }
      const std::string termination = output[key::summary].value(key::termination, "");
      const std::string outcome = termination == "converged"        ? (failed ? "FAIL" : "accurate")
                                  : termination == "not-applicable" ? "declined"
                                                                    : "diagnosed";
      std::string message = output[key::summary].value(key::message, "");
      if (message.size() > 160) message = message.substr(0, 157) + "...";
      t.rows.push_back(
          {scene.value(key::name, ""), solver, outcome, std::to_string(failed), message});
    }
  }
  if (t.rows.empty()) return;
  out.push_back(Heading{2, "Stress suite outcomes", "stress"});
  out.push_back(Paragraph{
      "Each solver on each stress scene: accurate (all its checks pass), diagnosed (a "
      "clear numerical diagnostic instead of a number), or declined (outside its model)."});
  out.push_back(t);
}

void add_time_to_accuracy(Document& out, const TimeToAccuracy& timing) {
  if (timing.cases.empty()) return;
  out.push_back(Heading{2, "Time to accuracy", "time-to-accuracy"});
  // The reference of the error is the file's to state (its first comment line).
  out.push_back(Paragraph{fmt::format(
      "Fastest wall time for each solver to reach a relative error on the first six in-plane "
      "frequencies (benchmarks/results/time-vs-error.csv: {}; 'cannot': no setting reached it).",
      timing.description)});
  Table t{{"case", "solver", "1e-3", "1e-6", "1e-9"}, {}, "timing"};
  for (const auto& name : timing.cases) {
    if (!timing.best_time_s.count(name)) continue;
    for (const auto& [solver, targets] : timing.best_time_s.at(name)) {
      std::vector<std::string> row = {name, solver};
      for (double target : kAccuracyTargets) {
        row.push_back(targets.count(target) ? fmt::format("{:.3g} ms", targets.at(target) * 1e3)
                                            : "cannot");
      }
      t.rows.push_back(row);
    }
  }
  out.push_back(t);
}

void add_scenes(Document& out, const json& document) {
  out.push_back(Heading{2, "Scenes", "scenes"});
  for (const auto& scene : document[key::scenes]) {
    const std::string name = scene.value(key::name, "");
    out.push_back(Heading{3, name, name});
    out.push_back(Paragraph{scene_info(scene)});
    const std::string unit = display_unit(scene);
    for (const char* plane : {key::inplane, key::outofplane})
      add_frequency_table(out, scene, plane, unit);
    add_damping_tables(out, scene);
    add_forced_table(out, scene);
    add_dynamic_tension_table(out, scene);
  }
}

}  // namespace catena::internal
