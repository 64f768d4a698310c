// SPDX-License-Identifier: MIT
// Tests of the `asymptotic` solver (Grinfogel 1984, eqs. 21, 28, 34, 37, 38; WKB out of plane).
//
// Compared with:
// - Irvine's horizontal-cable equations (phi = 0): tan x = x - 4x^3/lambda^2 and kL = 2 n pi,
//   solved here independently by bisection in long double (to 1e-14);
// - a brute-force dense scan of eq. (21) itself (no root skipped, none spurious);
// - the closed-form near-cross-over splitting of eq. (21) (the pair straddling kL = 2 pi);
// - Irvine's symmetric and antisymmetric mode shapes (phi = 0);
// - the WKB travel time by an independent composite Simpson rule.
// No other solver is used (independence rule).
#include "catena/solvers/asymptotic_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/solvers/airy_solver.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;

// Both root sets are computed to full double precision; 1e-14 leaves ~50 ulp for the different
// arithmetic of the two formulations.
constexpr double kRelTolIrvine = 1e-14;

// Symmetric root of Irvine's equation on the tan branch n, by plain bisection in long double on
// sin x - (x - 4x^3/lambda^2) cos x (monotone on the branch: d/dx[tan x - x + 4x^3/l^2] >= 0).
double irvine_symmetric_x(int n, long double lambda2) {
  long double low = (n - 0.5L) * 3.14159265358979323846264338327950288L;
  long double high = (n + 0.5L) * 3.14159265358979323846264338327950288L;
  auto f = [&](long double x) {
    const long double rhs = std::isinf(lambda2) ? x : x - 4.0L * x * x * x / lambda2;
    return std::sin(x) - rhs * std::cos(x);
  };
  const long double f_low = f(low);
  for (int i = 0; i < 200; ++i) {
    const long double mid = 0.5L * (low + high);
    if ((f(mid) > 0) == (f_low > 0))
      low = mid;
    else
      high = mid;
  }
  return static_cast<double>(0.5L * (low + high));
}

struct Case {
  double eps;
  double phi_deg;
  double lambda2;
};

TEST(GrinfogelEq21, ReducesExactlyToIrvineForHorizontalCable) {
  for (double lambda2 : {0.5, 4.0, 19.0, 4.0 * kPi * kPi, 60.0, 150.0, 1e3, 1e5, kInfinity}) {
    std::vector<double> expected;
    for (int n = 1; n <= 6; ++n) {
      expected.push_back(2.0 * irvine_symmetric_x(n, lambda2));
      expected.push_back(2.0 * n * kPi);
    }
    std::sort(expected.begin(), expected.end());
    const std::vector<double> roots = grinfogel_eq21_roots(12, 0.1, 0.0, lambda2);
    ASSERT_EQ(roots.size(), 12u);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      EXPECT_LE(relative_error(roots[i], expected[i]), kRelTolIrvine)
          << "lambda2 " << lambda2 << " mode " << i + 1 << ": eq21 " << roots[i] << " Irvine "
          << expected[i];
    }
  }
}

TEST(GrinfogelEq21, RootsAreZerosAndNoneIsSkippedByADenseScan) {
  for (const Case& c : {Case{0.18, 23.46, 19.0}, Case{0.18, 23.46, 38.0}, Case{0.49, 45.0, 64.0},
                        Case{0.05, 60.0, 4.0 * kPi * kPi}, Case{0.3, 10.0, 400.0}}) {
    const double phi = c.phi_deg * kPi / 180.0;
    const std::vector<double> roots = grinfogel_eq21_roots(10, c.eps, phi, c.lambda2);
    for (double kl : roots) {
      // |f| at the root relative to the size of its terms.
      const double f = grinfogel_eq21(kl, c.eps, phi, c.lambda2);
      EXPECT_LE(std::abs(f), 1e-12 * (1.0 + kl * kl * kl / c.lambda2)) << "kL " << kl;
    }
    // Dense scan from kL = pi (no physical in-plane mode lies lower) to the top root: every sign
    // change must be one of our roots, in order.
    std::vector<double> scanned;
    const double step = 1e-4;
    double previous = grinfogel_eq21(kPi, c.eps, phi, c.lambda2);
    for (double kl = kPi + step; kl <= roots.back() + 2.0 * step; kl += step) {
      const double value = grinfogel_eq21(kl, c.eps, phi, c.lambda2);
      if ((value > 0.0) != (previous > 0.0)) scanned.push_back(kl);
      previous = value;
    }
    ASSERT_EQ(scanned.size(), roots.size()) << "eps " << c.eps << " lambda2 " << c.lambda2;
    for (std::size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(scanned[i], roots[i], step);
  }
}

TEST(GrinfogelEq21, SeparatesTheCloseNearCrossOverPair) {
  // At lambda^2 = 4 pi^2 and x = pi + delta, eq. (21) is 3 delta^2 = (49/64) e1^2 to leading
  // order: the two roots straddle kL = 2 pi, split by (7/2) e1 / sqrt(3) in kL.
  for (double eps : {1e-2, 1e-3, 1e-4}) {
    const double phi = 1.0 * kPi / 180.0;
    const double e1 = eps * std::sin(phi);
    const std::vector<double> roots = grinfogel_eq21_roots(2, eps, phi, 4.0 * kPi * kPi);
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_LT(roots[0], 2.0 * kPi);
    EXPECT_GT(roots[1], 2.0 * kPi);
    const double expected_gap = 3.5 * e1 / std::sqrt(3.0);
    EXPECT_LE(relative_error(roots[1] - roots[0], expected_gap), 5.0 * e1)
        << "eps " << eps << ": gap " << roots[1] - roots[0] << " expected " << expected_gap;
  }
}

TEST(AsymptoticSolver, LabelsModeCharacterAsIrvineForAHorizontalCable) {
  for (double lambda2 : {20.0, 100.0, 1000.0}) {
    const Problem problem = make_taut_inclined_problem(0.05, 0.0, lambda2, 1.0);
    const StaticSolution statics = solve_statics(problem);
    const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
    SolveRequest request;
    request.inplane_modes = 6;
    const SolverOutput out = solve_asymptotic(problem, statics, groups, request);
    std::string expected;
    for (const Mode& mode : out.inplane->modes) {
      const double n = mode.k_l_over_pi / 2.0;
      const bool antisymmetric = std::abs(n - std::round(n)) < 1e-12;
      expected +=
          (mode.index > 1 ? ", " : "") + std::to_string(mode.index) + (antisymmetric ? " A" : " S");
    }
    bool found = false;
    for (const std::string& note : out.inplane->summary.notes) {
      if (note.find("mode character") == std::string::npos) continue;
      found = true;
      EXPECT_NE(note.find(expected), std::string::npos) << note << " expected " << expected;
    }
    EXPECT_TRUE(found);
  }
}

TEST(GrinfogelEq21, ExtremeParametersGiveFiniteOrderedBracketedRoots) {
  for (double lambda2 : {1e-12, 1e-6, 1.0, 1e6, 1e12, kInfinity}) {
    for (double eps : {1e-8, 1e-3, 1.0}) {
      for (double phi_deg : {0.0, 1e-6, 45.0, 89.9}) {
        const auto roots = grinfogel_eq21_roots(8, eps, phi_deg * kPi / 180.0, lambda2);
        ASSERT_EQ(roots.size(), 8u);
        for (std::size_t i = 0; i < roots.size(); ++i) {
          ASSERT_TRUE(std::isfinite(roots[i]));
          // Mode i lies in its half-branch: x in ((n - 1/2) pi, n pi] or [n pi, (n + 1/2) pi).
          const int n = static_cast<int>(i / 2) + 1;
          const double x = 0.5 * roots[i];
          if (i % 2 == 0) {
            EXPECT_GE(x, (n - 0.5) * kPi * (1.0 - 1e-15));
            EXPECT_LE(x, n * kPi * (1.0 + 1e-15));
          } else {
            EXPECT_GE(x, n * kPi * (1.0 - 1e-15));
            EXPECT_LE(x, (n + 0.5) * kPi * (1.0 + 1e-15));
          }
          if (i > 0) {
            EXPECT_GE(roots[i], roots[i - 1]);
          }
        }
      }
    }
  }
  // lambda^2 -> 0 is the taut string: kL -> pi, 2 pi, 3 pi, ...
  const auto string = grinfogel_eq21_roots(4, 1e-3, 0.3, 1e-12);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(string[static_cast<std::size_t>(i)], (i + 1) * kPi, 1e-5);
}

TEST(GrinfogelEq21, RejectsBadArguments) {
  EXPECT_THROW(grinfogel_eq21_roots(-1, 0.1, 0.1, 10.0), InvalidInput);
  EXPECT_THROW(grinfogel_eq21_roots(2, 0.1, 0.1, 0.0), InvalidInput);
  EXPECT_THROW(grinfogel_eq21_roots(2, std::nan(""), 0.1, 10.0), InvalidInput);
}

using Solved = catena::testing::SolvedProblem;

Solved solve(double eps, double phi_deg, double lambda2, double mass_ratio = 1.0) {
  return catena::testing::prepare(make_taut_inclined_problem(eps, phi_deg, lambda2, mass_ratio));
}

TEST(AsymptoticSolver, FrequenciesAreEq21RootsWithEpsSquaredErrorEstimate) {
  const Solved s = solve(0.18, 23.46, 38.0);
  SolveRequest request;
  request.inplane_modes = 6;
  request.outofplane_modes = 3;
  const SolverOutput out = solve_asymptotic(s.problem, s.statics, s.groups, request);
  ASSERT_EQ(out.summary.termination, Termination::Converged) << out.summary.message;
  ASSERT_TRUE(out.inplane && out.outofplane);
  const auto roots =
      grinfogel_eq21_roots(6, s.groups.eps, s.groups.chord_angle_rad, s.groups.lambda2);
  ASSERT_EQ(out.inplane->modes.size(), 6u);
  EXPECT_EQ(out.inplane->proved_count_below_top, 6);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const Mode& mode = out.inplane->modes[i];
    EXPECT_LE(relative_error(mode.k_l_over_pi, roots[i] / kPi), 1e-14);
    // Model error: eps^2 plus half the static strain T0/EA that eq. (21) neglects.
    const double strain = s.groups.t0_n / s.problem.cable.axial_stiffness_n;
    EXPECT_DOUBLE_EQ(mode.relative_error_estimate, s.groups.eps * s.groups.eps + 0.5 * strain);
  }
  EXPECT_EQ(out.outofplane->modes.size(), 3u);
  // lambda^2 = 38 ~ 4 pi^2: the first two modes are hybrid, then Irvine's alternation.
  bool found = false;
  for (const std::string& note : out.inplane->summary.notes) {
    if (note.find("mode character") != std::string::npos) {
      found = true;
      EXPECT_NE(note.find("1 H, 2 H, 3 S, 4 A, 5 S, 6 A"), std::string::npos) << note;
    }
  }
  EXPECT_TRUE(found);
}

TEST(AsymptoticSolver, WkbOutOfPlaneMatchesIndependentQuadrature) {
  const Solved s = solve(0.49, 45.0, 30.0);
  const std::vector<double> omegas = wkb_outofplane_omegas(s.statics, 4);
  // Composite Simpson with 20000 intervals: error ~ h^4 ~ 1e-17 relative for this smooth T(s).
  const double L = s.problem.cable.length_m;
  const double M = s.problem.cable.normal_mass_kg_per_m();
  auto f = [&](double x) {
    return std::sqrt(M * (1.0 + s.statics.strain(x)) / s.statics.tension_n(x));
  };
  const int n = 20000;
  const double h = L / n;
  double sum = f(0.0) + f(L);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  const double travel = sum * h / 3.0;
  for (int i = 0; i < 4; ++i) {
    EXPECT_LE(relative_error(omegas[i], (i + 1) * kPi / travel), 1e-13) << "mode " << i + 1;
  }
}

// v(L) of the string (P v')' + M w^2 v = 0, P = T/(1+e), v(0) = 0, P v'(0) = 1, by classical RK4
// with n steps: a naive independent reference for the WKB frequencies.
double string_end_value(const StaticSolution& statics, double omega, int n) {
  const double L = statics.cable().length_m;
  const double M = statics.cable().normal_mass_kg_per_m();
  auto P = [&](double s) { return statics.tension_n(s) / (1.0 + statics.strain(s)); };
  auto f = [&](double s, double v, double q, double& dv, double& dq) {
    dv = q / P(s);
    dq = -M * omega * omega * v;
  };
  const double h = L / n;
  double v = 0.0, q = 1.0;
  for (int i = 0; i < n; ++i) {
    const double s = i * h;
    double k1v, k1q, k2v, k2q, k3v, k3q, k4v, k4q;
    f(s, v, q, k1v, k1q);
    f(s + 0.5 * h, v + 0.5 * h * k1v, q + 0.5 * h * k1q, k2v, k2q);
    f(s + 0.5 * h, v + 0.5 * h * k2v, q + 0.5 * h * k2q, k3v, k3q);
    f(s + h, v + h * k3v, q + h * k3q, k4v, k4q);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
  }
  return v;
}

TEST(AsymptoticSolver, WkbOutOfPlaneErrorIsWithinItsEpsSquaredEstimate) {
  // The out-of-plane equation is exact string dynamics; WKB neglects terms of relative order
  // (T'/T)^2 / k^2 ~ (eps sin phi / n pi)^2. Reference: RK4 shooting with 4000 steps (error
  // ~1e-13) and bisection on v(L).
  for (double eps : {0.1, 0.3}) {
    const Solved s = solve(eps, 60.0, 30.0);
    const std::vector<double> wkb = wkb_outofplane_omegas(s.statics, 3);
    for (std::size_t i = 0; i < wkb.size(); ++i) {
      double low = wkb[i] * 0.97, high = wkb[i] * 1.03;
      const double v_low = string_end_value(s.statics, low, 4000);
      for (int iteration = 0; iteration < 60; ++iteration) {
        const double mid = 0.5 * (low + high);
        if ((string_end_value(s.statics, mid, 4000) > 0.0) == (v_low > 0.0))
          low = mid;
        else
          high = mid;
      }
      const double exact = 0.5 * (low + high);
      EXPECT_LE(relative_error(wkb[i], exact), eps * eps) << "eps " << eps << " mode " << i + 1;
      EXPECT_GT(relative_error(wkb[i], exact), 0.0);
    }
  }
}

TEST(AsymptoticSolver, HorizontalShapesAreIrvines) {
  // phi = 0: (34) and (28) reduce to Irvine's symmetric shape 1 - cos(theta) - tan(x) sin(theta)
  // and the antisymmetric sin(theta). Tiny eps keeps the builder's cable near-straight; only
  // lambda2 enters the shape.
  const Solved s = solve(1e-3, 0.0, 50.0);
  for (const char* formula : {"34", "28"}) {
    AsymptoticSolverOptions options;
    options.shape_formula = *parse_asymptotic_shape_formula(formula);
    SolveRequest request;
    request.inplane_modes = 4;
    request.shapes = true;
    request.points = 41;
    const SolverOutput out = solve_asymptotic(s.problem, s.statics, s.groups, request, options);
    ASSERT_TRUE(out.inplane);
    for (const Mode& mode : out.inplane->modes) {
      const double kl = mode.k_l_over_pi * kPi;
      const bool antisymmetric = std::abs(kl / (2.0 * kPi) - std::round(kl / (2.0 * kPi))) < 1e-9;
      Vector expected(mode.s_m.size());
      for (Index j = 0; j < expected.size(); ++j) {
        const double theta = kl * mode.s_m[j] / s.problem.cable.length_m;
        expected[j] = antisymmetric ? std::sin(theta)
                                    : 1.0 - std::cos(theta) - std::tan(0.5 * kl) * std::sin(theta);
      }
      const Index at = [&] {
        Index k;
        mode.w.cwiseAbs().maxCoeff(&k);
        return k;
      }();
      expected /= expected[at];
      EXPECT_LE((mode.w - expected).cwiseAbs().maxCoeff(), 1e-12)
          << "formula " << formula << " mode " << mode.index;
      EXPECT_EQ(mode.normalised_by, "w");
    }
  }
}

TEST(AsymptoticSolver, ShapesVanishAtTheEndsToTheExpectedOrder) {
  // w(0) = 0 exactly for (34); w(L) = O(eps^2) relative to max |w| outside the hybrid region and
  // O(eps^2) too inside it (eq. 21 is satisfied only to that order). u from (37) likewise.
  for (double eps : {0.02, 0.05, 0.1}) {
    const Solved s = solve(eps, 30.0, 38.0);
    SolveRequest request;
    request.inplane_modes = 4;
    request.shapes = true;
    request.tension = true;
    const SolverOutput out = solve_asymptotic(s.problem, s.statics, s.groups, request);
    ASSERT_TRUE(out.inplane);
    for (const Mode& mode : out.inplane->modes) {
      const Index last = mode.w.size() - 1;
      EXPECT_LE(std::abs(mode.w[0]), 1e-14);
      EXPECT_LE(std::abs(mode.u[0]), 1e-14);
      EXPECT_LE(std::abs(mode.w[last]), 3.0 * eps * eps) << "eps " << eps << " mode " << mode.index;
      EXPECT_LE(std::abs(mode.u[last]), 3.0 * eps * eps) << "eps " << eps << " mode " << mode.index;
      EXPECT_GT(mode.max_abs_tension_n, 0.0);
      EXPECT_GT(mode.modal_mass_kg, 0.0);
    }
  }
}

TEST(AsymptoticSolver, FallingChordGivesTheMirroredModes) {
  // The same cable described from its upper end: frequencies equal, shapes mirrored in s.
  const Solved rising = solve(0.18, 23.46, 38.0);
  Problem falling = rising.problem;
  falling.supports.a_m = rising.problem.supports.b_m;
  falling.supports.b_m = rising.problem.supports.a_m;
  const double L = rising.problem.cable.length_m;
  falling.prescribed_forces =
      EndForces{rising.statics.horizontal_force_n(), -rising.statics.vertical_force_n(L)};
  falling.supports.a_m = Vec2::Zero();
  falling.supports.b_m = catenary_end_offset(falling.cable, falling.prescribed_forces->horizontal_n,
                                             falling.prescribed_forces->vertical_a_n);
  const StaticSolution statics = solve_statics(falling);
  const DimensionlessGroups groups = compute_dimensionless_groups(falling, statics);
  ASSERT_NEAR(groups.chord_angle_rad, -rising.groups.chord_angle_rad, 1e-12);
  SolveRequest request;
  request.inplane_modes = 3;
  request.shapes = true;
  request.tension = true;
  request.points = 51;
  const SolverOutput up = solve_asymptotic(rising.problem, rising.statics, rising.groups, request);
  const SolverOutput down = solve_asymptotic(falling, statics, groups, request);
  ASSERT_TRUE(up.inplane && down.inplane);
  for (int i = 0; i < 3; ++i) {
    const Mode& a = up.inplane->modes[i];
    const Mode& b = down.inplane->modes[i];
    EXPECT_LE(relative_error(a.omega_rad_s, b.omega_rad_s), 1e-12);
    EXPECT_LE((a.w - b.w.reverse()).cwiseAbs().maxCoeff(), 1e-9) << "mode " << i + 1;
    // Reversing s flips t and n; the normalisation then flips the whole mode back, so u (along
    // the reversed tangent) keeps its value at the mirrored station.
    EXPECT_LE((a.u - b.u.reverse()).cwiseAbs().maxCoeff(), 1e-9) << "mode " << i + 1;
    EXPECT_LE(relative_error(a.max_abs_tension_n, b.max_abs_tension_n), 1e-9);
  }
}

TEST(AsymptoticSolver, DeclinesVerticalAndSlackCablesAndWarnsAboveThreshold) {
  Problem vertical;
  vertical.cable.length_m = 10.0;
  vertical.cable.weight_n_per_m = 1.0;
  vertical.cable.axial_stiffness_n = 1e6;
  vertical.supports.a_m = Vec2(0.0, 0.0);
  vertical.supports.b_m = catenary_end_offset(vertical.cable, 0.0, 50.0);
  vertical.prescribed_forces = EndForces{0.0, 50.0};
  const StaticSolution statics = solve_statics(vertical);
  const DimensionlessGroups groups = compute_dimensionless_groups(vertical, statics);
  SolveRequest request;
  const SolverOutput out = solve_asymptotic(vertical, statics, groups, request);
  EXPECT_EQ(out.summary.termination, Termination::NotApplicable);
  EXPECT_NE(out.summary.message.find("vertical"), std::string::npos) << out.summary.message;

  const Solved slack = solve(1.5, 20.0, 50.0);
  EXPECT_EQ(
      solve_asymptotic(slack.problem, slack.statics, slack.groups, request).summary.termination,
      Termination::NotApplicable);

  const Solved moderate = solve(0.49, 45.0, 38.0);
  const SolverOutput warned =
      solve_asymptotic(moderate.problem, moderate.statics, moderate.groups, request);
  EXPECT_EQ(warned.summary.termination, Termination::Converged);
  ASSERT_FALSE(warned.summary.warnings.empty());
  EXPECT_NE(warned.summary.warnings.front().find("eps"), std::string::npos);
}

TEST(AsymptoticSolver, InextensibleCableUsesTheLimitOneOverLambdaSquaredZero) {
  Problem problem = make_taut_inclined_problem(0.1, 20.0, 50.0, 1.0);
  problem.cable.axial_stiffness_n = kInfinity;
  problem.supports.b_m = catenary_end_offset(problem.cable, problem.prescribed_forces->horizontal_n,
                                             problem.prescribed_forces->vertical_a_n);
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  SolveRequest request;
  request.inplane_modes = 4;
  const SolverOutput out = solve_asymptotic(problem, statics, groups, request);
  ASSERT_EQ(out.summary.termination, Termination::Converged) << out.summary.message;
  const auto roots = grinfogel_eq21_roots(4, groups.eps, groups.chord_angle_rad, kInfinity);
  for (int i = 0; i < 4; ++i) {
    EXPECT_LE(relative_error(out.inplane->modes[static_cast<std::size_t>(i)].k_l_over_pi,
                             roots[static_cast<std::size_t>(i)] / kPi),
              1e-14);
  }
}

TEST(AsymptoticSolver, RegistryEntryRunsAndRejectsBadKnobs) {
  const SolverEntry* entry = find_solver("asymptotic");
  ASSERT_NE(entry, nullptr);
  const Solved s = solve(0.18, 23.46, 64.0);
  SolveRequest request;
  request.inplane_modes = 2;
  SolveContext context{s.problem, s.statics, s.groups, request};
  const SolverOutput out = run_solver(*entry, context, {{"shape_formula", std::string("28")}});
  EXPECT_EQ(out.summary.termination, Termination::Converged) << out.summary.message;
  EXPECT_THROW(entry->validate_knobs({{"shape_formula", std::string("33")}}), InvalidInput);
  EXPECT_THROW(entry->validate_knobs({{"elements", 10L}}), InvalidInput);
  EXPECT_THROW(entry->validate_knobs({{"max_eps", -1.0}}), InvalidInput);
  AsymptoticSolverOptions options;
  options.quadrature_panels = 0;
  EXPECT_THROW(options.validate(), InvalidInput);

  // The eps limit is a knob: eps = 1.5 declines by default and runs (with a warning) when allowed.
  const Solved slack = solve(1.5, 20.0, 50.0);
  SolveContext slack_context{slack.problem, slack.statics, slack.groups, request};
  EXPECT_EQ(run_solver(*entry, slack_context, {}).summary.termination, Termination::NotApplicable);
  const SolverOutput allowed = run_solver(*entry, slack_context, {{"max_eps", 2.0}});
  EXPECT_EQ(allowed.summary.termination, Termination::Converged) << allowed.summary.message;
  EXPECT_FALSE(allowed.summary.warnings.empty());
}

}  // namespace
}  // namespace catena

namespace catena {
namespace {

TEST(AnalyticSolvers, PhysicalUnitsGiveTheSameDimensionlessAnswers) {
  // A stay-cable-like problem in SI units and its dimensionless twin built from its own groups:
  // kL/pi and tau L / T0 must coincide (the builder's twin has L = 1 m, T0 = 1 N, M = 1 kg/m).
  Problem physical;
  physical.cable.length_m = 200.0;
  physical.cable.weight_n_per_m = 800.0;
  physical.cable.axial_stiffness_n = 4e8;
  physical.cable.mass_kg_per_m = 80.0;
  physical.cable.added_mass_kg_per_m = 20.0;
  physical.supports.a_m = Vec2(0.0, 0.0);
  physical.supports.b_m = Vec2(184.0, 78.0);
  const StaticSolution statics = solve_statics(physical);
  const DimensionlessGroups groups = compute_dimensionless_groups(physical, statics);
  ASSERT_LT(groups.eps, 0.3);
  const Problem twin = make_taut_inclined_problem(groups.eps, groups.chord_angle_rad * 180.0 / kPi,
                                                  groups.lambda2, groups.mass_ratio);
  const StaticSolution twin_statics = solve_statics(twin);
  const DimensionlessGroups twin_groups = compute_dimensionless_groups(twin, twin_statics);
  SolveRequest request;
  request.inplane_modes = 4;
  request.outofplane_modes = 2;
  request.shapes = true;
  request.tension = true;
  const double L = physical.cable.length_m;
  const double T0 = groups.t0_n;
  const SolverOutput a = solve_asymptotic(physical, statics, groups, request);
  const SolverOutput b = solve_asymptotic(twin, twin_statics, twin_groups, request);
  ASSERT_TRUE(a.inplane && b.inplane && a.outofplane && b.outofplane);
  for (std::size_t i = 0; i < 4; ++i) {
    const Mode& x = a.inplane->modes[i];
    const Mode& y = b.inplane->modes[i];
    EXPECT_LE(relative_error(x.k_l_over_pi, y.k_l_over_pi), 1e-10) << i;
    EXPECT_LE(relative_error(x.max_abs_tension_n * L / T0, y.max_abs_tension_n), 1e-8) << i;
    EXPECT_LE((x.w - y.w).cwiseAbs().maxCoeff(), 1e-8) << i;
    EXPECT_LE((x.u - y.u).cwiseAbs().maxCoeff(), 1e-8) << i;
  }
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LE(
        relative_error(a.outofplane->modes[i].k_l_over_pi, b.outofplane->modes[i].k_l_over_pi),
        1e-10);
  }
  // The airy solver on the same pair (its roots are refined to 50 bits).
  const SolverOutput c = solve_airy(physical, statics, groups, request);
  const SolverOutput d = solve_airy(twin, twin_statics, twin_groups, request);
  ASSERT_TRUE(c.inplane && d.inplane);
  ASSERT_EQ(c.inplane->modes.size(), 4u);
  ASSERT_EQ(d.inplane->modes.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const Mode& x = c.inplane->modes[i];
    const Mode& y = d.inplane->modes[i];
    EXPECT_LE(relative_error(x.k_l_over_pi, y.k_l_over_pi), 1e-10) << i;
    EXPECT_LE(relative_error(x.max_abs_tension_n * L / T0, y.max_abs_tension_n), 1e-7) << i;
    EXPECT_LE((x.w - y.w).cwiseAbs().maxCoeff(), 1e-7) << i;
    EXPECT_LE((x.u - y.u).cwiseAbs().maxCoeff(), 1e-7) << i;
  }
}

}  // namespace
}  // namespace catena
