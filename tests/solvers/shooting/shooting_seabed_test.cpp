// SPDX-License-Identifier: MIT
// Tests of the `shooting` solver on a line resting on the seabed
// (docs/explanation/methods/shooting.md, "Seabed contact"):
//  - a taut line lying entirely on the seabed: out of plane a string on an elastic foundation,
//    w^2 = (T/(1+e) (n pi/L)^2 + k_t) / M; in plane the same with k_s merged with the bar on
//    a foundation, w^2 = (EA (n pi/L)^2 + k_t) / m (L unstretched, k per unstretched metre);
//    the conjugate-point count stays exact with the foundation (every mode found in order);
//  - a line touching down exactly at A reproduces the line without a seabed;
//  - the 40%-grounded chain (tests/statics/seabed_statics_test.cpp): 10 modes per plane converge
//    with estimates within the target at C_B = 0 and 0.1, and converge as k_s grows;
//  - friction that brings the grounded tension to zero is declined with a reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::omegas;

ShootingSolverOptions tight() {
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  return options;
}

// Also prints the largest relative difference (the numbers of
// docs/explanation/methods/shooting.md).
void expect_close(const std::vector<double>& got, const std::vector<double>& want, double tol) {
  ASSERT_EQ(got.size(), want.size());
  double worst = 0.0;
  for (std::size_t j = 0; j < got.size(); ++j) {
    EXPECT_NEAR(got[j] / want[j], 1.0, tol) << "mode " << j + 1;
    worst = std::max(worst, std::abs(got[j] / want[j] - 1.0));
  }
  std::printf("largest relative difference over %zu modes: %.2e\n", got.size(), worst);
}

// A taut line of length L lying on the seabed from A to B = A + (L (1 + H/EA), 0).
struct GroundedString {
  double L = 100.0, EA = 5e6, H = 1e5, m = 10.0, ma = 2.0, W = 50.0;
  double k_s = 2e4, k_t = 5e3;

  Problem problem() const {
    Problem p;
    p.cable = {L, W, EA, m, ma};
    p.supports.a_m = Vec2(0.0, -50.0);
    p.supports.b_m = Vec2(L * (1.0 + H / EA), -50.0);
    p.seabed = Seabed{-50.0, 0.0, k_s, k_t};
    return p;
  }
  StaticSolution statics() const {
    const Problem p = problem();
    return StaticSolution(p.as_line(), p.supports.a_m, *p.seabed, H, L);
  }
  double e() const { return H / EA; }
  // Transverse string on a foundation k (per unstretched metre), unstretched measure.
  double string(int n, double k) const {
    const double q = n * kPi / L;
    return std::sqrt((H / (1.0 + e()) * q * q + k) / (m + ma));
  }
  double bar(int n) const {
    const double q = n * kPi / L;
    return std::sqrt((EA * q * q + k_t) / m);
  }
};

SolverOutput solve_with(const Problem& problem,
                        const StaticSolution& statics,
                        int inplane,
                        int outofplane,
                        const ShootingSolverOptions& options = tight()) {
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  return solve_shooting(problem, statics, groups, testing::modes_request(inplane, outofplane),
                        options);
}

TEST(ShootingSeabed, LineEntirelyOnTheSeabedIsAStringAndABarOnAFoundation) {
  const GroundedString g;
  const SolverOutput out = solve_with(g.problem(), g.statics(), 12, 12);
  ASSERT_EQ(out.outofplane->summary.termination, Termination::Converged)
      << out.outofplane->summary.message;
  ASSERT_EQ(out.inplane->summary.termination, Termination::Converged)
      << out.inplane->summary.message;
  std::vector<double> outofplane, inplane;
  for (int n = 1; n <= 12; ++n) outofplane.push_back(g.string(n, g.k_t));
  for (int n = 1; n <= 12; ++n) {
    inplane.push_back(g.string(n, g.k_s));
    inplane.push_back(g.bar(n));
  }
  std::sort(inplane.begin(), inplane.end());
  inplane.resize(12);
  expect_close(omegas(*out.outofplane), outofplane, 1e-10);
  expect_close(omegas(*out.inplane), inplane, 1e-10);
}

// Forced at B, the line lying on the seabed responds as a string or bar on a foundation:
// y(s) = a sin(q s) / sin(q L), q^2 = (w^2 mass - k) / stiffness (sinh when q^2 < 0).
TEST(ShootingSeabed, ForcedResponseOfALineOnTheSeabedIsExact) {
  const GroundedString g;
  const double e = g.e(), a = 0.01, omega = 45.0;  // between modes in every direction
  auto exact = [&](double mass, double k, double stiffness, double s) {
    const double q2 = (omega * omega * mass - k) / stiffness;
    if (q2 < 0.0) return a * std::sinh(std::sqrt(-q2) * s) / std::sinh(std::sqrt(-q2) * g.L);
    return a * std::sin(std::sqrt(q2) * s) / std::sin(std::sqrt(q2) * g.L);
  };
  const double string_stiffness = g.H / (1.0 + e);
  struct Case {
    ForcingDirection direction;
    double mass, k, stiffness;
  };
  for (const Case& c : {Case{ForcingDirection::OutOfPlane, g.m + g.ma, g.k_t, string_stiffness},
                        Case{ForcingDirection::Normal, g.m + g.ma, g.k_s, string_stiffness},
                        Case{ForcingDirection::Tangential, g.m, g.k_t, g.EA}}) {
    SolveRequest request = testing::modes_request(0, 0);
    request.points = 11;
    request.forced = ForcedRequest{CableEnd::B, c.direction, Vec2(1.0, 0.0), a, {omega}};
    const Problem p = g.problem();
    const StaticSolution statics = g.statics();
    const SolverOutput out =
        solve_shooting(p, statics, compute_dimensionless_groups(p, statics), request, tight());
    ASSERT_EQ(out.forced.size(), 1u) << out.summary.message;
    const ForcedResponse& r = out.forced[0];
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    const Vector& y = c.direction == ForcingDirection::OutOfPlane ? r.v
                      : c.direction == ForcingDirection::Normal   ? r.w
                                                                  : r.u;
    // Within 100 rtol of the largest displacement. Not within the response's own estimate
    // (10 rtol / |det|): out of plane the error is 6.4e-11 against an estimate of 3.3e-11, in
    // plane (normal) 2.9e-11 against 1.0e-11, and on the same line without the foundation 1.4e-10
    // against 2.2e-11 (fourteen half-waves along the line): the estimate does not grow with the
    // number of waves (docs/explanation/methods/shooting.md, "Seabed contact").
    const double tolerance = 100.0 * tight().relative_tolerance * y.cwiseAbs().maxCoeff();
    EXPECT_LT(r.relative_error_estimate, 1e-9);
    double worst = 0.0;
    for (Index j = 0; j < r.s_m.size(); ++j) {
      const double want = exact(c.mass, c.k, c.stiffness, r.s_m[j]);
      EXPECT_NEAR(y[j], want, tolerance) << "s = " << r.s_m[j];
      worst = std::max(worst, std::abs(y[j] - want) / y.cwiseAbs().maxCoeff());
    }
    std::printf("forced: largest error %.2e of the largest displacement, estimate %.2e\n", worst,
                r.relative_error_estimate);
  }
}

// The conjugate-point count with the foundation: below sqrt(k / M) the transverse C is
// negative and the phase is not monotone along s, yet at every trial frequency between the exact
// roots (and from either end) the count equals the number of exact frequencies below it.
TEST(ShootingSeabed, ConjugatePointCountIsExactWithTheFoundation) {
  const GroundedString g;
  const internal::ShootingCoefficients k =
      internal::ShootingCoefficients::from_statics(g.statics());
  internal::IntegratorSettings settings;
  settings.relative_tolerance = 1e-11;
  std::vector<double> inplane, outofplane;
  for (int n = 1; n <= 14; ++n) {
    inplane.push_back(g.string(n, g.k_s));
    inplane.push_back(g.bar(n));
    outofplane.push_back(g.string(n, g.k_t));
  }
  std::sort(inplane.begin(), inplane.end());
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const std::vector<double>& exact = plane == Plane::InPlane ? inplane : outofplane;
    internal::ShootingIntegrator integrator(plane, k, settings);
    for (int j = 0; j < 12; ++j) {
      const double omega = j == 0 ? 0.5 * exact[0] : 0.5 * (exact[j - 1] + exact[j]);
      for (bool from_b : {false, true}) {
        const internal::Shot shot = integrator.shoot(omega, 1.0, nullptr, from_b);
        EXPECT_EQ(shot.count, j) << to_string(plane) << " at " << omega << " rad/s, from b "
                                 << from_b;
        EXPECT_LT(shot.phase_defect, 1e-3);
      }
    }
  }
}

ModalResult plane_of(const SolverOutput& out, Plane plane) {
  return plane == Plane::InPlane ? *out.inplane : *out.outofplane;
}

void expect_converged_within(const SolverOutput& out, double estimate) {
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const ModalResult r = plane_of(out, plane);
    ASSERT_EQ(r.summary.termination, Termination::Converged) << r.summary.message;
    EXPECT_EQ(r.modes.size(), 10u);
    EXPECT_LE(r.summary.max_error_estimate, estimate) << to_string(plane);
    EXPECT_GE(r.proved_count_below_top, 10) << to_string(plane);
  }
}

TEST(ShootingSeabed, FortyPercentGroundedChainConvergesWithAndWithoutFriction) {
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-11;
  for (double friction : {0.0, 0.1}) {
    const Problem p = testing::forty_percent_grounded_chain(friction, 3e6);
    const StaticSolution statics = solve_statics(p);
    ASSERT_TRUE(statics.converged && statics.has_contact());
    EXPECT_NEAR(statics.grounded_length_m() / 1000.0, 0.4, 0.05);
    const SolverOutput out = solve_with(p, statics, 10, 10, options);
    expect_converged_within(out, 1e-9);
    const std::vector<std::string>& notes = out.summary.notes;
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& note) {
      return note.find("Winkler foundation (k_s = 3e+06") != std::string::npos;
    }));
    std::printf("C_B = %g: in plane %.12g ... %.12g, out of plane %.12g ... %.12g rad/s\n",
                friction, out.inplane->modes.front().omega_rad_s,
                out.inplane->modes.back().omega_rad_s, out.outofplane->modes.front().omega_rad_s,
                out.outofplane->modes.back().omega_rad_s);
  }
}

// A line whose free catenary leaves A horizontally (V_A = 0) touches down exactly at A.
TEST(ShootingSeabed, TouchdownExactlyAtTheAnchorReproducesTheLineWithoutSeabed) {
  Problem p = testing::forty_percent_grounded_chain(0.5, 3e6);
  const double H = 1.5e6;
  p.supports.b_m = p.supports.a_m + catenary_end_offset(p.cable, H, 0.0);
  Problem free = p;
  free.seabed.reset();
  const SolverOutput free_out =
      solve_with(free, StaticSolution(p.cable, p.supports.a_m, H, 0.0), 8, 8);
  const SolverOutput free_solved = solve_with(free, solve_statics(free), 8, 8);
  // The seabed statics with L_g = 0 exactly, and as solved (L_g within rounding of 0).
  const StaticSolution at_a(p.as_line(), p.supports.a_m, *p.seabed, H, 0.0);
  const SolverOutput exact_out = solve_with(p, at_a, 8, 8);
  const SolverOutput solved_out = solve_with(p, solve_statics(p), 8, 8);
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    expect_close(omegas(plane_of(exact_out, plane)), omegas(plane_of(free_out, plane)), 1e-12);
    expect_close(omegas(plane_of(solved_out, plane)), omegas(plane_of(free_solved, plane)), 1e-9);
  }
}

TEST(ShootingSeabed, FrictionThatSlackensTheGroundedPartIsDeclinedWithAReason) {
  const GroundedString g;
  Problem p = g.problem();
  p.seabed->friction = 1.0;  // C_B w L = 5000 N of friction against H = 1e5 N: still taut
  const StaticSolution taut(p.as_line(), p.supports.a_m, *p.seabed, g.H, g.L);
  // The friction stretches the grounded part less: b where each statics ends (given statics must
  // be the problem's, catena/statics/statics_match.hpp).
  p.supports.b_m = taut.position_m(p.length_m());
  EXPECT_EQ(solve_with(p, taut, 3, 3).inplane->summary.termination, Termination::Converged);
  p.seabed->friction = 40.0;  // 2e5 N of friction: the tension reaches 0 halfway
  const StaticSolution slack(p.as_line(), p.supports.a_m, *p.seabed, g.H, g.L);
  p.supports.b_m = slack.position_m(p.length_m());
  const SolverOutput out = solve_with(p, slack, 3, 3);
  EXPECT_EQ(out.summary.termination, Termination::NotApplicable);
  EXPECT_NE(out.summary.message.find("seabed.friction"), std::string::npos) << out.summary.message;
  EXPECT_FALSE(out.inplane.has_value() && !out.inplane->modes.empty());
  EXPECT_FALSE(out.outofplane.has_value() && !out.outofplane->modes.empty());
}

// k_s = 1e24 N/m per m (1e12 e-folds of the foundation's solution on a chain) made the grounded
// run store one e^600 factor per 600 e-folds: 24 GB and a SIGKILL under a time limit (issue 32).
// Reading bounds k L^2 / W (Problem::validate), but the e-folds L sqrt(k / T) also grow as the
// tension falls: beyond 1e8 shooting declines, naming the stiffness, before any shot; below, it
// still solves. The line lies on the seabed: H = 1 N, k = 1e15 is 3.2e9 e-folds over 100 m.
TEST(ShootingSeabed, FoundationTooStiffForTheShotIsDeclinedNamingTheStiffness) {
  GroundedString g;
  g.H = 1.0;
  g.k_s = 1e15;
  const SolverOutput out = solve_with(g.problem(), g.statics(), 3, 3);
  EXPECT_EQ(out.summary.termination, Termination::NotApplicable);
  EXPECT_NE(out.summary.message.find("[seabed] stiffness 1e+15 N/m per m"), std::string::npos)
      << out.summary.message;
  g.H = 1e5;  // 1e7 e-folds
  const SolverOutput stiff = solve_with(g.problem(), g.statics(), 3, 0);
  ASSERT_TRUE(stiff.inplane.has_value()) << stiff.summary.message;
  EXPECT_EQ(stiff.inplane->summary.termination, Termination::Converged)
      << stiff.inplane->summary.message;
}

// As k_s grows the grounded part is pinned vertically: the in-plane frequencies converge, their
// change per decade of k_s shrinking by a steady factor (printed with the observed order in k_s).
TEST(ShootingSeabed, InPlaneFrequenciesConvergeAsTheSeabedStiffens) {
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-11;
  std::vector<std::vector<double>> table;
  // The grounded run's cost does not grow with k_s (docs/explanation/methods/shooting.md, "Seabed
  // contact").
  const std::vector<double> stiffnesses{3e3, 3e4, 3e5, 3e6, 3e7, 3e8, 3e9};
  for (double k_s : stiffnesses) {
    const Problem p = testing::forty_percent_grounded_chain(0.0, k_s);
    const SolverOutput out = solve_with(p, solve_statics(p), 10, 0, options);
    ASSERT_EQ(out.inplane->summary.termination, Termination::Converged)
        << out.inplane->summary.message;
    table.push_back(omegas(*out.inplane));
    std::printf("k_s = %.0e:", k_s);
    for (double w : table.back()) std::printf(" %.12f", w);
    std::printf("\n");
  }
  for (std::size_t j = 2; j < table.size(); ++j) {
    std::printf("k_s = %.0e, observed order of the change per decade:", stiffnesses[j]);
    for (std::size_t n = 0; n < 10; ++n) {
      const double before = table[j - 1][n] - table[j - 2][n], now = table[j][n] - table[j - 1][n];
      const double order = std::log10(std::abs(before / now));
      std::printf(" %.3f", order);
      // The boundary layer at the touchdown point has the width sqrt(T / k_s): order 1/2.
      if (j >= 3) {
        EXPECT_NEAR(order, 0.5, 0.05) << "k_s = " << stiffnesses[j] << ", mode " << n + 1;
      }
    }
    std::printf("\n");
  }
}

}  // namespace
}  // namespace catena
