// SPDX-License-Identifier: MIT
#pragma once
// Gale's inextensible catenary integrated directly in sigma = (s - s_apex) / a: no series, no
// change of variable, Boost.Odeint Runge-Kutta-Fehlberg 7(8). An independent check of the
// frobenius solver (docs/explanation/methods/frobenius.md) shared by the frobenius tools.
//
// Units a = H / W0 = 1 and H = 1; C = sqrt(1 + sigma^2), W2 = Omega^2 with Omega = w / sqrt(g/a),
// mu = M / m:
//   in plane, state (u, w, phi, tau):  u' = w / C^2,  w' = phi - u / C^2,
//                                      (C phi)' = -tau / C^2 - mu W2 w,  tau' = phi / C - W2 u
//   out of plane, state (v, p):        v' = p / C,  p' = -mu W2 v
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>

namespace catena_tools {

/// Integrator settings: error tolerances of the controlled stepper, the first step as the interval
/// divided by `initial_divisions`, and the mass ratio mu = M / m.
struct SigmaOdeSettings {
  double abs_tol = 1e-13;
  double rel_tol = 1e-12;
  double initial_divisions = 200.0;
  double mu = 1.0;
};

/// Integrates the in-plane (N = 4) or out-of-plane (N = 2) system from s1 to s2 at Omega^2 = w2.
template <int N>
std::array<double, N> integrate_sigma_ode(
    std::array<double, N> y, double s1, double s2, double w2, const SigmaOdeSettings& settings) {
  static_assert(N == 2 || N == 4, "out of plane (2) or in plane (4)");
  namespace odeint = boost::numeric::odeint;
  const double mu = settings.mu;
  auto rhs = [w2, mu](const std::array<double, N>& x, std::array<double, N>& dx, double s) {
    const double C = std::sqrt(1.0 + s * s);
    if constexpr (N == 4) {
      dx[0] = x[1] / (C * C);
      dx[1] = x[2] - x[0] / (C * C);
      dx[2] = (-x[3] / (C * C) - mu * w2 * x[1] - (s / C) * x[2]) / C;
      dx[3] = x[2] / C - w2 * x[0];
    } else {
      dx[0] = x[1] / C;
      dx[1] = -mu * w2 * x[0];
    }
  };
  odeint::integrate_adaptive(
      odeint::make_controlled(settings.abs_tol, settings.rel_tol,
                              odeint::runge_kutta_fehlberg78<std::array<double, N>>()),
      rhs, y, s1, s2, (s2 - s1) / settings.initial_divisions);
  return y;
}

/// The end condition of the solutions clamped at s1, evaluated at s2, as a function of Omega: in
/// plane det[u, w](s2) of the two solutions started with phi = 1 and tau = 1; out of plane v(s2).
/// Zero at a natural frequency. `normalised` divides by the norms of the end states, so that
/// the value stays O(1) over a scan.
double clamped_end_determinant(bool inplane,
                               double s1,
                               double s2,
                               double omega,
                               const SigmaOdeSettings& settings,
                               bool normalised = false);

/// A natural frequency by bisection of clamped_end_determinant on [guess (1 - half_width),
/// guess (1 + half_width)]; NaN when the interval does not bracket a sign change.
double bisect_natural_frequency(bool inplane,
                                double s1,
                                double s2,
                                double guess,
                                double half_width,
                                int iterations,
                                const SigmaOdeSettings& settings);

}  // namespace catena_tools
