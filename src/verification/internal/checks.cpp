#include "verification/internal/checks.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>

#include "catena/verification/findings.hpp"
#include "catena/verification/tolerance_table.hpp"

namespace catena::internal {
namespace {

// Statics closure |r(L) - (b - a)| relative to the cable size. Newton stops at 1e-14 (or the
// rounding floor near 1e-11); 1e-9 leaves room for ill-conditioned taut cables and still catches
// a wrong equilibrium.
constexpr double kStaticsClosureRel = 1e-9;
// Whatever a tolerance says, a relative difference above this is a gross disagreement (docs/verdicts.md).
constexpr double kGrossRelative = 0.5;
// Two solvers "confirm each other" against a published value when they differ by less than this
// fraction of their distance to it.
constexpr double kConfirmationRatio = 0.1;

const char* plane_name(Plane plane) { return plane == Plane::InPlane ? "in-plane" : "out-of-plane"; }

double relative_difference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 ? 0.0 : std::abs(a - b) / scale;
}

double estimate(const Mode& mode) { return std::max(0.0, mode.relative_error_estimate); }

class CheckBuilder {
 public:
  CheckBuilder(const SceneResult& result, const ToleranceTable& tolerances, const FindingsTable& findings)
      : result_(result), tolerances_(tolerances), findings_(findings) {}

  const ToleranceTable& tolerances() const { return tolerances_; }
  const FindingsTable& findings() const { return findings_; }

  const std::vector<CheckResult>& checks() const { return checks_; }

  // The tolerance for `check` between solvers a and b, with its reason; the scene's [checks]
  // override wins. Returns nullopt (and records a SKIP) when no rule exists.
  struct Tolerance {
    double value;
    std::string reason;
    bool warn_only = false;
  };
  std::optional<Tolerance> tolerance(const std::string& check, const std::string& a, const std::string& b,
                                     double estimate_sum, std::optional<double> scene_override) {
    if (scene_override) return Tolerance{*scene_override, "scene [checks] override"};
    const ToleranceRule* rule = tolerances_.find(check, a, b, result_.scene.name, result_.scene.tags);
    if (!rule) return std::nullopt;
    return Tolerance{std::max(rule->max, rule->estimate_factor * estimate_sum), rule->reason, rule->warn_only};
  }

  CheckResult base(const std::string& check, const std::string& compare, const std::string& plane, int mode) {
    CheckResult c;
    c.scene = result_.scene.name;
    c.check = check;
    c.compare = compare;
    c.plane = plane;
    c.mode = mode;
    c.value_a = c.value_b = std::nan("");
    return c;
  }

  void add(CheckResult check) { checks_.push_back(std::move(check)); }

  // measured <= tolerance, with the gross and non-finite rules.
  void add_measured(CheckResult check, double measured, const Tolerance& tol, bool relative) {
    check.measured = measured;
    check.tolerance = tol.value;
    if (!std::isfinite(measured)) {
      check.verdict = Verdict::Fail;
      check.detail = "non-finite value; " + check.detail;
    } else if (relative && measured > kGrossRelative && !tol.warn_only) {
      check.verdict = Verdict::Fail;
      check.detail = "gross disagreement; " + check.detail;
    } else if (measured <= tol.value) {
      check.verdict = Verdict::Pass;
    } else {
      // A rule marked beyond = "warn" describes a model's documented limit, not a defect.
      check.verdict = tol.warn_only ? Verdict::Warn : Verdict::Fail;
    }
    check.tolerance_reason = tol.reason;
    add(std::move(check));
  }

 private:
  const SceneResult& result_;
  const ToleranceTable& tolerances_;
  const FindingsTable& findings_;
  std::vector<CheckResult> checks_;
};

const ModalResult* modal(const SolverOutput& output, Plane plane) {
  const auto& m = plane == Plane::InPlane ? output.inplane : output.outofplane;
  return m && !m->modes.empty() ? &*m : nullptr;
}

void statics_closure(const SceneResult& result, CheckBuilder& builder) {
  CheckResult check = builder.base("statics-closure", "statics vs supports", "", 0);
  const double L = result.scene.problem.cable.length_m;
  const double chord = result.scene.problem.supports.chord_m().norm();
  check.measured = result.statics->closure_error_m / std::max(L, chord);
  check.tolerance = kStaticsClosureRel;
  check.verdict = check.measured <= check.tolerance ? Verdict::Pass : Verdict::Fail;
  check.detail = fmt::format("closure error {:.3e} m on a cable of {} m ({})", result.statics->closure_error_m,
                             L, result.statics->brief_report());
  builder.add(check);
}

void solver_status(const SolverOutput& output, CheckBuilder& builder) {
  CheckResult check = builder.base("solver-status", output.solver, "", 0);
  check.detail = output.summary.brief_report();
  switch (output.summary.termination) {
    case Termination::Converged: check.verdict = Verdict::Pass; break;
    case Termination::NotApplicable: check.verdict = Verdict::Skipped; break;
    case Termination::NoConvergence: check.verdict = Verdict::Warn; break;
    case Termination::NumericalFailure: check.verdict = Verdict::Fail; break;
  }
  builder.add(check);
}

void mode_count(const SolverOutput& output, Plane plane, CheckBuilder& builder) {
  const ModalResult* m = modal(output, plane);
  if (!m || m->proved_count_below_top < 0) return;
  CheckResult check = builder.base("mode-count", output.solver, plane_name(plane), 0);
  check.value_a = m->proved_count_below_top;
  check.value_b = static_cast<double>(m->modes.size());
  check.measured = std::abs(check.value_a - check.value_b);
  check.tolerance = 0.0;
  check.verdict = check.measured == 0.0 ? Verdict::Pass : Verdict::Fail;
  check.detail = fmt::format("{} eigenvalues proved at or below the top returned frequency, {} returned",
                             m->proved_count_below_top, m->modes.size());
  builder.add(check);
}

void frequency_pair(const SceneResult& result, const SolverOutput& a, const SolverOutput& b, Plane plane,
                    CheckBuilder& builder) {
  const ModalResult* ma = modal(a, plane);
  const ModalResult* mb = modal(b, plane);
  if (!ma || !mb) return;
  const std::size_t n = std::min(ma->modes.size(), mb->modes.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Mode& x = ma->modes[i];
    const Mode& y = mb->modes[i];
    const auto tol = builder.tolerance("frequency", a.solver, b.solver, estimate(x) + estimate(y),
                                       result.scene.checks.frequency_rel);
    CheckResult check = builder.base("frequency", a.solver + " vs " + b.solver, plane_name(plane), x.index);
    check.value_a = x.omega_rad_s;
    check.value_b = y.omega_rad_s;
    check.detail = fmt::format("omega {:.12g} vs {:.12g} rad/s (error estimates {:.1e}, {:.1e})", x.omega_rad_s,
                               y.omega_rad_s, x.relative_error_estimate, y.relative_error_estimate);
    if (!tol) continue;
    builder.add_measured(check, relative_difference(x.omega_rad_s, y.omega_rad_s), *tol, true);
  }
}

// Simpson on equally spaced stations when their number is odd, trapezoid otherwise.
double integrate(const Vector& s, const Vector& f) {
  const Index n = s.size();
  if (n < 3 || n % 2 == 0) {
    double sum = 0.0;
    for (Index i = 1; i < n; ++i) sum += 0.5 * (s[i] - s[i - 1]) * (f[i] + f[i - 1]);
    return sum;
  }
  const double h = (s[n - 1] - s[0]) / static_cast<double>(n - 1);
  double sum = f[0] + f[n - 1];
  for (Index i = 1; i < n - 1; ++i) sum += (i % 2 ? 4.0 : 2.0) * f[i];
  return sum * h / 3.0;
}

Vector shape_vector(const Mode& mode, Plane plane) {
  if (plane == Plane::OutOfPlane) return mode.v;
  Vector out(mode.u.size() + mode.w.size());
  out << mode.u, mode.w;
  return out;
}

bool has_shape(const Mode& mode, Plane plane) {
  return plane == Plane::OutOfPlane ? mode.v.size() > 0 : (mode.u.size() > 0 && mode.w.size() > 0);
}

void shape_pair(const SceneResult& result, const SolverOutput& a, const SolverOutput& b, Plane plane,
                CheckBuilder& builder) {
  const ModalResult* ma = modal(a, plane);
  const ModalResult* mb = modal(b, plane);
  if (!ma || !mb) return;
  const std::size_t n = std::min(ma->modes.size(), mb->modes.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Mode& x = ma->modes[i];
    const Mode& y = mb->modes[i];
    if (!has_shape(x, plane) || !has_shape(y, plane) || x.s_m.size() != y.s_m.size()) continue;
    const Vector p = shape_vector(x, plane), q = shape_vector(y, plane);
    const double mac = std::pow(p.dot(q), 2) / (p.squaredNorm() * q.squaredNorm());
    const std::string compare = a.solver + " vs " + b.solver;
    if (auto tol = builder.tolerance("mac", a.solver, b.solver, 0.0,
                                     result.scene.checks.mac_min ? std::optional(1.0 - *result.scene.checks.mac_min)
                                                                 : std::nullopt)) {
      CheckResult check = builder.base("mac", compare, plane_name(plane), x.index);
      check.value_a = mac;
      check.detail = fmt::format("MAC = {:.9f} (measured: 1 - MAC)", mac);
      builder.add_measured(check, 1.0 - mac, *tol, false);
    }
    // Max difference of the normalised shapes, signs aligned.
    const double sign = p.dot(q) < 0.0 ? -1.0 : 1.0;
    const double max_diff = (p - sign * q).cwiseAbs().maxCoeff() / std::max(p.cwiseAbs().maxCoeff(), 1e-300);
    if (auto tol = builder.tolerance("shape", a.solver, b.solver, 0.0, result.scene.checks.shape_max_diff)) {
      CheckResult check = builder.base("shape", compare, plane_name(plane), x.index);
      check.detail = "max |shape_a - shape_b| / max |shape_a| over the stations";
      builder.add_measured(check, max_diff, *tol, false);
    }
  }
}

void tension_pair(const SceneResult& result, const SolverOutput& a, const SolverOutput& b, Plane plane,
                  CheckBuilder& builder) {
  const ModalResult* ma = modal(a, plane);
  const ModalResult* mb = modal(b, plane);
  if (!ma || !mb || plane == Plane::OutOfPlane) return;  // out-of-plane modes carry no tension
  const std::size_t n = std::min(ma->modes.size(), mb->modes.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Mode& x = ma->modes[i];
    const Mode& y = mb->modes[i];
    if (x.max_abs_tension_n < 0.0 || y.max_abs_tension_n < 0.0) continue;
    if (x.normalised_by != y.normalised_by) continue;
    const auto tol = builder.tolerance("tension", a.solver, b.solver, 0.0, result.scene.checks.tension_rel);
    if (!tol) continue;
    CheckResult check = builder.base("tension", a.solver + " vs " + b.solver, plane_name(plane), x.index);
    check.value_a = x.max_abs_tension_n;
    check.value_b = y.max_abs_tension_n;
    check.detail = fmt::format("max |tau| {:.9g} vs {:.9g} N per unit max |{}|", x.max_abs_tension_n,
                               y.max_abs_tension_n, x.normalised_by);
    builder.add_measured(check, relative_difference(x.max_abs_tension_n, y.max_abs_tension_n), *tol, true);
  }
}

// A forcing frequency where at least one solver gave no finite response. Both without one, or a
// decline that is not a resonance (the frequency is beyond that method's resolution, which its
// status reports): SKIP with the reason. One solver at resonance while the other returns a finite
// response: consistent only when the other flags it near_resonance (resonance-amplified, within
// the first solver's accuracy of a natural frequency); a finite response nobody flags contradicts
// the resonance claim, and one of the two answers is wrong: FAIL.
void resonance_claim(const ForcedResponse& x, const ForcedResponse& y, const std::string& solver_x,
                     const std::string& solver_y, CheckResult& check) {
  check.verdict = Verdict::Skipped;
  const bool x_finite = x.diagnostic.empty(), y_finite = y.diagnostic.empty();
  const ForcedResponse& claim = x_finite ? y : x;
  if (!x_finite && !y_finite) {
    check.detail = "not compared: " + x.diagnostic + "; " + y.diagnostic;
    return;
  }
  const ForcedResponse& finite = x_finite ? x : y;
  const std::string& claimant = x_finite ? solver_y : solver_x;
  const std::string& other = x_finite ? solver_x : solver_y;
  if (!claim.at_resonance) {
    check.detail = fmt::format("not compared: {} declined this frequency: {}", claimant, claim.diagnostic);
  } else if (finite.near_resonance) {
    check.detail = fmt::format("not compared: {} is at resonance within its accuracy ({}); {} flags its finite "
                               "response near a natural frequency (error estimate {:.1e})",
                               claimant, claim.diagnostic, other, finite.relative_error_estimate);
  } else {
    check.verdict = Verdict::Fail;
    check.detail = fmt::format("contradiction: {} says resonance ({}) while {} gives a finite response, max |tau| = "
                               "{:.9g} N (error estimate {:.1e}), not flagged near a natural frequency",
                               claimant, claim.diagnostic, other, finite.max_abs_tension_n,
                               finite.relative_error_estimate);
  }
}

void forced_pair(const SceneResult& result, const SolverOutput& a, const SolverOutput& b, CheckBuilder& builder) {
  const std::size_t n = std::min(a.forced.size(), b.forced.size());
  for (std::size_t i = 0; i < n; ++i) {
    const ForcedResponse& x = a.forced[i];
    const ForcedResponse& y = b.forced[i];
    CheckResult check = builder.base("forced", a.solver + " vs " + b.solver, "forced", static_cast<int>(i + 1));
    check.value_a = x.max_abs_tension_n;
    check.value_b = y.max_abs_tension_n;
    if (!x.diagnostic.empty() || !y.diagnostic.empty()) {
      resonance_claim(x, y, a.solver, b.solver, check);
      builder.add(check);
      continue;
    }
    const double estimates = std::max(0.0, x.relative_error_estimate) + std::max(0.0, y.relative_error_estimate);
    const auto tol = builder.tolerance("forced", a.solver, b.solver, estimates, result.scene.checks.tension_rel);
    if (!tol) continue;
    check.detail = fmt::format("max |tau| at {:.6g} rad/s: {:.9g} vs {:.9g} N (error estimates {:.1e}, {:.1e})",
                               x.omega_rad_s, x.max_abs_tension_n, y.max_abs_tension_n, x.relative_error_estimate,
                               y.relative_error_estimate);
    builder.add_measured(check, relative_difference(x.max_abs_tension_n, y.max_abs_tension_n), *tol, true);
  }
}

void orthogonality(const SceneResult& result, const SolverOutput& output, Plane plane, CheckBuilder& builder) {
  const ModalResult* m = modal(output, plane);
  if (!m || m->modes.size() < 2 || !has_shape(m->modes[0], plane)) return;
  const double mass = result.scene.problem.cable.mass_kg_per_m;
  const double normal_mass = result.scene.problem.cable.normal_mass_kg_per_m();
  auto inner = [&](const Mode& x, const Mode& y) {
    const Vector density = plane == Plane::InPlane
                               ? Vector(mass * x.u.cwiseProduct(y.u) + normal_mass * x.w.cwiseProduct(y.w))
                               : Vector(normal_mass * x.v.cwiseProduct(y.v));
    return integrate(x.s_m, density);
  };
  double worst = 0.0;
  int worst_i = 0, worst_j = 0;
  for (std::size_t i = 0; i < m->modes.size(); ++i) {
    for (std::size_t j = i + 1; j < m->modes.size(); ++j) {
      const Mode& x = m->modes[i];
      const Mode& y = m->modes[j];
      if (!has_shape(x, plane) || !has_shape(y, plane)) continue;
      const double value = std::abs(inner(x, y)) / std::sqrt(inner(x, x) * inner(y, y));
      if (!(value <= worst)) {
        worst = value;
        worst_i = x.index;
        worst_j = y.index;
      }
    }
  }
  const auto tol = builder.tolerance("orthogonality", output.solver, output.solver, 0.0, result.scene.checks.orthogonality);
  if (!tol) return;
  CheckResult check = builder.base("orthogonality", output.solver, plane_name(plane), 0);
  check.detail = fmt::format("max |<phi_i, phi_j>_M| / (|phi_i| |phi_j|) over mode pairs, at modes {} and {}",
                             worst_i, worst_j);
  builder.add_measured(check, worst, *tol, false);
}

// The value a solver gives for a published entry, in the entry's unit, and its error estimate.
std::optional<std::pair<double, double>> solver_value(const SceneResult& result, const SolverOutput& output,
                                                      const PublishedValues& published, int mode) {
  if (published.quantity == PublishedQuantity::ForcedMaxTension) {
    if (mode < 0 || mode >= static_cast<int>(output.forced.size())) return std::nullopt;
    const ForcedResponse& response = output.forced[static_cast<std::size_t>(mode)];
    if (!response.diagnostic.empty()) return std::nullopt;
    return std::pair{response.max_abs_tension_n / result.statics->horizontal_force_n(),
                     std::max(0.0, response.relative_error_estimate)};
  }
  const ModalResult* m = modal(output, published.quantity == PublishedQuantity::InPlaneFrequency ? Plane::InPlane
                                                                                                  : Plane::OutOfPlane);
  if (!m) return std::nullopt;
  for (const auto& x : m->modes) {
    if (x.index == mode) {
      return std::pair{from_rad_per_second(x.omega_rad_s, published.unit, *result.groups), estimate(x)};
    }
  }
  return std::nullopt;
}

// Every usable solver's value for one published entry: solver -> (value, error estimate).
using PublishedCandidates = std::map<std::string, std::pair<double, double>>;

// A second solver that confirms `solver`'s value: it agrees with ours within their pair tolerance
// and far better (kConfirmationRatio) than ours agrees with the print. Empty when none does.
std::string confirming_solver(const SceneResult& result, const CheckBuilder& builder, const std::string& quantity,
                              const std::string& solver, const PublishedCandidates& values, double measured) {
  const auto [ours, est] = values.at(solver);
  std::string partner;
  for (const auto& [other, other_value] : values) {
    if (other == solver) continue;
    const double between = std::abs(other_value.first - ours);
    const ToleranceRule* pair_rule = builder.tolerances().find(
        quantity == "forced_max_tension" ? "forced" : "frequency", solver, other, result.scene.name,
        result.scene.tags);
    const double pair_tol =
        pair_rule ? std::max(pair_rule->max, pair_rule->estimate_factor * (est + other_value.second)) : 0.0;
    if (between <= pair_tol * std::abs(ours) && between <= kConfirmationRatio * measured) partner = other;
  }
  return partner;
}

// Beyond the printed digits: a source discrepancy when confirmed by a second solver or by a
// reviewed finding that still matches our value; a failure otherwise.
void judge_disagreement(const SceneResult& result, const CheckBuilder& builder, const std::string& quantity,
                        const std::string& solver, const PublishedCandidates& values, int mode,
                        CheckResult& check) {
  const double ours = values.at(solver).first;
  const std::string partner = confirming_solver(result, builder, quantity, solver, values, check.measured);
  const Finding* finding = builder.findings().find(result.scene.name, quantity, mode, solver);
  if (!partner.empty()) {
    check.verdict = Verdict::SourceDiscrepancy;
    check.detail += fmt::format("; confirmed by {} = {:.8g}", partner, values.at(partner).first);
  } else if (finding && relative_difference(finding->ours, ours) <= 1e-6) {
    check.verdict = Verdict::SourceDiscrepancy;
    check.detail += "; reviewed finding: " + finding->diagnosis;
  } else if (finding) {
    check.verdict = Verdict::Fail;
    check.detail += fmt::format("; stale finding (reviewed value {:.8g})", finding->ours);
  } else {
    check.verdict = Verdict::Fail;
  }
}

void published_entry(const SceneResult& result, CheckBuilder& builder, const PublishedValues& published,
                     const std::string& solver, const PublishedCandidates& values, int mode, double printed) {
  const std::string quantity = to_string(published.quantity);
  const double half_unit = published.decimals >= 0 ? 0.5 * std::pow(10.0, -published.decimals) : 0.0;
  const auto [ours, est] = values.at(solver);
  const ToleranceRule* rule =
      builder.tolerances().find("published", solver, "published", result.scene.name, result.scene.tags);
  const double slack = rule ? std::max(rule->max, rule->estimate_factor * est * std::abs(ours)) : 0.0;
  const bool forced = quantity == "forced_max_tension";
  CheckResult check = builder.base("published", solver + " vs " + published.source,
                                   forced                                 ? "forced"
                                   : quantity == "inplane_frequency" ? "in-plane"
                                                                          : "out-of-plane",
                                   forced ? mode + 1 : mode);
  check.value_a = ours;
  check.value_b = printed;
  check.measured = std::abs(ours - printed);
  check.tolerance = half_unit + slack;
  check.detail = fmt::format("ours {:.8g}, printed {} ({} decimals; absolute difference, in the table's unit)",
                             ours, printed, published.decimals);
  if (!std::isfinite(ours)) {
    check.verdict = Verdict::Fail;
  } else if (check.measured <= check.tolerance) {
    check.verdict = Verdict::Pass;
  } else {
    judge_disagreement(result, builder, quantity, solver, values, mode, check);
  }
  builder.add(check);
}

void published_values(const SceneResult& result, CheckBuilder& builder) {
  for (const auto& published : result.scene.published) {
    for (std::size_t k = 0; k < published.values.size(); ++k) {
      const int mode = published.modes[k];
      // Every usable solver's value (for confirmation), and the designated ones (to check).
      PublishedCandidates values;
      for (const auto& output : result.outputs) {
        if (!output.summary.is_usable()) continue;
        if (auto v = solver_value(result, output, published, mode)) values[output.solver] = *v;
      }
      for (const auto& [solver, value_and_estimate] : values) {
        const auto& only = published.compare_with;
        if (!only.empty() && std::find(only.begin(), only.end(), solver) == only.end()) continue;
        published_entry(result, builder, published, solver, values, mode, published.values[k]);
      }
    }
  }
}

}  // namespace

std::vector<CheckResult> run_checks(const SceneResult& result, const ToleranceTable& tolerances,
                                    const FindingsTable& findings) {
  CheckBuilder builder(result, tolerances, findings);
  if (!result.statics) return {};
  statics_closure(result, builder);
  for (const auto& output : result.outputs) solver_status(output, builder);
  std::vector<const SolverOutput*> usable;
  for (const auto& output : result.outputs) {
    if (output.summary.is_usable()) usable.push_back(&output);
  }
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    for (const SolverOutput* output : usable) mode_count(*output, plane, builder);
    for (std::size_t i = 0; i < usable.size(); ++i) {
      for (std::size_t j = i + 1; j < usable.size(); ++j) {
        frequency_pair(result, *usable[i], *usable[j], plane, builder);
        shape_pair(result, *usable[i], *usable[j], plane, builder);
        tension_pair(result, *usable[i], *usable[j], plane, builder);
      }
    }
    for (const SolverOutput* output : usable) orthogonality(result, *output, plane, builder);
  }
  for (std::size_t i = 0; i < usable.size(); ++i) {
    for (std::size_t j = i + 1; j < usable.size(); ++j) forced_pair(result, *usable[i], *usable[j], builder);
  }
  published_values(result, builder);
  return builder.checks();
}

}  // namespace catena::internal
