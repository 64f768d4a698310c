// SPDX-License-Identifier: MIT
// First-order damping of an analytic model's own undamped modes: see modal_damping.hpp.
#include "solvers/common/modal_damping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>

#include "solvers/common/mode_tools.hpp"

namespace catena::internal {
namespace {

using Rule = boost::math::quadrature::gauss<double, 10>;

double weighted_sum(const Vector& weights, const Vector& f) { return weights.dot(f); }

// The part of one mode the estimates need, before its root is set.
struct ModeDamping {
  double omega0 = 0.0;
  double delta = 0.0;
  double model_estimate = -1.0;  // the undamped model's relative error of omega0 (-1: none)
  double zeta_np = 0.0;          // D / (2 omega0)
  double coupling = 0.0;         // kappa = D / (2 |omega_j - omega0|), nearest mode j
  double rate_bound = 0.0;       // D [1/s]
};

// Relative error of delta: first order in the non-proportional part D of the damping, scaled by
// its share D / (2 delta) of the mode's decay. The shape enters through phi^T D phi: by
// Rayleigh's principle a relative frequency error e comes from a shape error ~ sqrt(e), which
// moves the quotient by ~ 2 sqrt(e); the neglected coupling to the nearest mode moves lambda by
// at most ~ D kappa / 2 (second-order perturbation, taken whole into delta: O(zeta), not the
// O(zeta^2) it usually is). Proportional damping (D = 0): the quotient is exact, rounding only.
double decay_estimate(const ModeDamping& d) {
  if (d.rate_bound == 0.0) return kDecayRoundingEstimate;
  if (d.model_estimate < 0.0 || !(d.delta > 0.0)) return -1.0;
  return d.rate_bound / (2.0 * d.delta) * (2.0 * std::sqrt(d.model_estimate) + d.coupling) +
         kDecayRoundingEstimate;
}

// Real parts stay the undamped, normalised shape; the imaginary parts are zero (the first-order
// shape correction is not computed, docs/explanation/methods/asymptotic.md, "Damping").
void add_zero_imaginary_parts(Mode& mode) {
  if (mode.u.size()) mode.u_imag = Vector::Zero(mode.u.size());
  if (mode.w.size()) mode.w_imag = Vector::Zero(mode.w.size());
  if (mode.v.size()) mode.v_imag = Vector::Zero(mode.v.size());
  if (mode.tension_n.size()) mode.tension_imag_n = Vector::Zero(mode.tension_n.size());
}

// lambda = -delta + i omega_d with omega_d = sqrt(omega0^2 - delta^2); the frequency estimate
// carries the model's (amplified by omega0^2 / omega_d^2), delta's, and the O(zeta^2) coupling.
void set_oscillatory(Mode& mode, const ModeDamping& d, const DimensionlessGroups& groups) {
  const double omega_d = std::sqrt((d.omega0 - d.delta) * (d.omega0 + d.delta));
  set_damped_root(mode, {-d.delta, omega_d}, groups);
  mode.decay_rate_error_estimate = decay_estimate(d);
  if (d.model_estimate < 0.0) {
    mode.relative_error_estimate = -1.0;
    return;
  }
  const double delta_error = std::max(mode.decay_rate_error_estimate, 0.0) * d.delta;
  mode.relative_error_estimate =
      (d.model_estimate * d.omega0 * d.omega0 + d.delta * delta_error) / (omega_d * omega_d) +
      d.zeta_np * d.coupling * d.omega0 / omega_d;
}

// The two real roots -delta -+ sqrt(delta^2 - omega0^2) of an overdamped mode, each with the
// error of its decay rate from those of delta and omega0 (none at the double root).
void add_overdamped(const Mode& undamped,
                    const ModeDamping& d,
                    const DimensionlessGroups& groups,
                    std::vector<Mode>& overdamped) {
  const double root = std::sqrt((d.delta - d.omega0) * (d.delta + d.omega0));
  const double delta_error_estimate = decay_estimate(d);
  // The slow root from the product of the two, omega0^2: no cancellation when omega0 << delta.
  for (double rate : {d.omega0 * d.omega0 / (d.delta + root), d.delta + root}) {
    Mode mode = undamped;
    set_damped_root(mode, {-rate, 0.0}, groups);
    mode.relative_error_estimate = -1.0;  // omega_d = 0: no oscillation
    const double abs_delta_error = delta_error_estimate * d.delta;
    mode.decay_rate_error_estimate =
        root > 0.0 && delta_error_estimate >= 0.0 && d.model_estimate >= 0.0
            ? (abs_delta_error +
               (d.delta * abs_delta_error + d.model_estimate * d.omega0 * d.omega0) / root) /
                  rate
            : -1.0;
    overdamped.push_back(std::move(mode));
  }
}

// The non-proportional ratio and the coupling to the nearest undamped mode of the same plane (for
// a plane of one mode, its own frequency: the spacing of a string's lowest modes).
std::vector<ModeDamping> mode_damping(Plane plane,
                                      const ModalResult& result,
                                      const std::vector<double>& decay_rates,
                                      const DampedSection& section) {
  std::vector<ModeDamping> out;
  const std::vector<Mode>& modes = result.modes;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    ModeDamping d;
    d.omega0 = modes[i].omega_rad_s;
    d.delta = decay_rates[i];
    d.model_estimate = modes[i].relative_error_estimate;
    d.rate_bound = nonproportional_rate_1_s(plane, section, d.omega0);
    double gap = modes.size() == 1 ? d.omega0 : kInfinity;
    for (std::size_t j = 0; j < modes.size(); ++j) {
      if (j != i) gap = std::min(gap, std::abs(modes[j].omega_rad_s - d.omega0));
    }
    d.zeta_np = d.rate_bound / (2.0 * d.omega0);
    d.coupling = d.rate_bound == 0.0 ? 0.0 : d.rate_bound / (2.0 * gap);
    out.push_back(d);
  }
  return out;
}

void decline(ModalResult& result, const Mode& mode, const ModeDamping& d) {
  result.modes.clear();
  result.overdamped.clear();
  result.proved_count_below_top = -1;
  SolverSummary& summary = result.summary;
  summary.termination = Termination::NotApplicable;
  summary.max_error_estimate = -1.0;
  summary.message = fmt::format(
      "damping too strong for the first-order perturbation: undamped mode {} (omega0 = {:.6g} "
      "rad/s) has non-proportional damping ratio D/(2 omega0) = {:.3g} and coupling D/(2 gap) = "
      "{:.3g} to its nearest mode (D = {:.3g} 1/s), above {:.2g}: an exact solver is needed",
      mode.index, d.omega0, d.zeta_np, d.coupling, d.rate_bound, kMaxPerturbationParameter);
}

}  // namespace

DampingQuadrature damping_quadrature(double length_m, double phase_rad) {
  const auto& x = Rule::abscissa();
  const auto& w = Rule::weights();
  const int points = 2 * static_cast<int>(x.size());  // 10: the rule stores the half x >= 0
  const double phase = std::isfinite(phase_rad) ? std::abs(phase_rad) : 0.0;
  const int panels = 8 + static_cast<int>(std::ceil(0.5 * phase));
  DampingQuadrature q;
  q.s_m.resize(panels * points);
  q.weights.resize(panels * points);
  const double half = 0.5 * length_m / panels;
  for (int p = 0; p < panels; ++p) {
    const double centre = (2 * p + 1) * half;
    const Index base = static_cast<Index>(p) * points;
    const int n = static_cast<int>(x.size());
    for (int i = 0; i < n; ++i) {
      q.s_m[base + i] = centre - half * x[n - 1 - i];
      q.weights[base + i] = half * w[n - 1 - i];
      q.s_m[base + n + i] = centre + half * x[i];
      q.weights[base + n + i] = half * w[i];
    }
  }
  return q;
}

DampedSection DampedSection::of(const Problem& problem) {
  const CableProperties& cable = problem.cable;
  DampedSection section;
  section.mass_kg_per_m = cable.mass_kg_per_m;
  section.normal_mass_kg_per_m = cable.normal_mass_kg_per_m();
  section.axial_stiffness_n = cable.axial_stiffness_n;
  section.damping = cable.damping;
  section.seabed_damping_n_s_per_m2 = problem.seabed ? problem.seabed->damping_n_s_per_m2 : 0.0;
  return section;
}

double inplane_decay_rate(const DampingQuadrature& quadrature,
                          const InplaneModeSamples& mode,
                          const DampedSection& section) {
  const Vector& q = quadrature.weights;
  const Vector u2 = mode.u.cwiseAbs2();
  const Vector w2 = mode.w.cwiseAbs2();
  const SectionDamping& c = section.damping;
  double dissipation =
      c.tangential_n_s_per_m2 * weighted_sum(q, u2) + c.normal_n_s_per_m2 * weighted_sum(q, w2);
  // Kelvin-Voigt: c_a eps_dyn^2 with eps_dyn = tau / EA (c_a = 0 when EA = inf, by validation).
  if (c.axial_n_s > 0.0 && mode.tension_n.size()) {
    const double ea = section.axial_stiffness_n;
    dissipation += c.axial_n_s / (ea * ea) * weighted_sum(q, mode.tension_n.cwiseAbs2());
  }
  if (section.seabed_damping_n_s_per_m2 > 0.0 && mode.grounded_vertical.size()) {
    dissipation +=
        section.seabed_damping_n_s_per_m2 * weighted_sum(q, mode.grounded_vertical.cwiseAbs2());
  }
  const double inertia = section.mass_kg_per_m * weighted_sum(q, u2) +
                         section.normal_mass_kg_per_m * weighted_sum(q, w2);
  return dissipation / (2.0 * inertia);
}

double outofplane_decay_rate(const DampingQuadrature& quadrature,
                             const Vector& v,
                             const DampedSection& section) {
  const double v2 = weighted_sum(quadrature.weights, v.cwiseAbs2());
  return section.damping.normal_n_s_per_m2 * v2 / (2.0 * (section.normal_mass_kg_per_m * v2));
}

double nonproportional_rate_1_s(Plane plane, const DampedSection& section, double omega0) {
  if (plane == Plane::OutOfPlane) return 0.0;
  const SectionDamping& c = section.damping;
  const double rate_t = c.tangential_n_s_per_m2 / section.mass_kg_per_m;
  const double rate_n = c.normal_n_s_per_m2 / section.normal_mass_kg_per_m;
  const double difference = std::abs(rate_t - rate_n);
  // c_t = alpha m and c_n = alpha M, written as decimals, give rates a few ulp apart.
  const double spread =
      difference <= 8.0 * std::numeric_limits<double>::epsilon() * std::max(rate_t, rate_n)
          ? 0.0
          : difference;
  const double axial = c.axial_n_s > 0.0 ? c.axial_n_s / section.axial_stiffness_n : 0.0;
  return 0.5 * spread + section.seabed_damping_n_s_per_m2 / section.normal_mass_kg_per_m +
         axial * omega0 * omega0;
}

void apply_perturbed_damping(Plane plane,
                             ModalResult& result,
                             const std::vector<double>& decay_rates_1_s,
                             const DampedSection& section,
                             const DimensionlessGroups& groups) {
  const std::vector<ModeDamping> damping = mode_damping(plane, result, decay_rates_1_s, section);
  for (std::size_t i = 0; i < damping.size(); ++i) {
    if (std::max(damping[i].zeta_np, damping[i].coupling) > kMaxPerturbationParameter) {
      decline(result, result.modes[i], damping[i]);
      return;
    }
  }
  std::vector<Mode> oscillatory, overdamped;
  for (std::size_t i = 0; i < damping.size(); ++i) {
    Mode mode = result.modes[i];
    add_zero_imaginary_parts(mode);
    if (damping[i].delta >= damping[i].omega0) {
      add_overdamped(mode, damping[i], groups, overdamped);
      continue;
    }
    set_oscillatory(mode, damping[i], groups);
    oscillatory.push_back(std::move(mode));
  }
  auto by = [](auto key) {
    return [key](const Mode& a, const Mode& b) { return key(a) < key(b); };
  };
  std::stable_sort(oscillatory.begin(), oscillatory.end(),
                   by([](const Mode& m) { return m.omega_rad_s; }));
  std::stable_sort(overdamped.begin(), overdamped.end(),
                   by([](const Mode& m) { return m.decay_rate_1_s; }));
  double max_estimate = -1.0;
  for (std::size_t i = 0; i < oscillatory.size(); ++i) {
    oscillatory[i].index = static_cast<int>(i) + 1;
    max_estimate = std::max(max_estimate, oscillatory[i].relative_error_estimate);
  }
  for (std::size_t i = 0; i < overdamped.size(); ++i) overdamped[i].index = static_cast<int>(i) + 1;
  result.modes = std::move(oscillatory);
  result.overdamped = std::move(overdamped);
  result.proved_count_below_top = -1;
  result.summary.max_error_estimate = max_estimate;
  result.summary.notes.push_back(fmt::format(
      "damped by first-order perturbation from the model's own undamped modes (delta = phi^T C "
      "phi / 2 phi^T Mass phi; exact for proportional damping): {} oscillatory, {} overdamped "
      "roots (from {} undamped modes); shapes are the undamped ones (imaginary parts 0); the "
      "count of modes is not proved for the damped roots",
      result.modes.size(), result.overdamped.size(), damping.size()));
}

}  // namespace catena::internal
