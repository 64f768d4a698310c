// SPDX-License-Identifier: MIT
// Forced response of the frobenius solver: see frobenius_forced.hpp.
#include "solvers/frobenius/frobenius_forced.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "solvers/frobenius/frobenius_root_scan.hpp"

namespace catena::internal {

namespace {

// A forced response with a resonance-amplified response (condition above this) is flagged
// near_resonance: the same 1e-3 as shooting's normalised determinant.
constexpr double kNearResonanceCondition = 1e3;

// The basis settings of the forced response at Omega = omega: the wave limit on each expansion
// (frobenius_forced.hpp) and the cap on centres. `finer` is the check evaluation: half the phase
// per expansion and the series cut 1e-3 finer.
PlaneSetup forced_setup(const PlaneSetup& base, bool finer) {
  PlaneSetup setup = base;
  setup.settings.max_phase_per_expansion =
      finer ? 0.5 * kForcedPhasePerExpansion : kForcedPhasePerExpansion;
  setup.settings.max_centres = finer ? 2 * kForcedMaxCentres : kForcedMaxCentres;
  if (finer) setup.settings.term_tolerance = std::max(setup.settings.term_tolerance * 1e-3, 1e-30);
  return setup;
}

// One evaluation of the boundary system at one frequency.
struct ForcedSolve {
  std::vector<long double> coefficients;       // in the unscaled basis
  std::vector<std::vector<long double>> rows;  // the scaled matrix, rows equilibrated
  std::vector<long double> row_scale;
  double entry_error = 0.0;  // the entries' own error estimate, relative to their row
  double condition = 0.0;    // 1-norm condition number of the row-equilibrated matrix
  long terms = 0;
  int centres = 0;
  bool truncated = false;
};

// 1-norm condition number of the small matrix `a` (its inverse column by column).
double condition_1(const std::vector<std::vector<long double>>& a) {
  const std::size_t n = a.size();
  long double norm = 0, inverse_norm = 0;
  for (std::size_t j = 0; j < n; ++j) {
    long double column = 0;
    for (std::size_t i = 0; i < n; ++i) column += std::abs(a[i][j]);
    norm = std::max(norm, column);
    std::vector<long double> e(n, 0.0L);
    e[j] = 1.0L;
    long double inverse_column = 0;
    for (long double x : solve_dense(a, e)) inverse_column += std::abs(x);
    inverse_norm = std::max(inverse_norm, inverse_column);
  }
  const double kappa = static_cast<double>(norm * inverse_norm);
  return std::isfinite(kappa) ? kappa : std::numeric_limits<double>::infinity();
}

// The boundary system with the fixed end at rest and the driven end displaced by `end`, solved
// in long double (the system is small; the extra digits are cheap and keep the fields accurate
// near resonance).
ForcedSolve solve_forcing(const PlaneSetup& setup,
                          double omega,
                          bool driven_at_b,
                          const EndDisplacement& end) {
  const auto m = boundary_matrix<long double>(setup, static_cast<long double>(omega));
  const std::size_t n = m.a.size();
  ForcedSolve out;
  out.terms = m.terms;
  out.centres = m.centres;
  out.truncated = !m.converged;
  std::vector<long double> rhs(n, 0.0L);
  const double sigma_end = driven_at_b ? setup.sigma2 : setup.sigma1;
  const std::size_t row = driven_at_b ? n / 2 : 0;
  rhs[row] = static_cast<long double>(end.u);
  if (setup.inplane)
    rhs[row + 1] = static_cast<long double>(end.v) /
                   static_cast<long double>(1.0 + sigma_end * sigma_end);  // DU = V / C^2
  // Solved as scaled (the rows' scaling is only for the condition and the uncertainty).
  out.coefficients = solve_dense(m.a, rhs);
  for (std::size_t j = 0; j < n; ++j) out.coefficients[j] /= m.column_scale[j];
  out.rows = m.a;
  out.row_scale.assign(n, 1.0L);
  for (std::size_t i = 0; i < n; ++i) {
    long double big = 0;
    for (long double x : m.a[i]) big = std::max(big, std::abs(x));
    if (big > 0) out.row_scale[i] = big;
    for (std::size_t j = 0; j < n; ++j) {
      out.rows[i][j] /= out.row_scale[i];
      out.entry_error =
          std::max(out.entry_error, static_cast<double>(m.error[i][j] / out.row_scale[i]));
    }
  }
  out.entry_error =
      std::max(out.entry_error, static_cast<double>(std::numeric_limits<long double>::epsilon()));
  out.condition = condition_1(out.rows);
  return out;
}

// Largest entrywise difference of two evaluations' row-equilibrated matrices (same rows, same
// basis functions: they approximate the same matrix).
double matrix_difference(const ForcedSolve& a, const ForcedSolve& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    for (std::size_t j = 0; j < a.rows.size(); ++j)
      worst = std::max(worst, static_cast<double>(std::abs(a.rows[i][j] - b.rows[i][j])));
  return worst;
}

// Fills the fields of `response` from the combination c of the basis at Omega = omega.
void set_fields(ForcedResponse& response,
                const PlaneSetup& setup,
                double omega,
                const std::vector<long double>& c,
                const FieldStations& stations,
                const CableUnits& units) {
  const auto values = fields<long double>(setup, omega, c, stations.sigma, setup.inplane);
  const Index n = stations.s_m.size();
  if (setup.inplane) {
    response.u.resize(n);
    response.w.resize(n);
    response.tension_n.resize(n);
    for (Index k = 0; k < n; ++k) {
      const FieldValues& f = values[static_cast<std::size_t>(k)];
      response.u(k) = units.length_m * f.u;
      response.w(k) = units.length_m * f.v;
      response.tension_n(k) = units.tension_n * f.t;
    }
    response.max_abs_tension_n = response.tension_n.cwiseAbs().maxCoeff();
  } else {
    response.v.resize(n);
    for (Index k = 0; k < n; ++k)
      response.v(k) = units.length_m * values[static_cast<std::size_t>(k)].u;
  }
}

// max |T| in plane, max |U| out of plane: the quantity whose two evaluations give the estimate.
double peak(const ForcedResponse& r) {
  if (r.tension_n.size()) return r.max_abs_tension_n;
  return r.v.size() ? r.v.cwiseAbs().maxCoeff() : 0.0;
}

bool finite_fields(const ForcedResponse& r) {
  return r.u.allFinite() && r.w.allFinite() && r.v.allFinite() && r.tension_n.allFinite() &&
         std::isfinite(r.max_abs_tension_n);
}

// A response without fields, declined with `reason` (at_resonance when it is the resonance).
void decline(ForcedResponse& response, std::string reason, bool at_resonance) {
  const double omega = response.omega_rad_s;
  const Vector s = response.s_m;
  response = ForcedResponse{};
  response.omega_rad_s = omega;
  response.s_m = s;
  response.diagnostic = std::move(reason);
  response.at_resonance = at_resonance;
}

// Why the basis of Omega = omega cannot be trusted (too many centres, truncated series, entries
// not known to kForcedMaxEntryError), or nullopt.
std::optional<std::string> basis_trouble(const PlaneSetup& setup,
                                         double omega,
                                         const ForcedSolve& a,
                                         const ForcedSolve& b,
                                         double uncertainty) {
  const double needed = forced_centres_needed(setup, omega);
  if (!(needed <= kForcedMaxCentres))
    return fmt::format(
        "forcing at Omega = {:g} is beyond the frobenius series: about {:.3g} expansion centres "
        "would be needed to keep each expansion within {:g} rad of phase (cap {}); declined",
        omega, needed, kForcedPhasePerExpansion, kForcedMaxCentres);
  if (a.truncated || b.truncated)
    return fmt::format(
        "forcing at Omega = {:g}: some series hit max_terms = {} before converging; declined",
        omega, setup.settings.max_terms);
  if (!(uncertainty <= kForcedMaxEntryError))
    return fmt::format(
        "forcing at Omega = {:g}: the boundary matrix is known only to {:.1e} (relative, two "
        "evaluations); declined",
        omega, uncertainty);
  return std::nullopt;
}

// Whether the response is resolved a quarter of the WKB mode spacing to either side of Omega =
// omega: then the condition kappa(omega) >= 1 / uncertainty comes from a natural frequency close
// to omega (near one, 1 / kappa falls linearly with the distance to it), not from the basis.
bool resolved_nearby(const PlaneSetup& setup,
                     double omega,
                     bool driven_at_b,
                     const EndDisplacement& end,
                     double uncertainty) {
  const double h = 0.25 * wkb_mode_spacing(setup);
  for (double side : {omega - h, omega + h}) {
    if (side <= 0.0) continue;
    if (!(solve_forcing(setup, side, driven_at_b, end).condition * uncertainty < 1.0)) return false;
  }
  return true;
}

// The diagnostic of a frequency whose boundary matrix is singular within its uncertainty: a
// resonance when the response is resolved nearby, else beyond the series' accuracy.
std::string unresolved_reason(double omega, bool resonance, double condition, double uncertainty) {
  const std::string measure = fmt::format(
      "condition number {:.2e} of the row-equilibrated boundary matrix times its uncertainty "
      "{:.1e} >= 1",
      condition, uncertainty);
  if (resonance)
    return fmt::format(
        "forcing at Omega = {:g} is at a natural frequency within the series' accuracy ({}): "
        "resonance, no finite response",
        omega, measure);
  return fmt::format(
      "forcing at Omega = {:g}: the response is not determined by the series at this frequency "
      "({}, "
      "also a quarter mode spacing away: not a resonance); declined",
      omega, measure);
}

// The response at one frequency [rad/s] (the resonance rule is in frobenius_forced.hpp).
ForcedResponse response_at(const PlaneSetup& base,
                           bool driven_at_b,
                           const EndDisplacement& end,
                           double omega_rad_s,
                           const FieldStations& stations,
                           const CableUnits& units,
                           ForcedWork& work) {
  ForcedResponse response;
  response.omega_rad_s = omega_rad_s;
  response.s_m = stations.s_m;
  const double omega = omega_rad_s / units.frequency_rad_s;
  if (!(forced_centres_needed(base, omega) <= kForcedMaxCentres)) {
    decline(response, *basis_trouble(base, omega, {}, {}, 0.0), false);
    return response;
  }
  const PlaneSetup setup = forced_setup(base, false), check = forced_setup(base, true);
  const ForcedSolve a = solve_forcing(setup, omega, driven_at_b, end);
  const ForcedSolve b = solve_forcing(check, omega, driven_at_b, end);
  work.terms = std::max(work.terms, a.terms);
  work.centres = std::max(work.centres, a.centres);
  work.evaluations += 2;
  const double uncertainty = std::max({a.entry_error, b.entry_error, matrix_difference(a, b)});
  if (const auto trouble = basis_trouble(base, omega, a, b, uncertainty)) {
    decline(response, *trouble, false);
    return response;
  }
  const double inaccuracy = a.condition * uncertainty;
  if (!(inaccuracy < 1.0)) {
    const bool resonance = resolved_nearby(setup, omega, driven_at_b, end, uncertainty);
    decline(response, unresolved_reason(omega, resonance, a.condition, uncertainty), resonance);
    return response;
  }
  set_fields(response, setup, omega, a.coefficients, stations, units);
  ForcedResponse finer = response;
  set_fields(finer, check, omega, b.coefficients, stations, units);
  if (!finite_fields(response) || !finite_fields(finer)) {
    decline(response, fmt::format("forcing at Omega = {:g}: non-finite fields; declined", omega),
            false);
    return response;
  }
  const double scale = std::max(peak(response), std::numeric_limits<double>::min());
  response.relative_error_estimate = inaccuracy + std::abs(peak(response) - peak(finer)) / scale;
  response.near_resonance = a.condition >= kNearResonanceCondition;
  return response;
}

}  // namespace

double forced_centres_needed(const PlaneSetup& setup, double omega) {
  // Phase from the apex to the farther end, Omega sqrt(mu) int_0^sigma C^(-1/2) dsigma (trapezoid,
  // 64 panels: a count, not a result); each expansion covers at least kForcedPhasePerExpansion.
  const double sigma_max = std::max(std::abs(setup.sigma1), std::abs(setup.sigma2));
  double integral = 0.0;
  const int panels = 64;
  for (int i = 0; i <= panels; ++i) {
    const double sigma = sigma_max * i / panels;
    integral += ((i == 0 || i == panels) ? 0.5 : 1.0) * std::pow(1.0 + sigma * sigma, -0.25);
  }
  integral *= sigma_max / panels;
  return 1.0 + omega * std::sqrt(setup.mu) * integral / kForcedPhasePerExpansion;
}

EndDisplacement forced_end_displacement(const ForcedRequest& forced,
                                        double sigma_end,
                                        double length_m) {
  const double a = length_m;
  EndDisplacement end;
  switch (forced.direction) {
    case ForcingDirection::Tangential:
      end.u = forced.amplitude_m / a;
      break;
    case ForcingDirection::Normal:
      end.v = forced.amplitude_m / a;
      break;
    case ForcingDirection::OutOfPlane:
      end.u = forced.amplitude_m / a;
      break;
    case ForcingDirection::GivenVector: {
      // Resolved on the end's unit tangent t = (1, sigma)/C and normal n = (-sigma, 1)/C.
      const double C_end = std::sqrt(1.0 + sigma_end * sigma_end);
      const Vec2 d = forced.unit_vector() * forced.amplitude_m / a;
      const Vec2 t(1.0 / C_end, sigma_end / C_end), n(-sigma_end / C_end, 1.0 / C_end);
      end.u = d.dot(t);
      end.v = d.dot(n);
      break;
    }
  }
  return end;
}

std::vector<ForcedResponse> frobenius_forced_responses(const PlaneSetup& base,
                                                       const ForcedRequest& forced,
                                                       const FieldStations& stations,
                                                       const CableUnits& units,
                                                       ForcedWork& work,
                                                       WorkMeter* meter) {
  const bool at_b = forced.end == CableEnd::B;
  PlaneSetup setup = base;
  setup.inplane = forced.direction != ForcingDirection::OutOfPlane;
  const EndDisplacement end =
      forced_end_displacement(forced, at_b ? base.sigma2 : base.sigma1, units.length_m);
  std::vector<ForcedResponse> responses;
  for (double omega_rad_s : forced.omegas_rad_s) {
    try {
      responses.push_back(response_at(setup, at_b, end, omega_rad_s, stations, units, work));
    } catch (const std::domain_error& e) {
      // The series engine met a logarithmic resonance it does not compute: this frequency only.
      ForcedResponse response;
      response.omega_rad_s = omega_rad_s;
      response.s_m = stations.s_m;
      decline(response,
              fmt::format("forcing at {:g} rad/s: series failure ({}); declined", omega_rad_s,
                          e.what()),
              false);
      responses.push_back(std::move(response));
    }
    if (meter && meter->stop_after(static_cast<long>(responses.size()))) break;
  }
  return responses;
}

}  // namespace catena::internal
