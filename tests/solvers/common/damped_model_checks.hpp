// SPDX-License-Identifier: MIT
#pragma once
// The damping anchors both analytic models (asymptotic, airy) are tested against
// (src/solvers/common/modal_damping.hpp), written once: each solver's test runs them with its own
// solve function. Every expected value is a closed form or the model's own undamped answer.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/modal_damping.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::testing {

/// A solver's entry point with its default options.
using ModelSolve = std::function<SolverOutput(
    const Problem&, const StaticSolution&, const DimensionlessGroups&, const SolveRequest&)>;

// lambda from omega0 and alpha/2 by the same arithmetic can differ by a few ulp in the quotient of
// two quadratures: 1e-14 is rounding.
inline constexpr double kRelTolDampedRounding = 1e-14;

inline SolvedProblem solve_model(const ModelSolve& solve,
                                 const Problem& problem,
                                 const SolveRequest& request) {
  SolvedProblem solved = prepare(problem);
  solved.output = solve(solved.problem, solved.statics, solved.groups, request);
  return solved;
}

/// Proportional damping c_t = alpha m, c_n = alpha M: every mode is lambda = -alpha/2 +-
/// i sqrt(omega0^2 - alpha^2/4) with omega0 the model's own undamped frequency, to rounding, in
/// both planes, with shapes; estimates: delta exact, omega_d the model's amplified. alpha is
/// `zeta1` times 2 omega1 (zeta1: the first in-plane mode's damping ratio); delta is checked on
/// its own, so a zeta of 1e-4 is as exact as 0.05.
inline void expect_proportional_damping_exact(const ModelSolve& solve,
                                              Problem problem,
                                              double zeta1) {
  SolveRequest request = modes_request(5, 4);
  request.shapes = true;
  request.tension = true;
  const SolvedProblem undamped = solve_model(solve, problem, request);
  ASSERT_EQ(undamped.output.summary.termination, Termination::Converged)
      << undamped.output.summary.message;
  const double alpha = 2.0 * zeta1 * undamped.output.inplane->modes[0].omega_rad_s;
  problem.cable.damping.tangential_n_s_per_m2 = alpha * problem.cable.mass_kg_per_m;
  problem.cable.damping.normal_n_s_per_m2 = alpha * problem.cable.normal_mass_kg_per_m();
  const SolvedProblem damped = solve_model(solve, problem, request);
  ASSERT_EQ(damped.output.summary.termination, Termination::Converged)
      << damped.output.summary.message;
  for (const auto& [before, after] :
       {std::pair{*undamped.output.inplane, *damped.output.inplane},
        std::pair{*undamped.output.outofplane, *damped.output.outofplane}}) {
    ASSERT_EQ(after.modes.size(), before.modes.size());
    EXPECT_TRUE(after.overdamped.empty());
    for (std::size_t i = 0; i < before.modes.size(); ++i) {
      const Mode& b = before.modes[i];
      const Mode& a = after.modes[i];
      const double omega0 = b.omega_rad_s;
      EXPECT_LE(relative_error(a.decay_rate_1_s, 0.5 * alpha), kRelTolDampedRounding) << i;
      EXPECT_LE(relative_error(a.omega_rad_s, std::sqrt(omega0 * omega0 - 0.25 * alpha * alpha)),
                kRelTolDampedRounding)
          << i;
      EXPECT_LE(relative_error(a.damping_ratio, 0.5 * alpha / omega0), kRelTolDampedRounding);
      EXPECT_EQ(a.decay_rate_error_estimate, internal::kDecayRoundingEstimate);
      EXPECT_GE(a.relative_error_estimate, b.relative_error_estimate);
      // The shape is the undamped one, with zero imaginary parts.
      ASSERT_EQ(a.w.size(), b.w.size());
      EXPECT_EQ(a.w, b.w);
      EXPECT_EQ(a.v, b.v);
      EXPECT_EQ(a.w_imag.size(), a.w.size());
      if (a.w_imag.size()) {
        EXPECT_EQ(a.w_imag.cwiseAbs().maxCoeff(), 0.0);
      }
      EXPECT_EQ(a.tension_imag_n.size(), a.tension_n.size());
    }
  }
}

/// Heavy proportional damping: alpha/2 above the first two undamped frequencies of each plane
/// and below the third: those modes give the overdamped pairs -alpha/2 +- sqrt(alpha^2/4 -
/// omega0^2), listed apart in ascending decay; the rest keep their exact roots, re-indexed 1, 2...
inline void expect_overdamped_listed_apart(const ModelSolve& solve, Problem problem) {
  const SolveRequest request = modes_request(5, 5);
  const SolvedProblem undamped = solve_model(solve, problem, request);
  ASSERT_EQ(undamped.output.summary.termination, Termination::Converged);
  for (const ModalResult* plane : {&*undamped.output.inplane, &*undamped.output.outofplane}) {
    const std::vector<Mode>& modes = plane->modes;
    const double half_alpha = 0.5 * (modes[1].omega_rad_s + modes[2].omega_rad_s);
    Problem heavy = problem;
    heavy.cable.damping.tangential_n_s_per_m2 = 2.0 * half_alpha * heavy.cable.mass_kg_per_m;
    heavy.cable.damping.normal_n_s_per_m2 = 2.0 * half_alpha * heavy.cable.normal_mass_kg_per_m();
    const SolvedProblem damped = solve_model(solve, heavy, request);
    const ModalResult& result =
        plane->plane == Plane::InPlane ? *damped.output.inplane : *damped.output.outofplane;
    ASSERT_EQ(result.summary.termination, Termination::Converged) << result.summary.message;
    ASSERT_EQ(result.modes.size(), 3u);
    ASSERT_EQ(result.overdamped.size(), 4u);
    std::vector<double> expected_rates;
    for (int i = 0; i < 2; ++i) {
      const double root = std::sqrt(half_alpha * half_alpha - std::pow(modes[i].omega_rad_s, 2));
      expected_rates.push_back(half_alpha - root);
      expected_rates.push_back(half_alpha + root);
    }
    std::sort(expected_rates.begin(), expected_rates.end());
    for (std::size_t i = 0; i < 4; ++i) {
      const Mode& mode = result.overdamped[i];
      EXPECT_EQ(mode.index, static_cast<int>(i) + 1);
      EXPECT_EQ(mode.omega_rad_s, 0.0);
      EXPECT_EQ(mode.damping_ratio, 1.0);
      // sqrt(a^2 - b^2) loses digits as a -> b; 1e-12 covers the cancellation here.
      EXPECT_LE(relative_error(mode.decay_rate_1_s, expected_rates[i]), 1e-12) << i;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      const double omega0 = modes[i + 2].omega_rad_s;
      EXPECT_EQ(result.modes[i].index, static_cast<int>(i) + 1);
      EXPECT_LE(relative_error(result.modes[i].omega_rad_s,
                               std::sqrt(omega0 * omega0 - half_alpha * half_alpha)),
                1e-12);
    }
  }
}

/// Uniform normal damping alone on a taut cable: out of plane delta = c_n / 2M exactly (the
/// string's closed form); in plane the same string value, less the share of the tangential
/// inertia int m u^2 / int (m u^2 + M w^2) that the model's shapes carry, within the mode's own
/// decay-rate estimate.
inline void expect_taut_string_normal_damping(const ModelSolve& solve, Problem problem) {
  const double c_n = 1e-3 * std::sqrt(problem.cable.normal_mass_kg_per_m());
  problem.cable.damping.normal_n_s_per_m2 = c_n;
  const double expected = c_n / (2.0 * problem.cable.normal_mass_kg_per_m());
  const SolvedProblem damped = solve_model(solve, problem, modes_request(4, 4));
  ASSERT_EQ(damped.output.summary.termination, Termination::Converged)
      << damped.output.summary.message;
  for (const Mode& mode : damped.output.outofplane->modes) {
    EXPECT_LE(relative_error(mode.decay_rate_1_s, expected), kRelTolDampedRounding);
    EXPECT_EQ(mode.decay_rate_error_estimate, internal::kDecayRoundingEstimate);
  }
  for (const Mode& mode : damped.output.inplane->modes) {
    EXPECT_LE(mode.decay_rate_1_s, expected);
    EXPECT_GT(mode.decay_rate_error_estimate, 0.0);
    EXPECT_LE(relative_error(mode.decay_rate_1_s, expected), mode.decay_rate_error_estimate)
        << "mode " << mode.index;
  }
}

/// Irvine's horizontal cable (L = 1, H = T0 = 1, M = 1, h = m/M): the symmetric mode's tan x =
/// x - 4 x^3 / lambda^2, omega = 2x. Kelvin-Voigt damping multiplies EA, and lambda^2 with it, by
/// 1 + (c_a/EA) lambda: to first order delta = (c_a / 2) d(omega^2)/dEA (Hellmann-Feynman on
/// Irvine's Rayleigh quotient, whose axial term is EA times the squared dynamic strain).
inline double irvine_kelvin_voigt_decay_rate(double x, double lambda2, double ea, double c_a) {
  const double t = std::tan(x);
  const double dx_dlambda2 =
      (4.0 * x * x * x / (lambda2 * lambda2)) / (t * t + 12.0 * x * x / lambda2);
  return 0.5 * c_a * (lambda2 / ea) * 8.0 * x * dx_dlambda2;
}

/// Symmetric root x of Irvine's equation on the first tan branch (x in (pi/2, 3 pi/2)).
inline double irvine_first_symmetric_x(double lambda2) {
  double low = 0.5 * kPi + 1e-12, high = 1.5 * kPi - 1e-12;
  auto f = [&](double x) { return std::sin(x) - (x - 4.0 * x * x * x / lambda2) * std::cos(x); };
  const bool f_low_positive = f(low) > 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    ((f(mid) > 0.0) == f_low_positive ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace catena::testing
