// SPDX-License-Identifier: MIT
// fe damped forced response (src/solvers/fe/fe_damped_forced.cpp) against closed forms of the
// straight bar (fe_test_support.hpp, T = 1 N, strain e = 0.1), forced at its end B:
// - out of plane with normal drag c_n, at resonance of mode 1 and half a band either side: the
//   damped string v = d sin(kappa s) / sin(kappa L), kappa^2 = (M w^2 - i w c_n)(1 + e) / T, real
//   and quadrature parts; the peak and the half-power band agree with the mode's own zeta (the
//   amplitude at omega_d +- delta is the peak's 1/sqrt 2);
// - along the bar with Kelvin-Voigt damping, at axial resonance: u = d sin(kappa s) / sin(kappa
//   L), kappa^2 = m w^2 / (EA + i w c_a), and the complex tension (EA + i w c_a) u'.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "catena/solvers/fe_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/fe/fe_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;
using catena::testing::modes_request;
using catena::testing::straight_bar;
using Solved = catena::testing::SolvedProblem;

Solved solve(const Problem& problem, const SolveRequest& request, const FeSolverOptions& options) {
  return catena::testing::solve_problem(solve_fe, problem, request, options);
}

// Near a resonance the response 1 / (w_n(h)^2 - w^2 + 2 i delta w) is smooth in h^2 with the
// expansion parameter (the mesh's frequency shift) / zeta, and Richardson leaves its square: at
// N = 2000 (shift ~1e-7 relative, zeta ~ 5e-4..1e-3) about 1e-7 of the peak. 1e-6 holds it.
constexpr double kRelTolResonant = 1e-6;

TEST(FeDampedForced, DampedStringAtResonanceMatchesTheClosedFormAndItsHalfPowerBand) {
  Problem problem = straight_bar();
  const StaticSolution statics = solve_statics(problem);
  const double T = statics.tension_n(0.5), e = T / problem.cable.axial_stiffness_n;
  const double M = problem.cable.normal_mass_kg_per_m(), L = problem.cable.length_m;
  const double w1 = kPi / L * std::sqrt(T / (M * (1.0 + e)));
  const double zeta = 1e-3, c_n = 2.0 * zeta * w1 * M;
  problem.cable.damping.normal_n_s_per_m2 = c_n;
  const double delta = 0.5 * c_n / M, wd = std::sqrt(w1 * w1 - delta * delta);
  const double d = 1e-3;
  SolveRequest request = modes_request(0, 2);
  request.points = 41;
  request.forced = ForcedRequest{.end = CableEnd::B,
                                 .direction = ForcingDirection::OutOfPlane,
                                 .amplitude_m = d,
                                 .omegas_rad_s = {wd - delta, wd, wd + delta}};
  const Solved solved = solve(problem, request, {.elements = 2000});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  const Mode& mode = solved.output.outofplane->modes.at(0);
  EXPECT_LE(catena::testing::relative_error(mode.damping_ratio, zeta), 1e-6);
  ASSERT_EQ(solved.output.forced.size(), 3u);
  std::vector<double> midspan;
  for (const ForcedResponse& response : solved.output.forced) {
    ASSERT_TRUE(response.diagnostic.empty()) << response.diagnostic;
    ASSERT_EQ(response.v_imag.size(), response.v.size());
    const double w = response.omega_rad_s;
    const Complex kappa = std::sqrt(Complex(M * w * w, -w * c_n) * (1.0 + e) / T);
    double peak = 0.0, worst = 0.0;
    for (Index j = 0; j < response.s_m.size(); ++j) {
      const Complex exact = d * std::sin(kappa * response.s_m[j]) / std::sin(kappa * L);
      peak = std::max(peak, std::abs(exact));
      worst = std::max(worst, std::abs(Complex(response.v[j], response.v_imag[j]) - exact));
    }
    EXPECT_LE(worst, kRelTolResonant * peak) << "omega = " << w;
    EXPECT_TRUE(response.near_resonance);
    EXPECT_FALSE(response.at_resonance);
    const Index middle = response.s_m.size() / 2;
    midspan.push_back(std::abs(Complex(response.v[middle], response.v_imag[middle])));
  }
  // The half-power band of the mode's own zeta (fe's delta from the modes of the same run): the
  // other modes' quasi-static share moves the ratio by O(zeta).
  for (double side : {midspan[0], midspan[2]})
    EXPECT_NEAR(side / midspan[1], 1.0 / std::sqrt(2.0), 1e-2);
  EXPECT_GT(midspan[1], 100.0 * d);  // finite, and resonant: ~1 / (pi zeta) d
}

TEST(FeDampedForced, KelvinVoigtBarAtAxialResonanceMatchesTheClosedForm) {
  Problem problem = straight_bar();
  const double EA = problem.cable.axial_stiffness_n, m = problem.cable.mass_kg_per_m;
  const double L = problem.cable.length_m, c_a = 1e-3, d = 1e-3;
  problem.cable.damping.axial_n_s = c_a;
  const double w = kPi / L * std::sqrt(EA / m);
  SolveRequest request = modes_request(0, 0);
  request.points = 21;
  request.forced = ForcedRequest{.end = CableEnd::B,
                                 .direction = ForcingDirection::Tangential,
                                 .amplitude_m = d,
                                 .omegas_rad_s = {w}};
  const Solved solved = solve(problem, request, {.elements = 2000});
  const ForcedResponse& response = solved.output.forced.at(0);
  ASSERT_TRUE(response.diagnostic.empty()) << response.diagnostic;
  const Complex stiffness(EA, w * c_a);
  const Complex kappa = std::sqrt(m * w * w / stiffness);
  double peak = 0.0, worst_u = 0.0, worst_tension = 0.0, peak_tension = 0.0;
  for (Index j = 0; j < response.s_m.size(); ++j) {
    const double s = response.s_m[j];
    const Complex u = d * std::sin(kappa * s) / std::sin(kappa * L);
    const Complex tau = stiffness * d * kappa * std::cos(kappa * s) / std::sin(kappa * L);
    peak = std::max(peak, std::abs(u));
    peak_tension = std::max(peak_tension, std::abs(tau));
    worst_u = std::max(worst_u, std::abs(Complex(response.u[j], response.u_imag[j]) - u));
    worst_tension = std::max(
        worst_tension, std::abs(Complex(response.tension_n[j], response.tension_imag_n[j]) - tau));
  }
  EXPECT_LE(worst_u, kRelTolResonant * peak);
  EXPECT_LE(worst_tension, kRelTolResonant * peak_tension);
  EXPECT_LE(catena::testing::relative_error(response.max_abs_tension_n, peak_tension),
            kRelTolResonant);
  EXPECT_GE(response.relative_error_estimate,
            catena::testing::relative_error(response.max_abs_tension_n, peak_tension));
}

}  // namespace
}  // namespace catena
