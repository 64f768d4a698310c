// SPDX-License-Identifier: MIT
// Tests of the `shooting` solver on damped lines (docs/explanation/methods/shooting.md, "Damping"),
// each against an independent value:
//  - proportional damping c_t = alpha m, c_n = alpha M, c_a = 0: lambda = -alpha/2 +-
//    i sqrt(w0^2 - alpha^2/4) exactly, w0 from shooting's own undamped solve of the same line
//    (Gale's cable, the mooring line, a two-segment line); omega_d to 1e-9, delta on its own;
//  - a damping ratio of 1e-4 (delta on its own);
//  - heavy damping: the first mode overdamped, its two real roots listed apart;
//  - a straight cable with non-proportional damping: transverse string modes
//    M lambda^2 + c_n lambda + T/(1+e) k^2 = 0 and the Kelvin-Voigt bar
//    m lambda^2 + c_t lambda + (EA + c_a lambda) k^2 = 0, k = n pi / L (closed forms);
//  - the argument-principle count equals the number of modes returned;
//  - zero damping coefficients: the undamped path, bit for bit;
//  - complex shapes: normalised, the string's shape a sine times one complex factor;
//  - the damped forced response of a string driven at one end out of plane against its closed
//    form A sin(kappa s) / sin(kappa L), kappa^2 = (1+e)/T (M w^2 - i w c_n), at resonance;
//    its peak ~ A / (pi zeta) and half-power bandwidth ~ 2 zeta w1 (to O(zeta));
//  - the in-plane damped forced response of the mooring line with vanishing damping tends to the
//    undamped one (u, w and the tension), away from resonance;
//  - proportional damping on a line resting on the seabed (the damped grounded run).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;
using Solved = catena::testing::SolvedProblem;

Solved solve(const Problem& problem, const SolveRequest& request) {
  return catena::testing::solve_problem(solve_shooting, problem, request, ShootingSolverOptions{});
}

SolveRequest modes_request(int inplane, int outofplane) {
  SolveRequest request;
  request.inplane_modes = inplane;
  request.outofplane_modes = outofplane;
  return request;
}

// Proportional damping alpha on every section of the problem (cable or line segments).
Problem with_proportional_damping(Problem problem, double alpha) {
  auto damp = [alpha](auto& section) {
    section.damping.tangential_n_s_per_m2 = alpha * section.mass_kg_per_m;
    section.damping.normal_n_s_per_m2 = alpha * section.normal_mass_kg_per_m();
  };
  if (problem.is_uniform()) {
    damp(problem.cable);
  } else {
    for (LineSegment& segment : problem.line.segments) damp(segment);
  }
  return problem;
}

// The plane converged and its count proves every mode returned.
void expect_proved(const ModalResult& result) {
  EXPECT_EQ(result.summary.termination, Termination::Converged) << result.summary.message;
  EXPECT_EQ(result.proved_count_below_top, static_cast<int>(result.modes.size()))
      << result.summary.message;
}

// Every mode of `damped` against lambda = -alpha/2 + i sqrt(w0^2 - alpha^2/4), w0 from `undamped`.
void expect_proportional(const ModalResult& undamped,
                         const ModalResult& damped,
                         double alpha,
                         double delta_tolerance) {
  expect_proved(damped);
  ASSERT_EQ(damped.modes.size(), undamped.modes.size());
  for (std::size_t j = 0; j < damped.modes.size(); ++j) {
    const double w0 = undamped.modes[j].omega_rad_s;
    const double omega_d = std::sqrt(w0 * w0 - 0.25 * alpha * alpha);
    const Mode& mode = damped.modes[j];
    EXPECT_NEAR(mode.omega_rad_s / omega_d - 1.0, 0.0, 1e-9) << "mode " << j + 1;
    EXPECT_NEAR(mode.decay_rate_1_s / (0.5 * alpha) - 1.0, 0.0, delta_tolerance)
        << "mode " << j + 1;
    EXPECT_NEAR(mode.damping_ratio, mode.decay_rate_1_s / std::hypot(mode.decay_rate_1_s, omega_d),
                1e-12);
    // The estimate of delta on its own covers its error and stays within the test's bound.
    EXPECT_GE(mode.decay_rate_error_estimate, std::abs(mode.decay_rate_1_s / (0.5 * alpha) - 1.0));
    EXPECT_LT(mode.decay_rate_error_estimate, 10.0 * delta_tolerance);
  }
}

TEST(ShootingDamped, ProportionalDampingOnGalesCable) {
  const Problem problem = make_gale_sag_problem(0.0, 0.5);
  const SolveRequest request = modes_request(6, 3);
  const Solved undamped = solve(problem, request);
  const double alpha = 0.1;
  const Solved damped = solve(with_proportional_damping(problem, alpha), request);
  expect_proportional(*undamped.output.inplane, *damped.output.inplane, alpha, 1e-7);
  expect_proportional(*undamped.output.outofplane, *damped.output.outofplane, alpha, 1e-7);
  EXPECT_TRUE(damped.output.inplane->overdamped.empty());
}

TEST(ShootingDamped, ProportionalDampingOnTheMooringLine) {
  const Problem problem = catena::testing::mooring_line(Vec2(900.0, 300.0));
  const SolveRequest request = modes_request(6, 0);
  const Solved undamped = solve(problem, request);
  // alpha = 2 zeta w0 for zeta = 2 % on the first mode: a moderate, non-trivial decay.
  const double alpha = 0.04 * undamped.output.inplane->modes[0].omega_rad_s;
  const Solved damped = solve(with_proportional_damping(problem, alpha), request);
  expect_proportional(*undamped.output.inplane, *damped.output.inplane, alpha, 1e-7);
}

TEST(ShootingDamped, ProportionalDampingOnATwoSegmentLine) {
  Problem problem = make_gale_sag_problem(0.0, 0.5);
  const double L = problem.cable.length_m;
  problem.line = line_of_cable(problem.cable);
  problem.prescribed_forces.reset();  // a general line is solved from its geometry
  problem.line.segments.push_back(problem.line.segments.front());
  problem.line.segments[0].length_m = 0.4 * L;
  problem.line.segments[1].length_m = 0.6 * L;
  problem.line.segments[1].mass_kg_per_m *= 2.0;
  problem.line.segments[1].weight_n_per_m *= 2.0;
  const SolveRequest request = modes_request(6, 2);
  const Solved undamped = solve(problem, request);
  ASSERT_EQ(undamped.output.summary.termination, Termination::Converged)
      << undamped.output.summary.full_report();
  const double alpha = 0.2;
  const Solved damped = solve(with_proportional_damping(problem, alpha), request);
  expect_proportional(*undamped.output.inplane, *damped.output.inplane, alpha, 1e-7);
  expect_proportional(*undamped.output.outofplane, *damped.output.outofplane, alpha, 1e-7);
}

TEST(ShootingDamped, DampingRatioOfOneInTenThousand) {
  const Problem problem = make_gale_sag_problem(0.0, 0.5);
  const SolveRequest request = modes_request(3, 0);
  const Solved undamped = solve(problem, request);
  const double alpha = 2e-4 * undamped.output.inplane->modes[0].omega_rad_s;  // zeta_1 = 1e-4
  const Solved damped = solve(with_proportional_damping(problem, alpha), request);
  // delta = 7e-5 1/s against |lambda| ~ 1: the root to 1e-10 relative leaves delta ~1e-6.
  expect_proportional(*undamped.output.inplane, *damped.output.inplane, alpha, 1e-5);
  EXPECT_NEAR(damped.output.inplane->modes[0].damping_ratio, 1e-4, 1e-9);
}

TEST(ShootingDamped, HeavyDampingOverdampsTheFirstMode) {
  const Problem problem = make_gale_sag_problem(0.0, 0.5);
  const Solved undamped = solve(problem, modes_request(7, 0));
  const std::vector<Mode>& modes0 = undamped.output.inplane->modes;
  const double w1 = modes0[0].omega_rad_s;
  const double alpha = 3.0 * w1;  // 2 w1 < alpha < 2 w2: only the first mode is overdamped
  ASSERT_LT(alpha, 2.0 * modes0[1].omega_rad_s);
  const Solved damped = solve(with_proportional_damping(problem, alpha), modes_request(6, 0));
  const ModalResult& result = *damped.output.inplane;
  expect_proved(result);
  ASSERT_EQ(result.overdamped.size(), 2u) << result.summary.message;
  const double root = std::sqrt(0.25 * alpha * alpha - w1 * w1);
  const double slow = 0.5 * alpha - root, fast = 0.5 * alpha + root;  // ascending delta
  EXPECT_NEAR(result.overdamped[0].decay_rate_1_s / slow - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(result.overdamped[1].decay_rate_1_s / fast - 1.0, 0.0, 1e-8);
  for (const Mode& mode : result.overdamped) {
    EXPECT_EQ(mode.omega_rad_s, 0.0);
    EXPECT_EQ(mode.damping_ratio, 1.0);
  }
  ASSERT_EQ(result.modes.size(), 6u);
  for (std::size_t j = 0; j < 6; ++j) {
    const double w0 = modes0[j + 1].omega_rad_s;
    EXPECT_NEAR(result.modes[j].omega_rad_s / std::sqrt(w0 * w0 - 0.25 * alpha * alpha) - 1.0, 0.0,
                1e-9);
    EXPECT_NEAR(result.modes[j].decay_rate_1_s / (0.5 * alpha) - 1.0, 0.0, 1e-8);
  }
}

// Straight cable along x, span chosen for tension T at strain T/EA, weight 1e-9 N/m (the
// undamped solver test's cable), with c_t, c_n and c_a.
Problem damped_straight_cable(double T, double EA, double c_t, double c_n, double c_a) {
  Problem problem;
  const double L = 10.0;
  problem.cable.length_m = L;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = EA;
  problem.cable.mass_kg_per_m = 1.0;
  problem.cable.added_mass_kg_per_m = 0.5;
  problem.cable.damping.tangential_n_s_per_m2 = c_t;
  problem.cable.damping.normal_n_s_per_m2 = c_n;
  problem.cable.damping.axial_n_s = c_a;
  problem.supports.b_m = Vec2(L * (1.0 + T / EA), 0.0);
  return problem;
}

// The upper root of a lambda^2 + b lambda + c = 0 (complex: b^2 < 4 a c here).
Complex upper_root(double a, Complex b, double c) {
  const Complex root = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return Complex(root.real(), std::abs(root.imag()));
}

TEST(ShootingDamped, StraightCableStringAndKelvinVoigtBar) {
  const double T = 2000.0, EA = 2e4, c_t = 0.5, c_n = 0.2, c_a = 5.0;
  const Problem problem = damped_straight_cable(T, EA, c_t, c_n, c_a);
  const Solved damped = solve(problem, modes_request(6, 3));
  const double L = 10.0, m = 1.0, M = 1.5;
  const double Ts = damped.statics.tension_n(0.5 * L);
  const double e = Ts / EA;
  std::vector<Complex> inplane;
  for (int n = 1; n <= 6; ++n) {
    const double k = n * kPi / L;
    inplane.push_back(upper_root(M, c_n, Ts / (1.0 + e) * k * k));
    // The Kelvin-Voigt bar: m lambda^2 + (c_t + c_a k^2) lambda + EA k^2 = 0.
    inplane.push_back(upper_root(m, c_t + c_a * k * k, EA * k * k));
  }
  std::sort(inplane.begin(), inplane.end(),
            [](const Complex& a, const Complex& b) { return a.imag() < b.imag(); });
  const ModalResult& in = *damped.output.inplane;
  expect_proved(in);
  ASSERT_EQ(in.modes.size(), 6u);
  bool has_bar = false;
  for (std::size_t j = 0; j < 6; ++j) {
    const Complex expected = inplane[j];
    has_bar = has_bar || -expected.real() > 0.5 * c_n / M * 1.5;
    EXPECT_NEAR(in.modes[j].omega_rad_s / expected.imag() - 1.0, 0.0, 1e-9) << "mode " << j + 1;
    EXPECT_NEAR(in.modes[j].decay_rate_1_s / -expected.real() - 1.0, 0.0, 1e-6) << "mode " << j + 1;
  }
  EXPECT_TRUE(has_bar) << "the six lowest in-plane modes should include a bar mode";
  const ModalResult& out = *damped.output.outofplane;
  expect_proved(out);
  ASSERT_EQ(out.modes.size(), 3u);
  for (int n = 1; n <= 3; ++n) {
    const double k = n * kPi / L;
    const Complex expected = upper_root(M, c_n, Ts / (1.0 + e) * k * k);
    const Mode& mode = out.modes[static_cast<std::size_t>(n - 1)];
    EXPECT_NEAR(mode.omega_rad_s / expected.imag() - 1.0, 0.0, 1e-9) << "mode " << n;
    EXPECT_NEAR(mode.decay_rate_1_s / -expected.real() - 1.0, 0.0, 1e-6) << "mode " << n;
  }
}

TEST(ShootingDamped, DampedStringShapeIsASineTimesOneComplexFactor) {
  const Problem problem = damped_straight_cable(2000.0, 2e4, 0.0, 0.3, 0.0);
  SolveRequest request = modes_request(0, 2);
  request.shapes = true;
  request.tension = true;
  request.points = 41;
  const Solved damped = solve(problem, request);
  const ModalResult& out = *damped.output.outofplane;
  expect_proved(out);
  for (int n = 1; n <= 2; ++n) {
    const Mode& mode = out.modes[static_cast<std::size_t>(n - 1)];
    ASSERT_EQ(mode.v_imag.size(), mode.v.size());
    EXPECT_EQ(mode.normalised_by, "v");
    double max_modulus = 0.0;
    for (Index j = 0; j < mode.v.size(); ++j) {
      const double shape = std::sin(n * kPi * mode.s_m[j] / 10.0);
      // Normalised to a real 1 at the first peak, the shape is the real sine (to the integration).
      EXPECT_NEAR(mode.v[j], shape, 1e-7);
      EXPECT_NEAR(mode.v_imag[j], 0.0, 1e-7);
      max_modulus = std::max(max_modulus, std::hypot(mode.v[j], mode.v_imag[j]));
    }
    EXPECT_NEAR(max_modulus, 1.0, 1e-12);
    EXPECT_EQ(mode.max_abs_tension_n, 0.0);
  }
}

TEST(ShootingDamped, ZeroDampingIsTheUndampedPathBitForBit) {
  const Problem problem = make_gale_sag_problem(0.0, 0.5);
  Problem zero = problem;
  zero.cable.damping = SectionDamping{};
  ASSERT_FALSE(zero.is_damped());
  const SolveRequest request = modes_request(4, 2);
  const Solved a = solve(problem, request), b = solve(zero, request);
  for (const auto& [x, y] : {std::pair(&*a.output.inplane, &*b.output.inplane),
                             std::pair(&*a.output.outofplane, &*b.output.outofplane)}) {
    ASSERT_EQ(x->modes.size(), y->modes.size());
    EXPECT_EQ(x->proved_count_below_top, y->proved_count_below_top);
    for (std::size_t j = 0; j < x->modes.size(); ++j) {
      EXPECT_EQ(x->modes[j].omega_rad_s, y->modes[j].omega_rad_s);
      EXPECT_EQ(y->modes[j].decay_rate_1_s, 0.0);
      EXPECT_EQ(y->modes[j].u_imag.size(), 0);
    }
  }
}

// On the seabed the foundation is stiffness, so proportional damping still shifts every root to
// -alpha/2 + i sqrt(w0^2 - alpha^2/4): the damped grounded run (shooting_damped_grounded.hpp)
// against shooting's own undamped grounded run.
TEST(ShootingDamped, ProportionalDampingOnTheSeabedShiftsTheUndampedRoots) {
  Problem problem = catena::testing::mooring_line(Vec2(900.0, 300.0));
  Seabed seabed;
  seabed.stiffness_n_per_m2 = 1e5;
  problem.seabed = seabed;
  problem.supports.b_m = Vec2(800.0, 300.0);
  const double alpha = 0.01;
  // At rtol 1e-12: the first in-plane mode (0.07 rad/s, zeta 0.07) checks zeta against the
  // expected omega_d to 1e-12, which the default tolerances' 1e-10 in omega does not reach.
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  const auto solve_tight = [&](const Problem& p) {
    return catena::testing::solve_problem(solve_shooting, p, modes_request(3, 2), options);
  };
  const Solved undamped = solve_tight(problem);
  const Solved damped = solve_tight(with_proportional_damping(problem, alpha));
  ASSERT_TRUE(damped.statics.has_contact());
  expect_proportional(*undamped.output.inplane, *damped.output.inplane, alpha, 1e-7);
  expect_proportional(*undamped.output.outofplane, *damped.output.outofplane, alpha, 1e-7);
}

// The string of damped_straight_cable(T, EA, 0, c_n, 0) driven out of plane at b with amplitude
// A at the frequencies `omegas`, responses at 21 stations.
Solved forced_string(double c_n, const std::vector<double>& omegas, double amplitude) {
  SolveRequest request = modes_request(0, 1);
  request.points = 21;
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::OutOfPlane;
  forced.amplitude_m = amplitude;
  forced.omegas_rad_s = omegas;
  request.forced = forced;
  return solve(damped_straight_cable(2000.0, 2e4, 0.0, c_n, 0.0), request);
}

TEST(ShootingDamped, ForcedStringAtResonanceMatchesTheClosedForm) {
  const double L = 10.0, M = 1.5, c_n = 0.3, A = 0.01;
  const Solved probe =
      solve(damped_straight_cable(2000.0, 2e4, 0.0, c_n, 0.0), modes_request(0, 1));
  const double T = probe.statics.tension_n(0.5 * L), e = T / 2e4;
  const double w1 = kPi / L * std::sqrt(T / (M * (1.0 + e)));  // undamped resonance
  const Solved solved = forced_string(c_n, {w1}, A);
  ASSERT_EQ(solved.output.forced.size(), 1u) << solved.output.summary.full_report();
  const ForcedResponse& r = solved.output.forced[0];
  ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
  const Complex kappa = std::sqrt((1.0 + e) / T * Complex(M * w1 * w1, -w1 * c_n));
  double peak = 0.0;
  for (Index j = 0; j < r.s_m.size(); ++j) {
    const Complex expected = A * std::sin(kappa * r.s_m[j]) / std::sin(kappa * L);
    peak = std::max(peak, std::abs(expected));
    EXPECT_NEAR(r.v[j], expected.real(), 1e-7 * std::abs(A / std::sin(kappa * L)));
    EXPECT_NEAR(r.v_imag[j], expected.imag(), 1e-7 * std::abs(A / std::sin(kappa * L)));
  }
  EXPECT_GT(peak, 10.0 * A);  // resonant amplification, finite
  EXPECT_LT(r.relative_error_estimate, 1e-6);
}

TEST(ShootingDamped, ForcedStringPeakAndBandwidthFollowZeta) {
  const double M = 1.5, c_n = 0.05, A = 0.01;  // the cable of damped_straight_cable (L = 10 m)
  const Solved probe =
      solve(damped_straight_cable(2000.0, 2e4, 0.0, c_n, 0.0), modes_request(0, 1));
  const Mode& mode = probe.output.outofplane->modes[0];
  const double zeta = mode.damping_ratio, w1 = std::hypot(mode.omega_rad_s, mode.decay_rate_1_s);
  ASSERT_NEAR(zeta, c_n / (2.0 * M * w1), 1e-9);
  std::vector<double> omegas;
  for (int j = -60; j <= 60; ++j) omegas.push_back(w1 * (1.0 + 0.05 * zeta * j));
  const Solved solved = forced_string(c_n, omegas, A);
  ASSERT_EQ(solved.output.forced.size(), omegas.size());
  std::vector<double> midpoint;  // |v(L/2)| (station 10 of 21)
  for (const ForcedResponse& r : solved.output.forced) {
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    midpoint.push_back(std::hypot(r.v[10], r.v_imag[10]));
  }
  const auto top = std::max_element(midpoint.begin(), midpoint.end());
  const double peak = *top;
  // Peak A / (pi zeta) and half-power width 2 zeta w1 of the first mode, to O(zeta) = 1e-3 and
  // the sampling (0.05 zeta w1).
  EXPECT_NEAR(peak * kPi * zeta / A, 1.0, 0.01);
  const double half = peak / std::sqrt(2.0);
  auto crossing = [&](int step) {
    for (long j = top - midpoint.begin(); j + step >= 0 && j + step < long(midpoint.size());
         j += step) {
      const double a = midpoint[std::size_t(j)], b = midpoint[std::size_t(j + step)];
      if (b < half) {
        return omegas[std::size_t(j)] +
               (omegas[std::size_t(j + step)] - omegas[std::size_t(j)]) * (a - half) / (a - b);
      }
    }
    return 0.0;
  };
  const double bandwidth = crossing(1) - crossing(-1);
  EXPECT_NEAR(bandwidth / (2.0 * zeta * w1), 1.0, 0.01);
}

TEST(ShootingDamped, ForcedResponseWithVanishingDampingIsTheUndampedOne) {
  const Problem problem = catena::testing::mooring_line(Vec2(900.0, 300.0));
  SolveRequest request = modes_request(1, 0);
  request.points = 51;
  request.tension = true;
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::Tangential;
  forced.amplitude_m = 0.5;
  forced.omegas_rad_s = {0.2, 0.47, 0.9};  // below, between and above the first modes
  request.forced = forced;
  const Solved undamped = solve(problem, request);
  // delta ~ 5e-9 1/s: the response differs from the undamped one by O(delta / distance to the
  // nearest resonance) ~ 1e-7.
  const Solved damped = solve(with_proportional_damping(problem, 1e-8), request);
  ASSERT_EQ(damped.output.forced.size(), 3u) << damped.output.summary.full_report();
  for (std::size_t j = 0; j < 3; ++j) {
    const ForcedResponse& a = undamped.output.forced[j];
    const ForcedResponse& b = damped.output.forced[j];
    ASSERT_TRUE(b.diagnostic.empty()) << b.diagnostic;
    ASSERT_EQ(b.tension_imag_n.size(), b.tension_n.size());
    const double scale_w = a.w.cwiseAbs().maxCoeff(), scale_t = a.tension_n.cwiseAbs().maxCoeff();
    EXPECT_LT((a.u - b.u).cwiseAbs().maxCoeff(), 1e-6 * a.u.cwiseAbs().maxCoeff());
    EXPECT_LT((a.w - b.w).cwiseAbs().maxCoeff(), 1e-6 * scale_w);
    EXPECT_LT((a.tension_n - b.tension_n).cwiseAbs().maxCoeff(), 1e-6 * scale_t);
    EXPECT_LT(b.w_imag.cwiseAbs().maxCoeff(), 1e-6 * scale_w);
    EXPECT_LT(b.tension_imag_n.cwiseAbs().maxCoeff(), 1e-6 * scale_t);
    EXPECT_NEAR(b.max_abs_tension_n / a.max_abs_tension_n, 1.0, 1e-6);
  }
}

}  // namespace
}  // namespace catena
