// SPDX-License-Identifier: MIT
#include "cli/solve_table_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

#include "catena/solvers/solver_registry.hpp"

namespace catena::cli {
namespace {

int severity(Verdict verdict) {
  switch (verdict) {
    case Verdict::Fail:
      return 4;
    case Verdict::SourceDiscrepancy:
      return 3;
    case Verdict::Warn:
      return 2;
    case Verdict::Pass:
      return 1;
    case Verdict::Skipped:
      return 0;
  }
  return 0;
}

bool is_exact(const std::string& solver) {
  const SolverEntry* entry = find_solver(solver);
  return entry != nullptr && entry->kind == SolverKind::Exact;
}

const ModalResult* plane_result(const SolverOutput& output, Plane plane) {
  const auto& result = plane == Plane::InPlane ? output.inplane : output.outofplane;
  return result && (!result->modes.empty() || !result->overdamped.empty()) ? &*result : nullptr;
}

// The table's solver columns: the outputs `has` accepts, in the run's order.
SolverTable table_of(const SceneResult& result,
                     const std::function<bool(const SolverOutput&)>& has) {
  SolverTable table;
  for (const auto& output : result.outputs) {
    if (!has(output)) continue;
    table.solvers.push_back(output.solver);
    table.exact.push_back(is_exact(output.solver));
  }
  return table;
}

const SolverOutput& output_of(const SceneResult& result, const std::string& solver) {
  return *std::find_if(result.outputs.begin(), result.outputs.end(),
                       [&](const SolverOutput& o) { return o.solver == solver; });
}

const Mode* mode_at(const ModalResult& modes, int index) {
  for (const auto& mode : modes.modes)
    if (mode.index == index) return &mode;
  return nullptr;
}

}  // namespace

std::string row_verdict(const std::vector<CheckResult>& checks,
                        const std::string& place,
                        int index) {
  const CheckResult* worst = nullptr;
  for (const auto& check : checks) {
    if (check.plane != place || check.mode != index) continue;
    if (!worst || severity(check.verdict) > severity(worst->verdict)) worst = &check;
  }
  return worst ? to_string(worst->verdict) : std::string();
}

FrequencyUnit usable_unit(const SceneResult& result, FrequencyUnit wanted) {
  for (const auto& output : result.outputs)
    for (const ModalResult* modes :
         {plane_result(output, Plane::InPlane), plane_result(output, Plane::OutOfPlane)}) {
      if (!modes) continue;
      for (const auto& mode : modes->modes)
        if (!in_unit(mode, wanted)) return FrequencyUnit::RadPerSecond;
    }
  return wanted;
}

std::optional<SolverTable> modal_table(const SceneResult& result,
                                       Plane plane,
                                       FrequencyUnit unit,
                                       const std::string& reference) {
  SolverTable table = table_of(
      result, [plane](const SolverOutput& o) { return plane_result(o, plane) != nullptr; });
  if (table.solvers.empty()) return std::nullopt;
  const bool damped = result.scene.problem.is_damped();
  table.title = fmt::format(
      "{} modes{}", to_string(plane),
      damped ? ", damped: omega_d = Im lambda, delta = -Re lambda, zeta = delta / |lambda|" : "");
  table.unit = unit_label(unit);
  const bool has_reference =
      std::find(table.solvers.begin(), table.solvers.end(), reference) != table.solvers.end();
  const std::string delta_solver = has_reference ? reference : table.solvers.front();
  const ModalResult& delta_modes = *plane_result(output_of(result, delta_solver), plane);
  if (damped) table.extra_headers = {delta_solver + " delta [1/s]", delta_solver + " zeta"};
  int top = 0;
  for (const auto& solver : table.solvers)
    for (const auto& mode : plane_result(output_of(result, solver), plane)->modes)
      top = std::max(top, mode.index);
  for (int index = 1; index <= top; ++index) {
    TableRow row{
        std::to_string(index), {}, {}, row_verdict(result.checks, to_string(plane), index)};
    for (const auto& solver : table.solvers) {
      const Mode* mode = mode_at(*plane_result(output_of(result, solver), plane), index);
      const auto value = mode ? in_unit(*mode, unit) : std::nullopt;
      row.cells.push_back(value ? std::optional<TableCell>(TableCell{
                                      *value, mode->relative_error_estimate, mode->meets_target})
                                : std::nullopt);
    }
    if (damped) {
      const Mode* mode = mode_at(delta_modes, index);
      row.extra = {mode ? fmt::format("{:.10g}", mode->decay_rate_1_s) : "-",
                   mode ? fmt::format("{:.6g}", mode->damping_ratio) : "-"};
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::optional<SolverTable> forced_table(const SceneResult& result) {
  SolverTable table = table_of(result, [](const SolverOutput& o) { return !o.forced.empty(); });
  if (table.solvers.empty()) return std::nullopt;
  table.title = "forced response: max |tau| along the line";
  table.label_header = "omega [rad/s]";
  table.unit = "N";
  table.digits = 10;
  const auto& first = output_of(result, table.solvers.front()).forced;
  for (std::size_t i = 0; i < first.size(); ++i) {
    TableRow row{fmt::format("{:.10g}", first[i].omega_rad_s),
                 {},
                 {},
                 row_verdict(result.checks, "forced", static_cast<int>(i + 1))};
    for (const auto& solver : table.solvers) {
      const auto& forced = output_of(result, solver).forced;
      // At a resonance there is no finite response to show (the note under the table says so).
      const bool usable = i < forced.size() && !forced[i].at_resonance;
      row.cells.push_back(usable
                              ? std::optional<TableCell>(TableCell{
                                    forced[i].max_abs_tension_n, forced[i].relative_error_estimate})
                              : std::nullopt);
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::optional<SolverTable> dynamic_tension_table(const SceneResult& result) {
  SolverTable table =
      table_of(result, [](const SolverOutput& o) { return !o.dynamic_tension.empty(); });
  if (table.solvers.empty()) return std::nullopt;
  table.title = "dynamic tension at the ends (drag linearised to its fixed point)";
  table.label_header = "excitation, end, quantity";
  table.labels_left = true;
  table.digits = 8;
  const auto& first = output_of(result, table.solvers.front()).dynamic_tension;
  using Quantity = std::pair<const char*, double (*)(const DynamicTensionEnd&)>;
  const Quantity regular[] = {
      {"amplitude [N]", [](const DynamicTensionEnd& e) { return e.amplitude_n; }},
      {"max = mean + amplitude [N]",
       [](const DynamicTensionEnd& e) { return e.mean_n + e.amplitude_n; }}};
  const Quantity irregular[] = {
      {"std [N]", [](const DynamicTensionEnd& e) { return e.std_n; }},
      {"Tz [s]", [](const DynamicTensionEnd& e) { return e.zero_upcrossing_period_s; }},
      {"most probable max [N]", [](const DynamicTensionEnd& e) { return e.most_probable_max_n; }}};
  for (std::size_t k = 0; k < first.size(); ++k) {
    const std::string excitation = first[k].irregular
                                       ? std::string("irregular")
                                       : fmt::format("T = {:g} s", first[k].period_s);
    for (const bool fairlead : {true, false}) {
      const char* end = fairlead ? "fairlead" : "anchor";
      const std::string verdict = row_verdict(result.checks, end, static_cast<int>(k + 1));
      const auto add = [&](const Quantity& quantity) {
        TableRow row{fmt::format("{} {} {}", excitation, end, quantity.first), {}, {}, verdict};
        for (const auto& solver : table.solvers) {
          const auto& tensions = output_of(result, solver).dynamic_tension;
          const bool usable = k < tensions.size() && tensions[k].converged;
          row.cells.push_back(
              usable ? std::optional<TableCell>(TableCell{
                           quantity.second(fairlead ? tensions[k].fairlead : tensions[k].anchor),
                           tensions[k].relative_error_estimate})
                     : std::nullopt);
        }
        table.rows.push_back(std::move(row));
      };
      if (first[k].irregular)
        for (const auto& q : irregular) add(q);
      else
        for (const auto& q : regular) add(q);
    }
  }
  return table;
}

}  // namespace catena::cli
