// SPDX-License-Identifier: MIT
// Tests of the damped frobenius solver (Gale's viscous medium, docs/explanation/methods/
// frobenius.md, "Damping"): proportional drag against the closed form lambda = -eta/2 +-
// i sqrt(Omega0^2 - eta^2/4) from the solver's own undamped roots, delta on its own; distinct
// drag against a direct integration of Gale's first-order system in sigma (Boost.Odeint, complex
// lambda, no series); zeta = 1e-4; an overdamped root; out of plane; undamped unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

#include "catena/solvers/frobenius_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;
using Solved = catena::testing::SolvedProblem;

SolveRequest modes(int inplane, int outofplane) {
  return catena::testing::modes_request(inplane, outofplane);
}

// The Gale problem with drag eta1, eta2 in Gale's units (c = eta m sqrt(g/a), eq. 2.28e,f).
Problem with_drag(Problem problem, double eta1, double eta2) {
  const Solved undamped = catena::testing::prepare(problem);
  const double scale = problem.cable.mass_kg_per_m * undamped.groups.gale_frequency_scale_rad_s;
  problem.cable.damping.tangential_n_s_per_m2 = eta1 * scale;
  problem.cable.damping.normal_n_s_per_m2 = eta2 * scale;
  return problem;
}

Solved run(const Problem& problem, const SolveRequest& request) {
  return catena::testing::solve_problem(solve_frobenius, problem, request,
                                        FrobeniusSolverOptions{});
}

// lambda / sqrt(g/a) of a mode.
Complex gale_lambda(const Mode& mode, const Solved& s) {
  const double unit = s.groups.gale_frequency_scale_rad_s;
  return {-mode.decay_rate_1_s / unit, mode.omega_rad_s / unit};
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Proportional drag eta (Gale's form, mu = 1): every undamped root Omega0 gives
// lambda = -eta/2 + i sqrt(Omega0^2 - eta^2/4).
void expect_proportional(const ModalResult& damped,
                         const ModalResult& undamped,
                         double eta,
                         const Solved& s) {
  ASSERT_EQ(damped.summary.termination, Termination::Converged) << damped.summary.message;
  ASSERT_EQ(damped.modes.size(), undamped.modes.size());
  for (std::size_t i = 0; i < damped.modes.size(); ++i) {
    const double w0 = *undamped.modes[i].gale_ratio;
    const Complex l = gale_lambda(damped.modes[i], s);
    EXPECT_LT(rel(l.imag(), std::sqrt(w0 * w0 - eta * eta / 4)), 1e-10) << i;
    EXPECT_LT(rel(-l.real(), eta / 2), 1e-10) << i;  // delta on its own
    EXPECT_LT(damped.modes[i].decay_rate_error_estimate, 1e-10) << i;
    EXPECT_GE(damped.modes[i].decay_rate_error_estimate, 0.0) << i;
    EXPECT_NEAR(damped.modes[i].damping_ratio, eta / 2 / std::abs(l), 1e-12) << i;
  }
  EXPECT_EQ(damped.proved_count_below_top, static_cast<int>(damped.modes.size()))
      << damped.summary.notes.back();
}

TEST(FrobeniusDampedTest, ProportionalDragMatchesTheClosedFormInBothPlanes) {
  const Problem problem = make_gale_xi_problem(-0.524, 1.116);
  const Solved undamped = run(problem, modes(4, 4));
  const double eta = 0.3;
  const Solved damped = run(with_drag(problem, eta, eta), modes(4, 4));
  ASSERT_TRUE(damped.output.inplane && damped.output.outofplane);
  expect_proportional(*damped.output.inplane, *undamped.output.inplane, eta, damped);
  expect_proportional(*damped.output.outofplane, *undamped.output.outofplane, eta, damped);
  EXPECT_TRUE(damped.output.inplane->overdamped.empty());
}

TEST(FrobeniusDampedTest, DampingRatioOfOneInTenThousandKeepsDeltaToTenDigits) {
  const Problem problem = make_gale_sag_problem(0.0, 0.5);
  const Solved undamped = run(problem, modes(3, 0));
  const double w1 = *undamped.output.inplane->modes[0].gale_ratio;
  const double eta = 2e-4 * w1;  // zeta = 1e-4 on the first mode
  const Solved damped = run(with_drag(problem, eta, eta), modes(3, 0));
  expect_proportional(*damped.output.inplane, *undamped.output.inplane, eta, damped);
  EXPECT_NEAR(damped.output.inplane->modes[0].damping_ratio, 1e-4, 1e-14);
}

TEST(FrobeniusDampedTest, HeavyDragMakesTheFirstModeOverdamped) {
  const Problem problem = make_gale_xi_problem(-0.524, 1.116);
  const Solved undamped = run(problem, modes(0, 4));
  const auto& u = undamped.output.outofplane->modes;
  const double w1 = *u[0].gale_ratio, w2 = *u[1].gale_ratio;
  const double eta = 1.5 * w1 + 0.5 * std::min(w2, 2.0 * w1);  // 2 w1 < eta < 2 w2
  ASSERT_LT(eta, 2.0 * w2);
  const Solved damped = run(with_drag(problem, eta, eta), modes(0, 3));
  const ModalResult& r = *damped.output.outofplane;
  ASSERT_EQ(r.overdamped.size(), 2u) << r.summary.notes.back();
  const double root = std::sqrt(eta * eta / 4 - w1 * w1);
  const double unit = damped.groups.gale_frequency_scale_rad_s;
  EXPECT_LT(rel(r.overdamped[0].decay_rate_1_s / unit, eta / 2 - root), 1e-10);
  EXPECT_LT(rel(r.overdamped[1].decay_rate_1_s / unit, eta / 2 + root), 1e-10);
  EXPECT_EQ(r.overdamped[0].omega_rad_s, 0.0);
  EXPECT_EQ(r.overdamped[0].damping_ratio, 1.0);
  ASSERT_EQ(r.modes.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const double w0 = *u[static_cast<std::size_t>(i) + 1].gale_ratio;
    const Complex l = gale_lambda(r.modes[static_cast<std::size_t>(i)], damped);
    EXPECT_LT(rel(l.imag(), std::sqrt(w0 * w0 - eta * eta / 4)), 1e-10) << i;
    EXPECT_LT(rel(-l.real(), eta / 2), 1e-10) << i;
  }
  EXPECT_EQ(r.proved_count_below_top, 3) << r.summary.notes.back();
}

TEST(FrobeniusDampedTest, ProportionalDragWithAddedMassUsesTheNormalMass) {
  // c_t = alpha m, c_n = alpha (m + ma): lambda = -alpha/2 + i sqrt(w0^2 - alpha^2/4) [rad/s].
  Problem problem = make_gale_xi_problem(-0.7, 1.2);
  problem.cable.added_mass_kg_per_m = 0.6 * problem.cable.mass_kg_per_m;
  const Solved undamped = run(problem, modes(3, 3));
  const double alpha = 0.2 * undamped.output.inplane->modes[0].omega_rad_s;
  problem.cable.damping.tangential_n_s_per_m2 = alpha * problem.cable.mass_kg_per_m;
  problem.cable.damping.normal_n_s_per_m2 = alpha * problem.cable.normal_mass_kg_per_m();
  const Solved damped = run(problem, modes(3, 3));
  for (const auto& [d, u] : {std::pair{damped.output.inplane, undamped.output.inplane},
                             std::pair{damped.output.outofplane, undamped.output.outofplane}}) {
    ASSERT_EQ(d->summary.termination, Termination::Converged) << d->summary.message;
    ASSERT_EQ(d->modes.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      const double w0 = u->modes[i].omega_rad_s;
      EXPECT_LT(rel(d->modes[i].omega_rad_s, std::sqrt(w0 * w0 - alpha * alpha / 4)), 1e-10) << i;
      EXPECT_LT(rel(d->modes[i].decay_rate_1_s, alpha / 2), 1e-10) << i;
    }
    EXPECT_EQ(d->proved_count_below_top, 3);
  }
}

// Gale's first-order system in sigma (eqs. 2.33, units a and H, C = sqrt(1 + s^2)) with complex
// lambda: u' = w/C^2, w' = phi - u/C^2, tau' = phi/C + mu1 u, (C phi)' = -tau/C^2 + mu2 w, as 8
// real unknowns (real and imaginary parts of u, w, phi, tau).
using State8 = std::vector<double>;  // (a std::array state trips a GCC false positive in odeint)
std::array<Complex, 4> integrate(
    std::array<Complex, 4> y0, double s1, double s2, Complex mu1, Complex mu2) {
  namespace odeint = boost::numeric::odeint;
  auto rhs = [&](const State8& x, State8& dx, double s) {
    const double C = std::sqrt(1.0 + s * s);
    const Complex u(x[0], x[1]), w(x[2], x[3]), phi(x[4], x[5]), tau(x[6], x[7]);
    const Complex d[4] = {w / (C * C), phi - u / (C * C), phi / C + mu1 * u,
                          (-tau / (C * C) + mu2 * w - (s / C) * phi) / C};
    const int order[4] = {0, 1, 3, 2};  // state (u, w, phi, tau): tau' is d[2], phi' is d[3]
    for (int k = 0; k < 4; ++k) {
      dx[2 * k] = d[order[k]].real();
      dx[2 * k + 1] = d[order[k]].imag();
    }
  };
  State8 y(8, 0.0);
  for (int k = 0; k < 4; ++k) {
    y[2 * k] = y0[static_cast<std::size_t>(k)].real();
    y[2 * k + 1] = y0[static_cast<std::size_t>(k)].imag();
  }
  odeint::integrate_adaptive(
      odeint::make_controlled(1e-14, 1e-13, odeint::runge_kutta_fehlberg78<State8>()), rhs, y, s1,
      s2, (s2 - s1) / 200.0);
  return {Complex(y[0], y[1]), Complex(y[2], y[3]), Complex(y[4], y[5]), Complex(y[6], y[7])};
}

// u = w = 0 at both ends: the 2x2 determinant of (u, w) at s2 of the solutions started with
// phi = 1 and tau = 1 at s1.
Complex shooting_det(double s1, double s2, Complex lambda, double eta1, double eta2) {
  const Complex mu1 = lambda * lambda + eta1 * lambda, mu2 = lambda * lambda + eta2 * lambda;
  const auto a = integrate({0.0, 0.0, 1.0, 0.0}, s1, s2, mu1, mu2);
  const auto b = integrate({0.0, 0.0, 0.0, 1.0}, s1, s2, mu1, mu2);
  return a[0] * b[1] - a[1] * b[0];
}

// The root of the shooting determinant near `guess` by the secant method.
Complex shooting_root(double s1, double s2, Complex guess, double eta1, double eta2) {
  Complex x0 = guess * 1.001, x1 = guess;
  Complex f0 = shooting_det(s1, s2, x0, eta1, eta2), f1 = shooting_det(s1, s2, x1, eta1, eta2);
  for (int it = 0; it < 30 && std::abs(x1 - x0) > 1e-15 * std::abs(x1); ++it) {
    const Complex x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1, f0 = f1, x1 = x2, f1 = shooting_det(s1, s2, x1, eta1, eta2);
  }
  return x1;
}

TEST(FrobeniusDampedTest, DistinctDragAgreesWithDirectIntegrationOfGalesSystem) {
  const Problem problem = make_gale_xi_problem(-0.524, 1.116);
  const double eta1 = 0.05, eta2 = 0.4;
  const Solved damped = run(with_drag(problem, eta1, eta2), modes(4, 0));
  const ModalResult& r = *damped.output.inplane;
  ASSERT_EQ(r.summary.termination, Termination::Converged) << r.summary.message;
  ASSERT_EQ(r.modes.size(), 4u);
  EXPECT_EQ(r.proved_count_below_top, 4) << r.summary.notes.back();
  for (const Mode& mode : r.modes) {
    const Complex l = gale_lambda(mode, damped);
    const Complex ref = shooting_root(damped.groups.sigma1, damped.groups.sigma2, l, eta1, eta2);
    EXPECT_LT(rel(l.imag(), ref.imag()), 1e-9) << mode.index;
    EXPECT_LT(rel(l.real(), ref.real()), 1e-9) << mode.index;  // delta on its own
    // Energy bound: delta lies between the two drags' halves.
    EXPECT_GT(-l.real(), eta1 / 2) << mode.index;
    EXPECT_LT(-l.real(), eta2 / 2) << mode.index;
  }
}

TEST(FrobeniusDampedTest, HeavyDistinctDragOverdampedRootsAgreeWithDirectIntegration) {
  const Problem problem = make_gale_xi_problem(-0.524, 1.116);
  const double eta1 = 1.0, eta2 = 6.0;
  const Solved damped = run(with_drag(problem, eta1, eta2), modes(3, 0));
  const ModalResult& r = *damped.output.inplane;
  ASSERT_EQ(r.summary.termination, Termination::Converged) << r.summary.message;
  ASSERT_FALSE(r.overdamped.empty());
  EXPECT_EQ(r.proved_count_below_top, 3) << r.summary.notes.back();
  const double s1 = damped.groups.sigma1, s2 = damped.groups.sigma2;
  for (const Mode& mode : r.overdamped) {
    const Complex l = gale_lambda(mode, damped);
    EXPECT_EQ(l.imag(), 0.0);
    const Complex ref = shooting_root(s1, s2, l, eta1, eta2);
    EXPECT_LT(std::abs(ref.imag()), 1e-9 * std::abs(ref)) << mode.index;
    EXPECT_LT(rel(l.real(), ref.real()), 1e-9) << mode.index;
    EXPECT_LE(-l.real(), eta2) << mode.index;  // real roots lie in [-max drag, 0]
  }
  for (const Mode& mode : r.modes) {
    const Complex l = gale_lambda(mode, damped);
    const Complex ref = shooting_root(s1, s2, l, eta1, eta2);
    EXPECT_LT(rel(l.imag(), ref.imag()), 1e-9) << mode.index;
    EXPECT_LT(rel(l.real(), ref.real()), 1e-9) << mode.index;
  }
}

TEST(FrobeniusDampedTest, DampedShapesAreComplexAndNormalised) {
  const Problem problem = make_gale_xi_problem(-0.524, 1.116);
  SolveRequest request = modes(2, 2);
  request.shapes = true;
  request.tension = true;
  request.points = 101;
  const Solved damped = run(with_drag(problem, 0.05, 0.4), request);
  for (const Mode& mode : damped.output.inplane->modes) {
    ASSERT_EQ(mode.w_imag.size(), mode.w.size());
    ASSERT_EQ(mode.tension_imag_n.size(), mode.tension_n.size());
    const Eigen::ArrayXd modulus = (mode.w.array().square() + mode.w_imag.array().square()).sqrt();
    EXPECT_NEAR(modulus.maxCoeff(), 1.0, 1e-12);
    EXPECT_GT(mode.w_imag.cwiseAbs().maxCoeff(), 1e-6);  // non-proportional: truly complex
    // Ends fixed.
    EXPECT_LT(std::abs(mode.w(0)) + std::abs(mode.w_imag(0)), 1e-9);
    EXPECT_LT(std::abs(mode.u(mode.u.size() - 1)), 1e-9);
    EXPECT_GT(mode.max_abs_tension_n, 0.0);
  }
  for (const Mode& mode : damped.output.outofplane->modes) ASSERT_EQ(mode.v_imag.size(), 101);
}

// Out of plane (C v')' = mu2 v in sigma, as v' = p/C, p' = mu2 v (real and imaginary parts),
// from v = 0, p = 1 at s1; v at each of `sigmas` (ascending).
std::vector<Complex> outofplane_solution(double s1,
                                         const std::vector<double>& sigmas,
                                         Complex mu2) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 4>;
  auto rhs = [&](const State& x, State& dx, double s) {
    const double C = std::sqrt(1.0 + s * s);
    const Complex v(x[0], x[1]), p(x[2], x[3]);
    const Complex dv = p / C, dp = mu2 * v;
    dx = {dv.real(), dv.imag(), dp.real(), dp.imag()};
  };
  State y{0.0, 0.0, 1.0, 0.0};
  std::vector<Complex> out;
  double at = s1;
  for (double s : sigmas) {
    if (s > at)
      odeint::integrate_adaptive(
          odeint::make_controlled(1e-14, 1e-13, odeint::runge_kutta_fehlberg78<State>()), rhs, y,
          at, s, (s - at) / 50.0);
    at = std::max(at, s);
    out.emplace_back(y[0], y[1]);
  }
  return out;
}

SolveRequest forced_request(ForcingDirection direction, std::vector<double> omegas) {
  SolveRequest request = modes(0, 0);
  request.points = 41;
  ForcedRequest forced;
  forced.direction = direction;
  forced.end = CableEnd::B;
  forced.amplitude_m = 0.01;
  forced.omegas_rad_s = std::move(omegas);
  request.forced = forced;
  return request;
}

double peak_v(const ForcedResponse& r) {
  return (r.v.array().square() + r.v_imag.array().square()).sqrt().maxCoeff();
}

TEST(FrobeniusDampedTest, ForcedResponseAtResonanceIsFiniteAndMatchesDirectIntegration) {
  const Problem problem = with_drag(make_gale_xi_problem(-0.524, 1.116), 0.02, 0.06);
  const Solved modal = run(problem, modes(0, 1));
  const double omega = modal.output.outofplane->modes[0].omega_rad_s;  // omega_d of mode 1
  const Solved s = run(problem, forced_request(ForcingDirection::OutOfPlane, {omega}));
  ASSERT_EQ(s.output.forced.size(), 1u);
  const ForcedResponse& r = s.output.forced[0];
  ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
  EXPECT_FALSE(r.at_resonance);
  ASSERT_EQ(r.v_imag.size(), r.v.size());
  const double a = s.groups.catenary_parameter_m;
  std::vector<double> sigmas;
  for (Index k = 0; k < r.s_m.size(); ++k) sigmas.push_back(s.groups.sigma1 + r.s_m(k) / a);
  const double unit = s.groups.gale_frequency_scale_rad_s;
  const Complex lambda(0.0, omega / unit);
  const auto y = outofplane_solution(s.groups.sigma1, sigmas, lambda * lambda + 0.06 * lambda);
  const double peak = peak_v(r);
  EXPECT_GT(peak, 10 * 0.01);  // amplified at resonance, finite
  for (Index k = 0; k < r.s_m.size(); ++k) {
    const Complex reference = 0.01 * y[static_cast<std::size_t>(k)] / y.back();
    EXPECT_LT(std::abs(Complex(r.v(k), r.v_imag(k)) - reference), 1e-9 * peak) << k;
  }
  EXPECT_LT(r.relative_error_estimate, 1e-8);
}

TEST(FrobeniusDampedTest, ResonancePeakAndHalfPowerBandwidthFollowTheDampingRatio) {
  const Problem base = make_gale_xi_problem(-0.524, 1.116);
  const Solved undamped = run(base, modes(0, 1));
  const double w0 = undamped.output.outofplane->modes[0].omega_rad_s;
  const double unit = undamped.groups.gale_frequency_scale_rad_s;
  const double zeta = 0.01, eta = 2 * zeta * w0 / unit;  // proportional: zeta on mode 1
  std::vector<double> omegas;
  for (int i = 0; i <= 160; ++i) omegas.push_back(w0 * (1.0 - 4 * zeta + 8 * zeta * i / 160.0));
  const Solved s =
      run(with_drag(base, eta, eta), forced_request(ForcingDirection::OutOfPlane, omegas));
  ASSERT_EQ(s.output.forced.size(), omegas.size());
  std::vector<double> amplitude;
  for (const auto& r : s.output.forced) {
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    amplitude.push_back(peak_v(r));
  }
  const std::size_t top = static_cast<std::size_t>(
      std::max_element(amplitude.begin(), amplitude.end()) - amplitude.begin());
  // The peak lies at omega0 (1 + O(zeta^2)): within one grid step (zeta / 20) of it.
  EXPECT_LT(std::abs(omegas[top] / w0 - 1.0), zeta / 20 + 1e-12);
  // Half-power points by linear interpolation on each side; bandwidth 2 zeta omega0 to O(zeta).
  const double half = amplitude[top] / std::sqrt(2.0);
  auto crossing = [&](int step) {
    std::size_t i = top;
    while (amplitude[i] > half) i = static_cast<std::size_t>(static_cast<int>(i) + step);
    const std::size_t j = static_cast<std::size_t>(static_cast<int>(i) - step);
    return omegas[i] +
           (half - amplitude[i]) * (omegas[j] - omegas[i]) / (amplitude[j] - amplitude[i]);
  };
  const double bandwidth = crossing(1) - crossing(-1);
  EXPECT_NEAR(bandwidth / (2 * zeta * w0), 1.0, 5 * zeta);
}

TEST(FrobeniusDampedTest, UndampedProblemsKeepRealResults) {
  const Solved s = run(make_gale_xi_problem(-0.524, 1.116), modes(2, 2));
  for (const Mode& mode : s.output.inplane->modes) {
    EXPECT_EQ(mode.decay_rate_1_s, 0.0);
    EXPECT_EQ(mode.damping_ratio, 0.0);
    EXPECT_EQ(mode.decay_rate_error_estimate, -1.0);
  }
  EXPECT_TRUE(s.output.inplane->overdamped.empty());
}

}  // namespace
}  // namespace catena
