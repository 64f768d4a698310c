// SPDX-License-Identifier: MIT
// Tests of the frobenius solver: Gale's published frequencies (Tables B-3, B-4), an independent
// direct integration of the equations in sigma (Boost.Odeint, no series), deep sag beyond the
// thesis, mode properties (orthogonality, inextensibility, dynamic tension), forced response
// boundary values, applicability and option checks.
#include "catena/solvers/frobenius_solver.hpp"

#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/csv_table.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::published_table;
using testing::relative_error;

using Solved = catena::testing::SolvedProblem;

Solved run(const Problem& problem,
           const SolveRequest& request,
           const FrobeniusSolverOptions& options = {}) {
  return catena::testing::solve_problem(solve_frobenius, problem, request, options);
}

SolveRequest modes(int inplane, int outofplane) {
  return catena::testing::modes_request(inplane, outofplane);
}

// Direct integration in sigma of the inextensible equations (units a, H; C = sqrt(1 + s^2)):
// u' = w/C^2, w' = phi - u/C^2, tau' = phi/C - W2 u, (C phi)' = -tau/C^2 - W2 w; state (u, w, phi,
// tau).
using State4 = std::array<double, 4>;
State4 integrate4(State4 y, double s1, double s2, double w2) {
  namespace odeint = boost::numeric::odeint;
  auto rhs = [w2](const State4& x, State4& dx, double s) {
    const double C = std::sqrt(1.0 + s * s);
    dx[0] = x[1] / (C * C);
    dx[1] = x[2] - x[0] / (C * C);
    dx[2] = (-x[3] / (C * C) - w2 * x[1] - (s / C) * x[2]) / C;
    dx[3] = x[2] / C - w2 * x[0];
  };
  odeint::integrate_adaptive(
      odeint::make_controlled(1e-14, 1e-13, odeint::runge_kutta_fehlberg78<State4>()), rhs, y, s1,
      s2, (s2 - s1) / 200.0);
  return y;
}

double inplane_shooting_det(double s1, double s2, double omega) {
  const State4 a = integrate4({0, 0, 1, 0}, s1, s2, omega * omega);
  const State4 b = integrate4({0, 0, 0, 1}, s1, s2, omega * omega);
  return a[0] * b[1] - a[1] * b[0];
}

double outofplane_shooting_value(double s1, double s2, double omega) {
  namespace odeint = boost::numeric::odeint;
  using State2 = std::array<double, 2>;
  State2 y{0.0, 1.0};
  const double w2 = omega * omega;
  auto rhs = [w2](const State2& x, State2& dx, double s) {
    dx[0] = x[1] / std::sqrt(1.0 + s * s);
    dx[1] = -w2 * x[0];
  };
  odeint::integrate_adaptive(
      odeint::make_controlled(1e-14, 1e-13, odeint::runge_kutta_fehlberg78<State2>()), rhs, y, s1,
      s2, (s2 - s1) / 200.0);
  return y[0];
}

// Root of the shooting function bracketed around `guess` (+-0.5 %): an independent frequency.
template <class F>
double independent_root(F&& f, double guess) {
  double lo = guess * 0.995, hi = guess * 1.005, flo = f(lo);
  EXPECT_LT(flo * f(hi), 0.0) << "no sign change of the shooting function near " << guess;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi), fm = f(mid);
    if ((fm < 0.0) == (flo < 0.0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

TEST(FrobeniusSolverTest, OutOfPlaneMatchesGaleTableB4RowWithinPrintedRounding) {
  // h/b = 0, sag 0.90 (xi = +-0.340): printed 1.91, 3.74, 5.59, 7.44, 9.29, 11.15.
  const Solved s = run(make_gale_sag_problem(0.0, 0.90), modes(0, 6));
  ASSERT_TRUE(s.output.outofplane);
  EXPECT_EQ(s.output.outofplane->summary.termination, Termination::Converged)
      << s.output.outofplane->summary.message;
  const std::vector<double> printed{1.91, 3.74, 5.59, 7.44, 9.29, 11.15};
  ASSERT_EQ(s.output.outofplane->modes.size(), 6u);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(*s.output.outofplane->modes[k].gale_ratio, printed[k], 0.005) << k;
  EXPECT_EQ(s.output.outofplane->proved_count_below_top, 6);
}

TEST(FrobeniusSolverTest, InPlaneMatchesGaleTableB3RowsWithinPrintedRounding) {
  struct Row {
    double h_over_b, sag;
    std::vector<double> printed;
  };
  const std::vector<Row> rows{{0.0, 0.500, {0.74, 1.33, 1.92, 2.47, 3.02, 3.56}},
                              {0.25, 0.90, {3.25, 5.15, 7.15, 8.97, 10.89, 12.70}},
                              {2.0, 0.90, {2.27, 3.62, 5.08, 6.39, 7.78, 9.08}}};
  for (const Row& row : rows) {
    const Solved s = run(make_gale_sag_problem(row.h_over_b, row.sag), modes(6, 0));
    ASSERT_TRUE(s.output.inplane);
    EXPECT_EQ(s.output.inplane->summary.termination, Termination::Converged);
    ASSERT_EQ(s.output.inplane->modes.size(), 6u);
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(*s.output.inplane->modes[k].gale_ratio, row.printed[k], 0.005)
          << row.h_over_b << " " << row.sag << " " << k;
  }
}

TEST(FrobeniusSolverTest, AgreesWithDirectIntegrationInSigma) {
  const Problem problem = make_gale_xi_problem(-0.524, 1.116);
  const Solved s = run(problem, modes(6, 6));
  ASSERT_TRUE(s.output.inplane && s.output.outofplane);
  EXPECT_EQ(s.output.inplane->summary.termination, Termination::Converged)
      << s.output.inplane->summary.message;
  EXPECT_EQ(s.output.outofplane->summary.termination, Termination::Converged)
      << s.output.outofplane->summary.message;
  // Six of each plane, every one of them compared below.
  ASSERT_EQ(s.output.inplane->modes.size(), 6u);
  ASSERT_EQ(s.output.outofplane->modes.size(), 6u);
  const double s1 = s.groups.sigma1, s2 = s.groups.sigma2;
  for (const auto& mode : s.output.inplane->modes) {
    const double omega = *mode.gale_ratio;
    const double reference =
        independent_root([&](double w) { return inplane_shooting_det(s1, s2, w); }, omega);
    EXPECT_LT(relative_error(omega, reference), 1e-10) << mode.index;
    EXPECT_LT(mode.relative_error_estimate, 1e-11);
  }
  for (const auto& mode : s.output.outofplane->modes) {
    const double omega = *mode.gale_ratio;
    const double reference =
        independent_root([&](double w) { return outofplane_shooting_value(s1, s2, w); }, omega);
    EXPECT_LT(relative_error(omega, reference), 1e-10) << mode.index;
  }
}

TEST(FrobeniusSolverTest, DeepSagBeyondTheThesisReachesXiEight) {
  // Gale's two expansions stop at |xi| < 4; the chained expansions reach xi = +-8.
  const Solved s = run(make_gale_xi_problem(-8.0, 8.0), modes(3, 3));
  ASSERT_TRUE(s.output.inplane && s.output.outofplane);
  EXPECT_EQ(s.output.summary.termination, Termination::Converged) << s.output.summary.message;
  const double s1 = s.groups.sigma1, s2 = s.groups.sigma2;
  for (const auto& mode : s.output.outofplane->modes) {
    const double reference = independent_root(
        [&](double w) { return outofplane_shooting_value(s1, s2, w); }, *mode.gale_ratio);
    EXPECT_LT(relative_error(*mode.gale_ratio, reference), 1e-10) << mode.index;
  }
  const auto& first = s.output.inplane->modes.front();
  const double reference = independent_root(
      [&](double w) { return inplane_shooting_det(s1, s2, w); }, *first.gale_ratio);
  EXPECT_LT(relative_error(*first.gale_ratio, reference), 1e-10);
}

TEST(FrobeniusSolverTest, InPlaneModesAreOrthogonalInextensibleAndCarryTheDynamicTension) {
  const Problem problem = make_gale_xi_problem(-0.7, 1.2);
  SolveRequest request = modes(4, 0);
  request.shapes = true;
  request.tension = true;
  request.points = 2001;
  const Solved s = run(problem, request);
  const auto& m = s.output.inplane->modes;
  ASSERT_EQ(m.size(), 4u);
  const double a = s.groups.catenary_parameter_m;
  // Orthogonality in int (m u_i u_j + M w_i w_j) ds (trapezoid on 2001 stations).
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double cross = 0.0;
      for (Index k = 1; k < m[i].s_m.size(); ++k) {
        const double ds = m[i].s_m(k) - m[i].s_m(k - 1);
        cross += 0.5 * ds *
                 (m[i].u(k) * m[j].u(k) + m[i].w(k) * m[j].w(k) + m[i].u(k - 1) * m[j].u(k - 1) +
                  m[i].w(k - 1) * m[j].w(k - 1));
      }
      EXPECT_LT(std::abs(cross) / std::sqrt(m[i].modal_mass_kg * m[j].modal_mass_kg), 1e-5)
          << i << " " << j;
    }
  for (const auto& mode : m) {
    EXPECT_EQ(mode.normalised_by, "w");
    EXPECT_NEAR(mode.w.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_LT(std::abs(mode.u(0)) + std::abs(mode.w(0)) + std::abs(mode.u(mode.u.size() - 1)) +
                  std::abs(mode.w(mode.w.size() - 1)),
              1e-9);
    // Inextensibility: du/ds = w / (a C^2) (central differences).
    double worst = 0.0;
    for (Index k = 1; k + 1 < mode.s_m.size(); ++k) {
      const double sigma = s.statics.vertical_force_n(mode.s_m(k)) / s.statics.horizontal_force_n();
      const double dudx = (mode.u(k + 1) - mode.u(k - 1)) / (mode.s_m(k + 1) - mode.s_m(k - 1));
      worst = std::max(worst, std::abs(dudx - mode.w(k) / (a * (1.0 + sigma * sigma))));
    }
    EXPECT_LT(worst, 1e-4) << mode.index;
    // Dynamic tension against the direct integration: the clamped-start solution with the
    // mode's null vector, scaled to the same normal amplitude at the station of largest |w|.
    const double omega = *mode.gale_ratio;
    const double s1 = s.groups.sigma1, s2 = s.groups.sigma2;
    const State4 ea = integrate4({0, 0, 1, 0}, s1, s2, omega * omega);
    const State4 eb = integrate4({0, 0, 0, 1}, s1, s2, omega * omega);
    // (alpha, beta) with alpha ea + beta eb having u = 0 at s2 (w vanishes with it at the
    // eigenvalue).
    const double alpha = eb[0], beta = -ea[0];
    Index peak = 0;
    mode.w.cwiseAbs().maxCoeff(&peak);
    const double sigma_peak =
        s.statics.vertical_force_n(mode.s_m(peak)) / s.statics.horizontal_force_n();
    const State4 ya = integrate4({0, 0, 1, 0}, s1, sigma_peak, omega * omega);
    const State4 yb = integrate4({0, 0, 0, 1}, s1, sigma_peak, omega * omega);
    const double scale = mode.w(peak) / (a * (alpha * ya[1] + beta * yb[1]));
    for (Index k : {Index(100), Index(700), Index(1500)}) {
      const double sigma = s.statics.vertical_force_n(mode.s_m(k)) / s.statics.horizontal_force_n();
      const State4 pa = integrate4({0, 0, 1, 0}, s1, sigma, omega * omega);
      const State4 pb = integrate4({0, 0, 0, 1}, s1, sigma, omega * omega);
      const double tau = scale * s.statics.horizontal_force_n() * (alpha * pa[3] + beta * pb[3]);
      EXPECT_NEAR(mode.tension_n(k), tau, 1e-7 * std::max(1.0, std::abs(mode.max_abs_tension_n)))
          << mode.index << " " << k;
    }
  }
}

TEST(FrobeniusSolverTest, ForcedResponseMeetsTheEndConditions) {
  SolveRequest request = modes(0, 0);
  request.points = 51;
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::Tangential;
  forced.amplitude_m = 0.01;
  forced.omegas_rad_s = {0.0, 1.0, 2.5};
  request.forced = forced;
  const Solved s = run(make_gale_sag_problem(0.0, 0.90), request);
  ASSERT_EQ(s.output.forced.size(), 3u);
  for (const auto& r : s.output.forced) {
    EXPECT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    const Index last = r.u.size() - 1;
    EXPECT_NEAR(r.u(0), 0.0, 1e-12);
    EXPECT_NEAR(r.w(0), 0.0, 1e-12);
    EXPECT_NEAR(r.u(last), 0.01, 1e-12);
    EXPECT_NEAR(r.w(last), 0.0, 1e-12);
    EXPECT_GT(r.max_abs_tension_n, 0.0);
  }
}

TEST(FrobeniusSolverTest, ShapesAndTensionAreFiniteAtTheApexStation) {
  // Symmetric cable, odd number of stations: the middle station is the apex (sigma = 0, xi = 0),
  // where the half-integer Frobenius solutions have sqrt(|xi|) factors.
  SolveRequest request = modes(4, 2);
  request.shapes = true;
  request.tension = true;
  request.points = 101;
  const Solved s = run(make_gale_xi_problem(-0.5, 0.5), request);
  for (const auto& mode : s.output.inplane->modes) {
    EXPECT_TRUE(mode.u.allFinite() && mode.w.allFinite() && mode.tension_n.allFinite())
        << mode.index;
    // Smooth through the apex: the second difference there continues its neighbours' (a kink or
    // a wrong value at sigma = 0 would make it jump).
    for (const Vector* f : {&mode.w, &mode.u, &mode.tension_n}) {
      const Vector& y = *f;
      const double d2_apex = y(51) - 2.0 * y(50) + y(49), d2_left = y(50) - 2.0 * y(49) + y(48),
                   d2_right = y(52) - 2.0 * y(51) + y(50);
      EXPECT_NEAR(d2_apex, 0.5 * (d2_left + d2_right),
                  0.05 * (std::abs(d2_left) + std::abs(d2_right)) + 1e-9)
          << mode.index;
    }
  }
  // Alternating antisymmetric / symmetric normal displacement (first in-plane mode antisymmetric).
  for (const auto& mode : s.output.inplane->modes) {
    const double parity = mode.index % 2 == 1 ? -1.0 : 1.0;
    for (Index k = 0; k < 50; ++k)
      EXPECT_NEAR(mode.w(100 - k), parity * mode.w(k), 1e-9) << mode.index;
  }
  for (const auto& mode : s.output.outofplane->modes) EXPECT_TRUE(mode.v.allFinite());
  EXPECT_EQ(s.output.inplane->proved_count_below_top, 4);
}

TEST(FrobeniusSolverTest, NormalAndOutOfPlaneForcingMeetTheirEndConditions) {
  for (const ForcingDirection direction :
       {ForcingDirection::Normal, ForcingDirection::OutOfPlane}) {
    SolveRequest request = modes(0, 0);
    request.points = 41;
    ForcedRequest forced;
    forced.end = CableEnd::A;
    forced.direction = direction;
    forced.amplitude_m = 0.02;
    forced.omegas_rad_s = {0.7, 4.1};
    request.forced = forced;
    const Solved s = run(make_gale_xi_problem(-0.4, 1.3), request);
    for (const auto& r : s.output.forced) {
      ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
      const Index last = r.s_m.size() - 1;
      if (direction == ForcingDirection::Normal) {
        EXPECT_NEAR(r.w(0), 0.02, 1e-12);
        EXPECT_NEAR(r.u(0), 0.0, 1e-12);
        EXPECT_NEAR(r.u(last), 0.0, 1e-12);
        EXPECT_NEAR(r.w(last), 0.0, 1e-12);
      } else {
        EXPECT_NEAR(r.v(0), 0.02, 1e-12);
        EXPECT_NEAR(r.v(last), 0.0, 1e-12);
      }
    }
  }
}

TEST(FrobeniusSolverTest, RegistryEntryReadsKnobsAndRejectsUnknownOnes) {
  const SolverEntry* entry = find_solver("frobenius");
  ASSERT_NE(entry, nullptr);
  const Problem problem = make_gale_sag_problem(0.5, 0.8);
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  const SolveRequest request = modes(3, 3);
  const SolveContext context{problem, statics, groups, request};
  EXPECT_FALSE(frobenius_not_applicable_reason(problem, groups).has_value());
  const SolverOutput output =
      run_solver(*entry, context, {{"tolerance", 1e-10}, {"max_terms", 300L}});
  EXPECT_EQ(output.solver, "frobenius");
  EXPECT_EQ(output.summary.termination, Termination::Converged) << output.summary.message;
  ASSERT_TRUE(output.inplane && output.outofplane);
  ASSERT_EQ(output.inplane->modes.size(), 3u);
  ASSERT_EQ(output.outofplane->modes.size(), 3u);
  // Table B-3 / B-4, h/b = 0.5, sag 0.80: in-plane 1.86, 3.16, 4.42; out-of-plane 1.22, 2.34, 3.48.
  EXPECT_NEAR(*output.inplane->modes[2].gale_ratio, 4.42, 0.005);
  EXPECT_NEAR(*output.outofplane->modes[2].gale_ratio, 3.48, 0.005);
  EXPECT_THROW(entry->validate_knobs({{"terms", 10L}}), InvalidInput);
  EXPECT_THROW(entry->validate_knobs({{"tolerance", 1.0}}), InvalidInput);
}

// Gale's Table C-2, h/b = 0, sag 0.90 (|xi| < 0.35, within his first expansion): max |T| / H for
// the end xi2 driven tangentially by 0.01 a. Rows near resonance (wf = 5.19, 5.23) are left out:
// there the printed 3 digits depend on the 1976 frequency to 1e-4.
TEST(FrobeniusSolverTest, ForcedMaxTensionMatchesGaleTableC2ShallowRows) {
  const CsvTable table =
      read_csv_table(published_table("gale-1976-table-C2-forced-max-tension.csv"));
  const Problem problem = make_gale_sag_problem(0.0, 0.90);
  int compared = 0;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    if (std::abs(*table.number(row, "sag_param") - 0.90) > 1e-9 ||
        *table.number(row, "h_over_b") != 0.0)
      continue;
    const double wf = *table.number(row, "wf");
    if (wf > 5.1 && wf < 5.3) continue;
    SolveRequest request = modes(0, 0);
    request.points = 801;
    ForcedRequest forced;
    forced.amplitude_m = 0.01;   // a = 1 m
    forced.omegas_rad_s = {wf};  // sqrt(g/a) = 1 rad/s
    request.forced = forced;
    const Solved s = run(problem, request);
    EXPECT_NEAR(s.output.forced.front().max_abs_tension_n, *table.number(row, "tmax"), 0.0015)
        << wf;
    ++compared;
  }
  EXPECT_EQ(compared, 15);
}

// Gale's Table C-3 (h/b = 0, sag 0.70, wf = 1.32) from xi = -0.629 to 1.383, where the printed U,
// V, T are consistent. The three printed points xi <= -0.880 are not reproduced (V has the opposite
// sign and T jumps to ~5 H): see the report; the direct-integration test above confirms our T.
TEST(FrobeniusSolverTest, ForcedDistributionMatchesGaleTableC3WherePrintedValuesAreConsistent) {
  const CsvTable table =
      read_csv_table(published_table("gale-1976-table-C3-forced-distribution.csv"));
  SolveRequest request = modes(0, 0);
  request.points = 20001;
  ForcedRequest forced;
  forced.amplitude_m = 0.01;
  forced.omegas_rad_s = {1.32};
  request.forced = forced;
  const Solved s = run(make_gale_sag_problem(0.0, 0.70), request);
  const auto& r = s.output.forced.front();
  int compared = 0;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const double xi = *table.number(row, "xi");
    if (std::abs(*table.number(row, "wf") - 1.32) > 1e-9 || xi < -0.7 || std::abs(xi) > 1.38)
      continue;
    const double position =
        (gale_sigma_from_xi(xi) - s.groups.sigma1) / (s.groups.sigma2 - s.groups.sigma1) * 20000.0;
    const Index k = static_cast<Index>(std::lround(position));
    EXPECT_NEAR(r.u(k), *table.number(row, "U"), 0.0012) << xi;
    EXPECT_NEAR(r.w(k), *table.number(row, "V"), 0.0012) << xi;
    EXPECT_NEAR(r.tension_n(k), *table.number(row, "T"), 0.0015) << xi;
    ++compared;
  }
  EXPECT_EQ(compared, 8);
}

TEST(FrobeniusSolverTest, DeclinesExtensibleCables) {
  const Problem problem = make_taut_inclined_problem(0.2, 20.0, 40.0, 1.0);
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  const std::optional<std::string> reason = frobenius_not_applicable_reason(problem, groups);
  ASSERT_TRUE(reason.has_value());
  EXPECT_NE(reason->find("inextensible"), std::string::npos);
  const SolverOutput output = solve_frobenius(problem, statics, groups, modes(2, 0));
  EXPECT_EQ(output.summary.termination, Termination::NotApplicable);
  EXPECT_EQ(output.summary.message, *reason);
  EXPECT_FALSE(output.inplane.has_value());
  // The registry path declines the same way, with the same reason.
  const SolveRequest request = modes(2, 0);
  const SolverOutput through_registry =
      run_solver(*find_solver("frobenius"), SolveContext{problem, statics, groups, request}, {});
  EXPECT_EQ(through_registry.summary.termination, Termination::NotApplicable);
  EXPECT_EQ(through_registry.summary.message, *reason);
}

TEST(FrobeniusSolverTest, RejectsBadOptions) {
  FrobeniusSolverOptions options;
  options.tolerance = 0.1;
  EXPECT_THROW(options.validate(), InvalidInput);
  options = {};
  options.max_terms = 2;
  EXPECT_THROW(options.validate(), InvalidInput);
  options = {};
  options.step_ratio = 0.95;
  EXPECT_THROW(options.validate(), InvalidInput);
}

}  // namespace
}  // namespace catena
