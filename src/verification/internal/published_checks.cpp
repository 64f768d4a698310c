// SPDX-License-Identifier: MIT
#include "verification/internal/published_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace catena::internal {
namespace {

// Two solvers "confirm each other" against a published value when they differ by less than this
// fraction of their distance to it.
constexpr double kConfirmationRatio = 0.1;

// The value a solver gives for a published entry, in the entry's unit.
std::optional<double> solver_value(const SceneResult& result,
                                   const SolverOutput& output,
                                   const PublishedValues& published,
                                   int mode) {
  if (published.quantity == PublishedQuantity::ForcedMaxTension) {
    if (mode < 0 || mode >= static_cast<int>(output.forced.size())) return std::nullopt;
    const ForcedResponse& response = output.forced[static_cast<std::size_t>(mode)];
    if (!response.diagnostic.empty()) return std::nullopt;
    return response.max_abs_tension_n / result.statics->horizontal_force_n();
  }
  const ModalResult* m = modal_of(output, published.quantity == PublishedQuantity::InPlaneFrequency
                                              ? Plane::InPlane
                                              : Plane::OutOfPlane);
  if (!m) return std::nullopt;
  for (const auto& x : m->modes) {
    if (x.index == mode) return from_rad_per_second(x.omega_rad_s, published.unit, *result.groups);
  }
  return std::nullopt;
}

// True when `solver` returned published frequency `mode` marked beyond its own accuracy target
// (Mode::meets_target; docs/reference/verdicts.md, "Declared misses").
bool declared_miss(const SceneResult& result,
                   const std::string& solver,
                   const PublishedValues& published,
                   int mode) {
  if (published.quantity == PublishedQuantity::ForcedMaxTension) return false;
  const Plane plane = published.quantity == PublishedQuantity::InPlaneFrequency ? Plane::InPlane
                                                                                : Plane::OutOfPlane;
  for (const auto& output : result.outputs) {
    const ModalResult* m = output.solver == solver ? modal_of(output, plane) : nullptr;
    if (!m) continue;
    for (const auto& x : m->modes) {
      if (x.index == mode) return !x.meets_target;
    }
  }
  return false;
}

// The compared quantity (SolverEntry::computations) and the cross-check kind of a published column.
std::pair<std::string, std::string> quantity_and_check(PublishedQuantity quantity) {
  switch (quantity) {
    case PublishedQuantity::InPlaneFrequency:
      return {"frequency-in-plane", "frequency"};
    case PublishedQuantity::OutOfPlaneFrequency:
      return {"frequency-out-of-plane", "frequency"};
    case PublishedQuantity::ForcedMaxTension:
      return {"forced", "forced"};
  }
  return {"", ""};
}

// Every usable solver's value for one published entry: solver -> value.
using PublishedCandidates = std::map<std::string, double>;

// The pair tolerance a confirmation is held to: for a forced entry the conditioned one at the
// forcing frequency (none where the response is at resonance, not checkable).
std::optional<double> pair_tolerance(const CheckBuilder& builder,
                                     const std::string& check,
                                     const std::string& a,
                                     const std::string& b,
                                     double forcing_omega) {
  if (check != "forced") {
    const auto tol = builder.tolerance(check, a, b, std::nullopt);
    return tol ? std::optional(tol->value) : std::nullopt;
  }
  const auto tol = builder.forced_tolerance(a, b, forcing_omega);
  return tol && tol->checkable ? std::optional(tol->tolerance.value) : std::nullopt;
}

// A second solver that confirms `solver`'s value: an independent computation (not sharing the
// code path) that agrees with ours within their pair tolerance and far better
// (kConfirmationRatio) than ours agrees with the print. Empty when none does.
std::string confirming_solver(const CheckBuilder& builder,
                              PublishedQuantity published_quantity,
                              const std::string& solver,
                              const PublishedCandidates& values,
                              double measured,
                              double forcing_omega) {
  const double ours = values.at(solver);
  const auto [quantity, check] = quantity_and_check(published_quantity);
  std::string partner;
  for (const auto& [other, other_value] : values) {
    if (other == solver || builder.shared(solver, other, quantity)) continue;
    const double between = std::abs(other_value - ours);
    const auto pair_tol = pair_tolerance(builder, check, solver, other, forcing_omega);
    if (pair_tol && between <= *pair_tol * std::abs(ours) &&
        between <= kConfirmationRatio * measured) {
      partner = other;
    }
  }
  return partner;
}

// True when every other independent solver's forced pair check with `solver` at this forcing
// frequency is "at resonance, not checkable".
bool at_resonance_for_all(const CheckBuilder& builder,
                          const std::string& solver,
                          const PublishedCandidates& values,
                          double forcing_omega) {
  bool any = false;
  for (const auto& [other, value] : values) {
    if (other == solver || builder.shared(solver, other, "forced")) continue;
    const auto tol = builder.forced_tolerance(solver, other, forcing_omega);
    if (!tol || tol->checkable) return false;
    any = true;
  }
  return any;
}

// Beyond the printed digits: a source discrepancy when confirmed by a second solver or by a
// reviewed finding that still matches our value; a failure otherwise.
void judge_disagreement(const CheckBuilder& builder,
                        const PublishedValues& published,
                        const std::string& solver,
                        const PublishedCandidates& values,
                        int mode,
                        CheckResult& check) {
  const double ours = values.at(solver);
  const auto& forced = builder.result().request.forced;
  const double forcing_omega =
      forced && mode >= 0 && mode < static_cast<int>(forced->omegas_rad_s.size())
          ? forced->omegas_rad_s[static_cast<std::size_t>(mode)]
          : 0.0;
  const std::string partner =
      confirming_solver(builder, published.quantity, solver, values, check.measured, forcing_omega);
  const Finding* finding = builder.findings().find(builder.result().scene.name,
                                                   to_string(published.quantity), mode, solver);
  if (!partner.empty()) {
    check.verdict = Verdict::SourceDiscrepancy;
    check.detail += fmt::format("; confirmed by {} = {:.8g}", partner, values.at(partner));
  } else if (finding && relative_difference(finding->ours, ours) <= 1e-6) {
    check.verdict = Verdict::SourceDiscrepancy;
    check.detail += "; reviewed finding: " + finding->diagnosis;
  } else if (finding) {
    check.verdict = Verdict::Fail;
    check.detail += fmt::format("; stale finding (reviewed value {:.8g})", finding->ours);
  } else if (published.quantity == PublishedQuantity::ForcedMaxTension &&
             at_resonance_for_all(builder, solver, values, forcing_omega)) {
    // No second solver can confirm or refute a response at resonance (docs/reference/verdicts.md,
    // "Forced response: conditioning"): the same WARN as the forced pair checks there.
    check.verdict = Verdict::Warn;
    check.detail += "; at resonance, not checkable: no second solver can confirm it";
  } else {
    check.verdict = Verdict::Fail;
  }
}

const char* published_plane(PublishedQuantity quantity) {
  switch (quantity) {
    case PublishedQuantity::InPlaneFrequency:
      return "in-plane";
    case PublishedQuantity::OutOfPlaneFrequency:
      return "out-of-plane";
    case PublishedQuantity::ForcedMaxTension:
      return "forced";
  }
  return "";
}

// The tolerance: the printed rounding half-width, plus the rule's stated `max` (absolute, in the
// table's unit), plus its model term relative to our value.
void published_entry(CheckBuilder& builder,
                     const PublishedValues& published,
                     const std::string& solver,
                     const PublishedCandidates& values,
                     int mode,
                     double printed) {
  const SceneResult& result = builder.result();
  const double half_unit =
      published.decimals >= 0 ? 0.5 * std::pow(10.0, -published.decimals) : 0.0;
  const double ours = values.at(solver);
  const ToleranceRule* rule = builder.tolerances().find("published", solver, "published",
                                                        result.scene.name, result.scene.tags);
  const double slack =
      rule ? rule->max + rule->model_term(model_parameters(result)) * std::abs(ours) : 0.0;
  const bool forced = published.quantity == PublishedQuantity::ForcedMaxTension;
  CheckResult check = builder.base("published", solver + " vs " + published.source,
                                   published_plane(published.quantity), forced ? mode + 1 : mode);
  check.value_a = ours;
  check.value_b = printed;
  check.measured = std::abs(ours - printed);
  check.tolerance = half_unit + slack;
  check.detail =
      fmt::format("ours {:.8g}, printed {} ({} decimals; absolute difference, in the table's unit)",
                  ours, printed, published.decimals);
  if (!std::isfinite(ours)) {
    check.verdict = Verdict::Fail;
  } else if (check.measured <= check.tolerance) {
    check.verdict = Verdict::Pass;
  } else {
    judge_disagreement(builder, published, solver, values, mode, check);
    if (check.verdict == Verdict::Fail && declared_miss(result, solver, published, mode)) {
      check.verdict = Verdict::Warn;
      check.detail += "; declared beyond its solver's accuracy target (missed_modes)";
    }
  }
  builder.add(check);
}

}  // namespace

void published_checks(CheckBuilder& builder) {
  const SceneResult& result = builder.result();
  for (const auto& published : result.scene.published) {
    for (std::size_t k = 0; k < published.values.size(); ++k) {
      const int mode = published.modes[k];
      // Every usable solver's value (for confirmation), and the designated ones (to check).
      PublishedCandidates values;
      for (const auto& output : result.outputs) {
        if (!output.summary.is_usable()) continue;
        if (auto v = solver_value(result, output, published, mode)) values[output.solver] = *v;
      }
      for (const auto& [solver, value] : values) {
        const auto& only = published.compare_with;
        if (!only.empty() && std::find(only.begin(), only.end(), solver) == only.end()) continue;
        published_entry(builder, published, solver, values, mode, published.values[k]);
      }
    }
  }
}

}  // namespace catena::internal
