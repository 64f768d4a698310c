// SPDX-License-Identifier: MIT
// The damped forced response of the frobenius solver: see frobenius_damped_forced.hpp.
#include "solvers/frobenius/frobenius_damped_forced.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace catena::internal {

namespace {

using Complex = DampedComplex;
using R = DampedReal;

// The forced basis settings (frobenius_forced.cpp's rule): the wave limit per expansion, the cap
// on centres; `finer` halves the phase and cuts the series 1e-3 finer.
DampedSetup forced_setup(const DampedSetup& base, bool finer) {
  DampedSetup setup = base;
  auto& s = setup.plane.settings;
  s.max_phase_per_expansion = finer ? 0.5 * kForcedPhasePerExpansion : kForcedPhasePerExpansion;
  s.max_centres = finer ? 2 * kForcedMaxCentres : kForcedMaxCentres;
  if (finer) s.term_tolerance = std::max(s.term_tolerance * 1e-3, 1e-30);
  return setup;
}

struct DampedSolve {
  std::vector<Complex> coefficients;       // in the unscaled basis
  std::vector<std::vector<Complex>> rows;  // scaled matrix, rows equilibrated
  double entry_error = 0.0;
  double condition = 0.0;
  long terms = 0;
  int centres = 0;
  bool truncated = false;
};

// 1-norm condition number of a small complex matrix (its inverse column by column).
double condition_1(const std::vector<std::vector<Complex>>& a) {
  const std::size_t n = a.size();
  R norm = 0, inverse_norm = 0;
  for (std::size_t j = 0; j < n; ++j) {
    R column = 0;
    for (std::size_t i = 0; i < n; ++i) column += std::abs(a[i][j]);
    norm = std::max(norm, column);
    std::vector<Complex> e(n, Complex(0));
    e[j] = Complex(1);
    R inverse_column = 0;
    for (const Complex& x : solve_dense(a, e)) inverse_column += std::abs(x);
    inverse_norm = std::max(inverse_norm, inverse_column);
  }
  const double kappa = static_cast<double>(norm * inverse_norm);
  return std::isfinite(kappa) ? kappa : std::numeric_limits<double>::infinity();
}

DampedSolve solve_forcing(const DampedSetup& setup,
                          double omega,
                          bool driven_at_b,
                          const EndDisplacement& end) {
  const DampedMatrix m = damped_boundary_matrix(setup, Complex(0, omega));
  const std::size_t n = m.a.size();
  DampedSolve out;
  out.terms = m.terms;
  out.centres = m.centres;
  out.truncated = !m.converged;
  std::vector<Complex> rhs(n, Complex(0));
  const double sigma_end = driven_at_b ? setup.plane.sigma2 : setup.plane.sigma1;
  const std::size_t row = driven_at_b ? n / 2 : 0;
  rhs[row] = R(end.u);
  if (setup.plane.inplane) rhs[row + 1] = R(end.v) / R(1.0 + sigma_end * sigma_end);  // DU = V/C^2
  out.coefficients = solve_dense(m.a, rhs);
  for (std::size_t j = 0; j < n; ++j) out.coefficients[j] /= m.column_scale[j];
  out.rows = m.a;
  for (std::size_t i = 0; i < n; ++i) {
    R big = 0;
    for (const Complex& x : m.a[i]) big = std::max(big, std::abs(x));
    if (!(big > 0)) big = 1;
    for (std::size_t j = 0; j < n; ++j) {
      out.rows[i][j] /= big;
      out.entry_error = std::max(out.entry_error, static_cast<double>(m.error[i][j] / big));
    }
  }
  out.entry_error =
      std::max(out.entry_error, static_cast<double>(std::numeric_limits<R>::epsilon()));
  out.condition = condition_1(out.rows);
  return out;
}

// The fields of the combination c at lambda = i omega, as real and imaginary parts.
void set_fields(ForcedResponse& r,
                const DampedSetup& setup,
                double omega,
                const std::vector<Complex>& c,
                const FieldStations& stations,
                const CableUnits& units) {
  const bool inplane = setup.plane.inplane;
  const auto values = damped_fields(setup, Complex(0, omega), c, stations.sigma, inplane);
  const Index n = stations.s_m.size();
  auto fill = [&](Vector& re, Vector& im, auto get, double unit) {
    re.resize(n);
    im.resize(n);
    for (Index k = 0; k < n; ++k) {
      const Complex x = get(values[static_cast<std::size_t>(k)]) * R(unit);
      re(k) = static_cast<double>(x.real());
      im(k) = static_cast<double>(x.imag());
    }
  };
  if (inplane) {
    fill(
        r.u, r.u_imag, [](const DampedFieldValues& f) { return f.u; }, units.length_m);
    fill(
        r.w, r.w_imag, [](const DampedFieldValues& f) { return f.v; }, units.length_m);
    fill(
        r.tension_n, r.tension_imag_n, [](const DampedFieldValues& f) { return f.t; },
        units.tension_n);
    r.max_abs_tension_n =
        (r.tension_n.cwiseAbs2() + r.tension_imag_n.cwiseAbs2()).cwiseSqrt().maxCoeff();
  } else {
    fill(
        r.v, r.v_imag, [](const DampedFieldValues& f) { return f.u; }, units.length_m);
  }
}

// max |tau| in plane, max |v| out of plane.
double peak(const ForcedResponse& r) {
  if (r.tension_n.size()) return r.max_abs_tension_n;
  return r.v.size() ? (r.v.cwiseAbs2() + r.v_imag.cwiseAbs2()).cwiseSqrt().maxCoeff() : 0.0;
}

bool finite_fields(const ForcedResponse& r) {
  return r.u.allFinite() && r.w.allFinite() && r.v.allFinite() && r.tension_n.allFinite() &&
         r.u_imag.allFinite() && r.w_imag.allFinite() && r.v_imag.allFinite() &&
         r.tension_imag_n.allFinite() && std::isfinite(r.max_abs_tension_n);
}

ForcedResponse declined(double omega_rad_s, const Vector& s, std::string reason) {
  ForcedResponse r;
  r.omega_rad_s = omega_rad_s;
  r.s_m = s;
  r.diagnostic = std::move(reason);
  return r;
}

ForcedResponse response_at(const DampedSetup& base,
                           bool driven_at_b,
                           const EndDisplacement& end,
                           double omega_rad_s,
                           const FieldStations& stations,
                           const CableUnits& units,
                           ForcedWork& work) {
  const double omega = omega_rad_s / units.frequency_rad_s;
  const double needed = forced_centres_needed(base.plane, omega);
  if (!(needed <= kForcedMaxCentres))
    return declined(omega_rad_s, stations.s_m,
                    fmt::format("forcing at Omega = {:g} is beyond the frobenius series: about "
                                "{:.3g} expansion centres would be needed (cap {}); declined",
                                omega, needed, kForcedMaxCentres));
  const DampedSetup setup = forced_setup(base, false), check = forced_setup(base, true);
  const DampedSolve a = solve_forcing(setup, omega, driven_at_b, end);
  const DampedSolve b = solve_forcing(check, omega, driven_at_b, end);
  work.terms = std::max(work.terms, a.terms);
  work.centres = std::max(work.centres, a.centres);
  work.evaluations += 2;
  double difference = 0.0;
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    for (std::size_t j = 0; j < a.rows.size(); ++j)
      difference = std::max(difference, static_cast<double>(std::abs(a.rows[i][j] - b.rows[i][j])));
  const double uncertainty = std::max({a.entry_error, b.entry_error, difference});
  if (a.truncated || b.truncated || !(uncertainty <= kForcedMaxEntryError))
    return declined(omega_rad_s, stations.s_m,
                    fmt::format("forcing at Omega = {:g}: the boundary matrix is known only to "
                                "{:.1e}{}; declined",
                                omega, uncertainty,
                                a.truncated || b.truncated ? " (series hit max_terms)" : ""));
  const double inaccuracy = a.condition * uncertainty;
  if (!(inaccuracy < 1.0))
    return declined(omega_rad_s, stations.s_m,
                    fmt::format("forcing at Omega = {:g}: condition number {:.2e} times the "
                                "matrix uncertainty {:.1e} >= 1: beyond the series' accuracy "
                                "(damped: not a resonance); declined",
                                omega, a.condition, uncertainty));
  ForcedResponse response;
  response.omega_rad_s = omega_rad_s;
  response.s_m = stations.s_m;
  set_fields(response, setup, omega, a.coefficients, stations, units);
  ForcedResponse finer = response;
  set_fields(finer, check, omega, b.coefficients, stations, units);
  if (!finite_fields(response) || !finite_fields(finer))
    return declined(omega_rad_s, stations.s_m,
                    fmt::format("forcing at Omega = {:g}: non-finite fields; declined", omega));
  const double scale = std::max(peak(response), std::numeric_limits<double>::min());
  response.relative_error_estimate = inaccuracy + std::abs(peak(response) - peak(finer)) / scale;
  response.near_resonance = a.condition >= 1e3;
  return response;
}

}  // namespace

std::vector<ForcedResponse> frobenius_damped_forced_responses(const DampedSetup& base,
                                                              const ForcedRequest& forced,
                                                              const FieldStations& stations,
                                                              const CableUnits& units,
                                                              ForcedWork& work,
                                                              WorkMeter* meter) {
  const bool at_b = forced.end == CableEnd::B;
  DampedSetup setup = base;
  setup.plane.inplane = forced.direction != ForcingDirection::OutOfPlane;
  const EndDisplacement end =
      forced_end_displacement(forced, at_b ? base.plane.sigma2 : base.plane.sigma1, units.length_m);
  std::vector<ForcedResponse> responses;
  for (double omega_rad_s : forced.omegas_rad_s) {
    try {
      responses.push_back(response_at(setup, at_b, end, omega_rad_s, stations, units, work));
    } catch (const std::domain_error& e) {
      responses.push_back(
          declined(omega_rad_s, stations.s_m,
                   fmt::format("forcing at {:g} rad/s: series failure ({}); declined", omega_rad_s,
                               e.what())));
    }
    if (meter && meter->stop_after(static_cast<long>(responses.size()))) break;
  }
  return responses;
}

}  // namespace catena::internal
