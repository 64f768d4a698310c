// SPDX-License-Identifier: MIT
// Tests of the `shooting` solver against exact results:
//  - straight, nearly weightless pre-tensioned cable: transverse string modes
//    omega_n = n pi sqrt(T / (M (1+e))) / L and axial bar modes omega_n = n pi sqrt(EA / m) / L,
//    exactly (the weight, 1e-9 N/m, couples them only at the 1e-12 level);
//  - the same cable with EA chosen so that the second string mode and the first bar mode coincide
//    exactly: an exact double root that must come out as two modes;
//  - taut string from make_taut_inclined_problem with tiny eps: kL/pi = n out of plane;
//  - Irvine's horizontal shallow cable (eps small): antisymmetric kL = 2 n pi, and at
//    lambda^2 = 4 pi^2 the first symmetric and antisymmetric modes both found near kL = 2 pi;
//  - inextensible Gale problems with EA = inf exactly (finite, converged, counts consistent);
//  - observed convergence vs rtol (printed);
//  - options validation and knob errors.
#include "catena/solvers/shooting_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::relative_error;

// rtol 1e-12 in CVODE gives frequencies to a few 1e-12 on these smooth problems (see the
// convergence test); 1e-10 leaves a factor ~30 over that for the root bracket and for platform
// differences in CVODE's step selection.
constexpr double kRelTolExact = 1e-10;

using Solved = catena::testing::SolvedProblem;

Solved solve(const Problem& problem,
             const SolveRequest& request,
             const ShootingSolverOptions& options = {}) {
  return catena::testing::solve_problem(solve_shooting, problem, request, options);
}

// Straight cable along x, span chosen for tension T at strain T/EA, weight 1e-9 N/m.
Problem straight_cable(double tension_n, double ea_n, double length_m = 10.0) {
  Problem problem;
  problem.cable.length_m = length_m;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = ea_n;
  problem.cable.mass_kg_per_m = 1.0;
  problem.cable.added_mass_kg_per_m = 0.0;
  problem.supports.b_m = Vec2(length_m * (1.0 + tension_n / ea_n), 0.0);
  return problem;
}

std::vector<double> merged_string_and_bar(const StaticSolution& statics, int count) {
  const CableProperties& cable = statics.cable();
  const double L = cable.length_m;
  const double T = statics.tension_n(0.5 * L);
  const double e = T / cable.axial_stiffness_n;
  std::vector<double> omegas;
  for (int n = 1; n <= count; ++n) {
    omegas.push_back(n * kPi / L * std::sqrt(T / (cable.normal_mass_kg_per_m() * (1.0 + e))));
    omegas.push_back(n * kPi / L * std::sqrt(cable.axial_stiffness_n / cable.mass_kg_per_m));
  }
  std::sort(omegas.begin(), omegas.end());
  omegas.resize(static_cast<std::size_t>(count));
  return omegas;
}

TEST(ShootingSolver, StraightCableGivesExactStringAndBarModes) {
  SolveRequest request;
  request.inplane_modes = 8;
  request.outofplane_modes = 6;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  const Solved solved = solve(straight_cable(2000.0, 1e4), request, options);
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  const std::vector<double> expected = merged_string_and_bar(solved.statics, 8);
  ASSERT_EQ(solved.output.inplane->modes.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    const double got = solved.output.inplane->modes[i].omega_rad_s;
    EXPECT_LT(relative_error(got, expected[i]), kRelTolExact)
        << "in-plane mode " << i + 1 << ": expected " << expected[i] << ", got " << got;
  }
  const double L = 10.0;
  const double T = solved.statics.tension_n(5.0);
  const double e = T / 1e4;
  for (std::size_t i = 0; i < 6; ++i) {
    const double exact = double(i + 1) * kPi / L * std::sqrt(T / (1.0 + e));
    const double got = solved.output.outofplane->modes[i].omega_rad_s;
    EXPECT_LT(relative_error(got, exact), kRelTolExact)
        << "out-of-plane mode " << i + 1 << ": expected " << exact << ", got " << got;
  }
  EXPECT_EQ(solved.output.inplane->proved_count_below_top, 8);
}

TEST(ShootingSolver, ExactDoubleRootIsReturnedAsTwoModes) {
  // EA = 3 T: bar speed sqrt(EA/m) = 2 x string speed sqrt(T/(M(1+e))), e = 1/3.
  SolveRequest request;
  request.inplane_modes = 4;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  const Solved solved = solve(straight_cable(2000.0, 6000.0), request, options);
  ASSERT_TRUE(solved.output.inplane.has_value());
  ASSERT_EQ(solved.output.inplane->modes.size(), 4u) << solved.output.summary.full_report();
  const std::vector<double> expected = merged_string_and_bar(solved.statics, 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const double got = solved.output.inplane->modes[i].omega_rad_s;
    EXPECT_LT(relative_error(got, expected[i]), kRelTolExact)
        << "mode " << i + 1 << ": expected " << expected[i] << ", got " << got;
  }
  EXPECT_LT(relative_error(expected[1], expected[2]), 1e-14) << "the test case must be double";
}

TEST(ShootingSolver, DoubleRootShapesAreMassOrthogonal) {
  SolveRequest request;
  request.inplane_modes = 3;
  request.shapes = true;
  request.points = 401;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  const Solved solved = solve(straight_cable(2000.0, 6000.0), request, options);
  ASSERT_EQ(solved.output.inplane->modes.size(), 3u);
  const Mode& a = solved.output.inplane->modes[1];
  const Mode& b = solved.output.inplane->modes[2];
  double cross = 0.0;
  for (Index j = 1; j < a.s_m.size(); ++j) {
    auto density = [&](Index i) { return a.u[i] * b.u[i] + a.w[i] * b.w[i]; };  // m = M = 1
    cross += 0.5 * (a.s_m[j] - a.s_m[j - 1]) * (density(j) + density(j - 1));
  }
  // Any mass-orthogonal basis of the two-dimensional eigenspace is a valid answer.
  EXPECT_LT(std::abs(cross) / std::sqrt(a.modal_mass_kg * b.modal_mass_kg), 1e-8);
}

TEST(ShootingSolver, TautStringFromGroupsHasIntegerKLOverPi) {
  SolveRequest request;
  request.inplane_modes = 0;
  request.outofplane_modes = 6;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  for (double phi : {0.0, 30.0, 80.0}) {
    const Solved solved = solve(make_taut_inclined_problem(1e-6, phi, 1.0, 0.5), request, options);
    ASSERT_EQ(solved.output.summary.termination, Termination::Converged);
    for (const Mode& mode : solved.output.outofplane->modes) {
      // kL/pi = n / sqrt(1 + e), e = T/EA = eps^2 cos^2(phi) / lambda^2 ~ 1e-12.
      EXPECT_LT(relative_error(mode.k_l_over_pi, mode.index), kRelTolExact)
          << "phi " << phi << " mode " << mode.index << ": kL/pi = " << mode.k_l_over_pi;
    }
  }
}

TEST(ShootingSolver, IrvineAntisymmetricModesAndCrossOver) {
  // Horizontal shallow cable, eps = 1e-3: the shallow theory is exact to O(eps^2).
  constexpr double kShallowTheoryAccuracy = 1e-5;
  SolveRequest request;
  request.inplane_modes = 4;
  for (double lambda2 : {1.0, 4.0 * kPi * kPi, 200.0}) {
    const Solved solved = solve(make_taut_inclined_problem(1e-3, 0.0, lambda2, 1.0), request);
    ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
        << solved.output.summary.full_report();
    const auto& modes = solved.output.inplane->modes;
    for (const Mode& mode : modes) {
      std::printf("lambda2 %.4f mode %d kL/pi %.12f err %.1e\n", lambda2, mode.index,
                  mode.k_l_over_pi, mode.relative_error_estimate);
    }
    // Count the modes near the antisymmetric values kL/pi = 2, 4.
    for (double target : {2.0, 4.0}) {
      int near = 0;
      for (const Mode& mode : modes)
        near += relative_error(mode.k_l_over_pi, target) < kShallowTheoryAccuracy;
      const int expected = (lambda2 == 4.0 * kPi * kPi && target == 2.0) ? 2 : 1;
      EXPECT_EQ(near, expected) << "lambda2 " << lambda2 << " target kL/pi " << target;
    }
  }
}

TEST(ShootingSolver, InextensibleGaleProblemsConverge) {
  SolveRequest request;
  request.inplane_modes = 6;
  request.outofplane_modes = 6;
  for (const Problem& problem : {make_gale_sag_problem(0.0, 0.8), make_gale_sag_problem(1.0, 0.9),
                                 make_gale_xi_problem(-3.468, 3.468)}) {
    const Solved solved = solve(problem, request);
    ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
        << solved.output.summary.full_report();
    std::printf("%s\n", solved.output.summary.full_report().c_str());
    for (const auto* plane : {&*solved.output.inplane, &*solved.output.outofplane}) {
      for (const Mode& mode : plane->modes) {
        std::printf("  mode %d: omega %.12g gale %.6f err %.1e\n", mode.index, mode.omega_rad_s,
                    *mode.gale_ratio, mode.relative_error_estimate);
        EXPECT_LT(mode.relative_error_estimate, 1e-8);
      }
    }
  }
}

// An inextensible cable with chord = L (1 - 1e-12) (L = 1 m, W0 = 1 N/m, m = 1 kg/m): the true
// answer. The statics give H = 204126.4030577 N (50-digit bisection of L = 2 (H/W0)
// sinh(W0 c / 2H) for the double c nearest 1 - 1e-12); the tension varies along the cable by
// (W0 L / H)^2 / 8 ~ 3e-12 relative, so the cable is a string: out of plane omega_n = n pi
// sqrt(H/m) / L; in plane Irvine's inextensible limit, antisymmetric kL = 2 n pi and symmetric
// tan(kL/2) = kL/2 (kL/2 = 4.493409457909064). Sag effects are O(sag/span) = 1e-6 below that.
// (fe, whose penalty strain is 2e6 times this slack, declines: see fe_solver_test.cpp.)
TEST(ShootingSolver, NearlyTautInextensibleCableHasTheStringFrequencies) {
  Problem problem;
  problem.supports.b_m = Vec2(1.0 - 1e-12, 0.0);
  const Solved solved = solve(problem, catena::testing::modes_request(2, 2));
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  const double H = solved.statics.horizontal_force_n();
  EXPECT_LT(relative_error(H, 204126.4030577217), 1e-9);
  const double string_omega = kPi * std::sqrt(H);
  EXPECT_LT(relative_error(solved.output.outofplane->modes[0].omega_rad_s, string_omega), 1e-9);
  EXPECT_LT(relative_error(solved.output.outofplane->modes[1].omega_rad_s, 2.0 * string_omega),
            1e-9);
  EXPECT_LT(relative_error(solved.output.inplane->modes[0].omega_rad_s, 2.0 * string_omega), 1e-6);
  EXPECT_LT(relative_error(solved.output.inplane->modes[1].omega_rad_s,
                           2.0 * 4.493409457909064 / kPi * string_omega),
            1e-6);
}

TEST(ShootingSolver, ObservedConvergenceVsRtolIsMonotone) {
  // Error of the first three frequencies of each plane against a run at rtol 1e-14, for rtol
  // 1e-4 ... 1e-12, on a sagging inclined inextensible cable with added mass and on an elastic
  // mooring-type cable. Printed (the table in the report), and checked to fall monotonically
  // (within a factor 2 of run-to-run jitter) and to be covered by the solver's own estimate.
  Problem gale = make_gale_sag_problem(0.5, 0.8);
  gale.cable.added_mass_kg_per_m = 0.5;
  const Problem elastic = catena::testing::mooring_line(Vec2(900.0, 300.0));
  SolveRequest request;
  request.inplane_modes = 3;
  request.outofplane_modes = 3;
  for (const Problem& problem : {gale, elastic}) {
    ShootingSolverOptions options;
    options.relative_tolerance = 1e-14;
    const Solved reference = solve(problem, request, options);
    ASSERT_EQ(reference.output.summary.termination, Termination::Converged);
    double previous = kInfinity;
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      options.relative_tolerance = rtol;
      const Solved solved = solve(problem, request, options);
      ASSERT_EQ(solved.output.summary.termination, Termination::Converged);
      double error = 0.0, estimate = 0.0;
      for (const auto* plane : {&solved.output.inplane, &solved.output.outofplane}) {
        const auto& ref = plane == &solved.output.inplane ? reference.output.inplane
                                                          : reference.output.outofplane;
        for (std::size_t i = 0; i < 3; ++i) {
          error = std::max(
              error, relative_error((*plane)->modes[i].omega_rad_s, ref->modes[i].omega_rad_s));
          estimate = std::max(estimate, (*plane)->modes[i].relative_error_estimate);
        }
      }
      std::printf(
          "L = %7.1f m  rtol %.0e: max rel error %.2e, max estimate %.2e, %ld shots, %ld "
          "RHS evaluations\n",
          problem.cable.length_m, rtol, error, estimate, solved.output.summary.iterations,
          solved.output.summary.operations);
      EXPECT_LE(error, 2.0 * previous) << "rtol " << rtol;
      EXPECT_LE(error, 10.0 * estimate + 1e-13) << "rtol " << rtol << ": estimate not covering";
      previous = error;
    }
    EXPECT_LT(previous, 1e-10);
  }
}

TEST(ShootingSolver, ThirtyModesAreCountedWithoutGaps) {
  // The conjugate-point count at the top bracket must equal the number of modes returned, and the
  // frequencies must not decrease, on scenes with close pairs (near Irvine's cross-over), large
  // sag, inclination and elasticity.
  std::vector<Problem> problems = {
      make_taut_inclined_problem(0.01, 0.0, 4.0 * kPi * kPi * (1.0 + 1e-6), 1.0),
      make_taut_inclined_problem(0.49, 80.0, 400.0, 0.6),
      make_taut_inclined_problem(0.05, 10.0, 40.0, 1.0),
      make_gale_sag_problem(0.5, 0.8),
  };
  SolveRequest request;
  request.inplane_modes = 30;
  request.outofplane_modes = 30;
  ShootingSolverOptions options;
  options.error_estimate = false;
  for (const Problem& problem : problems) {
    const Solved solved = solve(problem, request, options);
    ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
        << solved.output.summary.full_report();
    for (const auto* plane : {&*solved.output.inplane, &*solved.output.outofplane}) {
      ASSERT_EQ(plane->modes.size(), 30u);
      EXPECT_EQ(plane->proved_count_below_top, 30);
      for (std::size_t i = 1; i < plane->modes.size(); ++i) {
        EXPECT_GE(plane->modes[i].omega_rad_s, plane->modes[i - 1].omega_rad_s) << i;
      }
    }
  }
}

TEST(ShootingSolver, IntegratorFailureIsReportedNotThrown) {
  // 100 integration steps cannot cover ten wavelengths at rtol 1e-12: a numerical outcome, reported
  // in the summary with the reason, never an exception or a NaN.
  SolveRequest request;
  request.inplane_modes = 10;
  request.outofplane_modes = 10;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  options.max_steps = 100;
  const Solved solved = solve(make_gale_sag_problem(0.0, 0.8), request, options);
  EXPECT_EQ(solved.output.summary.termination, Termination::NumericalFailure)
      << solved.output.summary.full_report();
  ASSERT_TRUE(solved.output.inplane.has_value());
  EXPECT_NE(solved.output.inplane->summary.message.find("max_steps"), std::string::npos)
      << solved.output.inplane->summary.message;
  EXPECT_TRUE(solved.output.inplane->modes.empty());
}

TEST(ShootingSolverOptions, RejectsBadValues) {
  ShootingSolverOptions options;
  options.relative_tolerance = 0.0;
  EXPECT_THROW(options.validate(), InvalidInput);
  options = {};
  options.max_steps = 1;
  EXPECT_THROW(options.validate(), InvalidInput);
  options = {};
  options.max_condition = 1.0;
  EXPECT_THROW(options.validate(), InvalidInput);
  try {
    options = {};
    options.absolute_tolerance = -1.0;
    options.validate();
    FAIL() << "no exception";
  } catch (const InvalidInput& error) {
    // The message names the scene knob that sets absolute_tolerance.
    EXPECT_NE(std::string(error.what()).find("[solvers.shooting].atol"), std::string::npos)
        << error.what();
  }
}

TEST(ShootingSolverEntry, RejectsUnknownAndBadKnobs) {
  const SolverEntry* entry = find_solver("shooting");
  ASSERT_NE(entry, nullptr);
  EXPECT_THROW(entry->validate_knobs({{"elements", KnobValue(10L)}}), InvalidInput);
  EXPECT_THROW(entry->validate_knobs({{"method", KnobValue(std::string("rk4"))}}), InvalidInput);
  EXPECT_THROW(entry->validate_knobs({{"rtol", KnobValue(1.0)}}), InvalidInput);
  EXPECT_NO_THROW(entry->validate_knobs(
      {{"rtol", KnobValue(1e-8)}, {"method", KnobValue(std::string("bdf"))}}));
}

}  // namespace
}  // namespace catena
