// SPDX-License-Identifier: MIT
// The natural frequencies behind the forced check's condition number: see
// forced_conditioning_solve.hpp and docs/reference/verdicts.md.
#include "verification/internal/forced_conditioning_solve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "catena/core/error.hpp"

namespace catena {

bool ForcedConditioning::covers(double omega) const {
  return !omegas_rad_s.empty() && omegas_rad_s.back() > omega;
}

double ForcedConditioning::condition(double omega) const {
  if (!covers(omega)) return 1.0;
  double kappa = 1.0;
  for (std::size_t n = 0; n < omegas_rad_s.size(); ++n) {
    const double wn = omegas_rad_s[n];
    if (n < decay_rates_1_s.size() && decay_rates_1_s[n] > 0.0) {
      // Damped: |lambda_n|^2 - Omega^2 + 2 i delta_n Omega, finite at resonance.
      const double delta = decay_rates_1_s[n];
      const double modulus2 = wn * wn + delta * delta;
      const double distance = std::hypot(modulus2 - omega * omega, 2.0 * delta * omega);
      if (distance == 0.0) return std::numeric_limits<double>::infinity();
      kappa = std::max(kappa, 2.0 * modulus2 / distance);
      continue;
    }
    const double distance = std::abs(wn * wn - omega * omega);
    if (distance == 0.0) return std::numeric_limits<double>::infinity();
    kappa = std::max(kappa, 2.0 * wn * wn / distance);
  }
  return kappa;
}

namespace internal {

std::size_t doubling_count(const std::vector<double>& omegas, double top) {
  std::size_t count = kFirstConditioningModes;
  while (count < omegas.size() && omegas[count - 1] <= top) count *= 2;
  return std::min(count, omegas.size());
}

// It only skips solves: the list is cut back to the doubling's count afterwards (doubling_count),
// so the frequencies kept are those the plain doubling keeps. A Gale C-2 catenary forced up to
// 105 sqrt(g/a) no longer pays for the 16- and 32-mode solves before its 64-mode one (8% of that
// scene's CPU time: the 64-mode solve dominates).
int next_count(int solved, double highest, double top) {
  const double predicted = highest > 0.0 ? solved * top / highest : 2.0 * solved;
  int count = 2 * solved;
  while (count < kMostConditioningModes && count < predicted) count *= 2;
  return std::min(count, kMostConditioningModes);
}

namespace {

constexpr double kAboveForcing = 1.05;
// The work spent on the condition number is bounded: at most kMostConditioningModes (64), within
// 10 s per scene (frobenius took 630 s for the 128 modes below 100 sqrt(g/a) on a Gale C-2
// catenary). Beyond that the conditioning is unknown and the check keeps its strictest tolerance.
constexpr double kBudgetSeconds = 10.0;

// The scene's limits, with a deadline no later than the conditioning budget.
RunLimits conditioning_limits(const RunLimits& scene) {
  RunLimits limits = RunLimits::time_limit(kBudgetSeconds);
  if (scene.deadline && *scene.deadline < *limits.deadline) limits = scene;
  return limits;
}

// The exact solvers that ran and converged, most accurate (smallest declared accuracy) first.
std::vector<const SolverOutput*> exact_candidates(const SceneResult& result,
                                                  const ToleranceTable& tolerances) {
  std::vector<const SolverOutput*> out;
  for (const SolverOutput& output : result.outputs) {
    const SolverAccuracy* declared = tolerances.solver(output.solver);
    if (declared && declared->exact && output.summary.termination == Termination::Converged)
      out.push_back(&output);
  }
  std::stable_sort(out.begin(), out.end(), [&](const SolverOutput* a, const SolverOutput* b) {
    return tolerances.solver(a->solver)->accuracy < tolerances.solver(b->solver)->accuracy;
  });
  return out;
}

std::vector<double> frequencies(const std::optional<ModalResult>& modal) {
  std::vector<double> out;
  if (modal) {
    for (const Mode& mode : modal->modes) out.push_back(mode.omega_rad_s);
  }
  return out;
}

// The decay rates of the same modes; empty when none is positive (an undamped line).
std::vector<double> decay_rates(const std::optional<ModalResult>& modal) {
  std::vector<double> out;
  bool damped = false;
  if (modal) {
    for (const Mode& mode : modal->modes) {
      out.push_back(mode.decay_rate_1_s);
      damped = damped || mode.decay_rate_1_s > 0.0;
    }
  }
  return damped ? out : std::vector<double>{};
}

// The forced plane's modes of `solver`, solved for: the lowest kFirstConditioningModes, then more
// (next_count) until the top one lies above `top`, cut back to the count the doubling from
// kFirstConditioningModes would stop at. Empty when the solver gives none (or throws on the
// request).
std::vector<double> solve_modes(const SceneResult& result,
                                const std::string& solver,
                                Plane plane,
                                double top,
                                const RunLimits& limits,
                                std::vector<double>& deltas) {
  const SolverEntry* entry = find_solver(solver);
  if (!entry) return {};
  SolveRequest request = result.request;
  request.forced.reset();
  request.shapes = false;
  request.tension = false;
  const SolverKnobs knobs =
      result.scene.solvers.count(solver) ? result.scene.solvers.at(solver) : SolverKnobs{};
  std::vector<double> omegas;
  int solved = 0;  // the count behind `omegas`
  for (int count = kFirstConditioningModes;;) {
    request.inplane_modes = plane == Plane::InPlane ? count : 0;
    request.outofplane_modes = plane == Plane::OutOfPlane ? count : 0;
    const SolveContext context{result.scene.problem, *result.statics, *result.groups, request,
                               &limits};
    try {
      const SolverOutput output = run_solver(*entry, context, knobs);
      if (!output.summary.is_usable()) return {};
      omegas = frequencies(plane == Plane::InPlane ? output.inplane : output.outofplane);
      deltas = decay_rates(plane == Plane::InPlane ? output.inplane : output.outofplane);
      solved = count;
    } catch (const InvalidInput&) {
      // More modes than the solver resolves: keep the last list, after trying the doubling's
      // own next count when this one skipped it.
      if (solved == 0 || count == 2 * solved) break;
      count = 2 * solved;
      continue;
    }
    if ((!omegas.empty() && omegas.back() > top) || limits.expired() ||
        count >= kMostConditioningModes)
      break;
    count = next_count(count, omegas.empty() ? 0.0 : omegas.back(), top);
  }
  omegas.resize(doubling_count(omegas, top));
  if (!deltas.empty()) deltas.resize(omegas.size());
  return omegas;
}

}  // namespace

// The modes up to above the forcing: from the result of the most accurate exact solver whose
// output holds them, else solved for. The solve asks an exact solver that gives all modes at once
// first (fe), whether or not the scene ran it: kappa needs the frequencies to ~1e-4 only (a
// relative delta moves kappa by ~kappa x delta), and fe gives 64 modes of a Gale C-2 catenary in
// 0.04 s where frobenius took 3.9 s (and stopped at 40 modes, the top ones beyond its target) and
// shooting 2.2 s.
ForcedConditioning find_forced_conditioning(const SceneResult& result,
                                            const ToleranceTable& tolerances,
                                            const RunLimits& limits) {
  ForcedConditioning out;
  if (!result.request.forced || result.request.forced->omegas_rad_s.empty() || !result.statics)
    return out;
  const ForcedRequest& forced = *result.request.forced;
  out.plane = forced.direction == ForcingDirection::OutOfPlane ? Plane::OutOfPlane : Plane::InPlane;
  const double top =
      kAboveForcing * *std::max_element(forced.omegas_rad_s.begin(), forced.omegas_rad_s.end());
  const auto keep = [&](const std::string& solver, std::vector<double> omegas,
                        std::vector<double> deltas, const char* how) {
    out.solver = solver;
    out.omegas_rad_s = std::move(omegas);
    out.decay_rates_1_s = std::move(deltas);
    out.note = fmt::format("{} lowest {} natural frequencies of {} ({}), up to {:.6g} rad/s",
                           out.omegas_rad_s.size(), to_string(out.plane), out.solver, how,
                           out.omegas_rad_s.back());
    return out;
  };
  const std::vector<const SolverOutput*> candidates = exact_candidates(result, tolerances);
  for (const SolverOutput* candidate : candidates) {
    const auto& modal = out.plane == Plane::InPlane ? candidate->inplane : candidate->outofplane;
    std::vector<double> omegas = frequencies(modal);
    if (!omegas.empty() && omegas.back() > top)
      return keep(candidate->solver, std::move(omegas), decay_rates(modal), "from its result");
  }
  // The exact solvers that give all modes at once first (SolverEntry::all_modes_at_once), then
  // the candidates.
  std::vector<std::string> solvers;
  for (const SolverEntry& entry : solver_registry())
    if (entry.kind == SolverKind::Exact && entry.all_modes_at_once) solvers.push_back(entry.name);
  for (const SolverOutput* candidate : candidates)
    if (std::find(solvers.begin(), solvers.end(), candidate->solver) == solvers.end())
      solvers.push_back(candidate->solver);
  const RunLimits budget = conditioning_limits(limits);
  for (const std::string& solver : solvers) {
    std::vector<double> deltas;
    std::vector<double> omegas = solve_modes(result, solver, out.plane, top, budget, deltas);
    if (!omegas.empty())
      return keep(solver, std::move(omegas), std::move(deltas), "solved for the condition number");
  }
  out.note = "no exact solver gave the natural frequencies of the forced plane";
  return out;
}

}  // namespace internal
}  // namespace catena
