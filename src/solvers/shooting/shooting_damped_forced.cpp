// SPDX-License-Identifier: MIT
// Damped forced response: see shooting_damped_forced.hpp.
#include "solvers/shooting/shooting_damped_forced.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

#include "solvers/shooting/shooting_damped_integrator.hpp"
#include "solvers/shooting/shooting_forced.hpp"
#include "solvers/shooting/shooting_profile.hpp"

namespace catena::internal {

namespace {

using Complex = std::complex<double>;

// As the undamped response: the tight shot's factor and its error ratio assumed.
constexpr double kEstimateFactor = 0.01;
constexpr double kTightErrorRatio = 0.1;

// The response of one damped shot: the complex combination of its end basis that meets the drive.
ComplexProfile damped_response(const DampedShot& shot,
                               const Drive& drive,
                               const ShootingCoefficients& k,
                               const Vector& stations,
                               bool from_b) {
  const int D = drive.plane == Plane::InPlane ? 2 : 1;
  const Eigen::MatrixXcd phi_end = shot.y_end.topRows(D);
  const Eigen::VectorXcd d = (drive.d / k.length_m).cast<Complex>();
  const Eigen::VectorXcd c = phi_end.fullPivLu().solve(d);
  if (!c.allFinite()) throw ShootingFailure("the damped end matrix Phi(L) is singular");
  ComplexProfile p = evaluate_damped_profile(shot, c, k, stations, from_b, drive.plane);
  if (drive.string_only) p = {string_as_inplane(p.real), string_as_inplane(p.imag)};
  return p;
}

// The largest change of the complex response between two computations, relative to each
// quantity's largest modulus (displacements and tension separately).
double complex_change(const ComplexProfile& a, const ComplexProfile& b) {
  double change = 0.0;
  const std::pair<const Vector*, const Vector*> parts[4][2] = {
      {{&a.real.u, &a.imag.u}, {&b.real.u, &b.imag.u}},
      {{&a.real.w, &a.imag.w}, {&b.real.w, &b.imag.w}},
      {{&a.real.v, &a.imag.v}, {&b.real.v, &b.imag.v}},
      {{&a.real.tension, &a.imag.tension}, {&b.real.tension, &b.imag.tension}}};
  for (const auto& [x, y] : parts) {
    if (x.first->size() == 0 || x.first->size() != y.first->size()) continue;
    const double scale = (y.first->cwiseAbs2() + y.second->cwiseAbs2()).cwiseSqrt().maxCoeff();
    const Vector re = *x.first - *y.first, im = *x.second - *y.second;
    if (scale > 0.0)
      change = std::max(change, (re.cwiseAbs2() + im.cwiseAbs2()).cwiseSqrt().maxCoeff() / scale);
  }
  return change;
}

void set_response(ForcedResponse& response,
                  const ComplexProfile& p,
                  const Vector& stations,
                  bool inplane) {
  response.s_m = stations;
  if (inplane) {
    response.u = p.real.u, response.u_imag = p.imag.u;
    response.w = p.real.w, response.w_imag = p.imag.w;
    response.tension_n = p.real.tension, response.tension_imag_n = p.imag.tension;
  } else {
    response.v = p.real.v, response.v_imag = p.imag.v;
    response.tension_n = Vector::Zero(stations.size());
    response.tension_imag_n = Vector::Zero(stations.size());
  }
  response.max_abs_tension_n =
      (response.tension_n.cwiseAbs2() + response.tension_imag_n.cwiseAbs2()).cwiseSqrt().maxCoeff();
}

ForcedResponse damped_forced_response(DampedShootingIntegrator& integrator,
                                      const ShootingCoefficients& k,
                                      const ForcedRequest& forced,
                                      const Drive& drive,
                                      double omega,
                                      const Vector& stations,
                                      double relative_tolerance,
                                      bool estimate) {
  ForcedResponse response;
  response.omega_rad_s = omega;
  if (drive.diagnostic) {
    response.diagnostic = *drive.diagnostic;
    return response;
  }
  const bool from_b = forced.end == CableEnd::A;  // start at the fixed end
  const std::vector<double> x = scaled_stations(stations, k.length_m, from_b);
  const Complex lambda(0.0, omega);
  const ComplexProfile p =
      damped_response(integrator.shoot(lambda, 1.0, &x, from_b), drive, k, stations, from_b);
  set_response(response, p, stations, drive.plane == Plane::InPlane || drive.string_only);
  if (!estimate) {
    response.relative_error_estimate = -1.0;
    return response;
  }
  const ComplexProfile q = damped_response(integrator.shoot(lambda, kEstimateFactor, &x, from_b),
                                           drive, k, stations, from_b);
  response.relative_error_estimate =
      std::max(complex_change(p, q) / (1.0 - kTightErrorRatio), relative_tolerance);
  return response;
}

}  // namespace

ForcedOutcome shooting_damped_forced_responses(DampedShootingIntegrator& integrator,
                                               const ShootingCoefficients& k,
                                               const ForcedRequest& forced,
                                               const Vector& stations,
                                               const IntegratorSettings& settings,
                                               bool estimate,
                                               WorkMeter* meter) {
  ForcedOutcome outcome;
  SolverSummary& summary = outcome.summary;
  const std::size_t asked = forced.omegas_rad_s.size();
  const long rhs_before = integrator.total_rhs_evaluations();
  try {
    const Drive drive = make_drive(k, forced);
    for (double omega : forced.omegas_rad_s) {
      outcome.responses.push_back(damped_forced_response(
          integrator, k, forced, drive, omega, stations, settings.relative_tolerance, estimate));
      if (!outcome.responses.back().diagnostic.empty()) {
        summary.warnings.push_back(fmt::format("forced response at {:.10g} rad/s: {}", omega,
                                               outcome.responses.back().diagnostic));
      }
      if (meter && meter->stop_after(static_cast<long>(outcome.responses.size()))) break;
    }
    summary.termination = Termination::Converged;
    summary.message =
        fmt::format("{} of {} forced frequencies (damped)", outcome.responses.size(), asked);
    summary.iterations = static_cast<long>(asked);
    summary.operations = integrator.total_rhs_evaluations() - rhs_before;
  } catch (const ShootingFailure& failure) {
    summary.termination =
        outcome.responses.empty() ? Termination::NumericalFailure : Termination::NoConvergence;
    summary.message = fmt::format("{} of {} forced frequencies ({})", outcome.responses.size(),
                                  asked, failure.what());
    summary.warnings.push_back(fmt::format("forced response: {}", failure.what()));
  }
  return outcome;
}

ForcedOutcome shooting_damped_forced_responses(const ShootingCoefficients& k,
                                               const ForcedRequest& forced,
                                               const Vector& stations,
                                               const IntegratorSettings& settings,
                                               WorkMeter* meter) {
  try {
    DampedShootingIntegrator integrator(damped_forced_plane(k, forced), k, settings);
    return shooting_damped_forced_responses(integrator, k, forced, stations, settings, true, meter);
  } catch (const ShootingFailure& failure) {
    ForcedOutcome outcome;
    outcome.summary.termination = Termination::NumericalFailure;
    outcome.summary.message =
        fmt::format("0 of {} forced frequencies ({})", forced.omegas_rad_s.size(), failure.what());
    outcome.summary.warnings.push_back(fmt::format("forced response: {}", failure.what()));
    return outcome;
  }
}

Plane damped_forced_plane(const ShootingCoefficients& k, const ForcedRequest& forced) {
  return make_drive(k, forced).plane;
}

}  // namespace catena::internal
