// SPDX-License-Identifier: MIT
// fe with linearised drag and tangential added mass (src/solvers/fe/fe_drag_forced.cpp; issue 30),
// against anchors that need no other solver:
// - tangential added mass: the straight bar's axial modes omega_n = n pi sqrt(EA / (m + ma_t)) / L;
// - a zero drag profile (Cd = 0) gives exactly the damped forced response of forced();
// - a uniform profile (constant velocity scale) on the straight bar (fe_test_support.hpp): out of
//   plane the damped string v = d sin(k s) / sin(k L), k^2 = (M w^2 - i w c_n)(1 + e) / T; along
//   the bar u = d sin(k s) / sin(k L), k^2 = ((m + ma_t) w^2 - i w c_t) / EA, tau = EA u', within
//   fe's own estimate (actual error <= estimate);
// - a dynamic-tension run (driver fixed point) on a chain-wire-chain line on the seabed reaches
//   its fixed point.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>

#include "catena/solvers/fe_solver.hpp"
#include "solvers/common/drag_profile.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/fe/fe_drag_forced.hpp"
#include "solvers/fe/fe_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;
using catena::testing::modes_request;
using catena::testing::relative_error;
using catena::testing::straight_bar;
using Solved = catena::testing::SolvedProblem;

Solved solve(const Problem& problem, const SolveRequest& request, const FeSolverOptions& options) {
  return catena::testing::solve_problem(solve_fe, problem, request, options);
}

// As FeSolver.StraightBarHasAxialFrequenciesOfTheElasticRod: Richardson leaves ~1e-12.
constexpr double kRelTolAxial = 1e-6;

TEST(FeDrag, TangentialAddedMassGivesTheAxialModesOfTheHeavierRod) {
  Problem problem = straight_bar();
  problem.cable.added_mass_tangential_kg_per_m = 1.5;
  SolveRequest request = modes_request(20, 0);
  request.shapes = true;
  request.points = 201;
  const Solved solved = solve(problem, request, {.elements = 1000});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  const CableProperties& cable = solved.problem.cable;
  const double mt = cable.tangential_mass_kg_per_m(), L = cable.length_m;
  int axial = 0;
  for (const Mode& mode : solved.output.inplane->modes) {
    if (mode.normalised_by != "u") continue;
    ++axial;
    const double exact = axial * kPi * std::sqrt(cable.axial_stiffness_n / mt) / L;
    EXPECT_LE(relative_error(mode.omega_rad_s, exact), kRelTolAxial)
        << "axial mode " << axial << ": " << mode.omega_rad_s << " vs " << exact;
    // u = sin(n pi s / L) with max 1: modal mass (m + ma_t) L / 2 (the trapezoid rule on whole
    // half waves is exact up to the transverse share, O(W0 L / T)).
    EXPECT_LE(relative_error(mode.modal_mass_kg, 0.5 * mt * L), 1e-6) << "axial mode " << axial;
  }
  // Axial speed 2 m/s against the transverse 0.953 m/s: 20 modes hold the lowest 6 axial ones.
  EXPECT_EQ(axial, 6);
}

// The straight bar with Morison drag on its section (the profile's coefficients come from it).
Problem bar_with_drag() {
  Problem problem = straight_bar();
  problem.cable.added_mass_tangential_kg_per_m = 0.5;
  problem.cable.drag = {.diameter_m = 0.01, .normal = 1.2, .tangential = 0.4};
  return problem;
}

TEST(FeDrag, ZeroDragProfileGivesExactlyTheDampedForcedResponse) {
  // Section damping only (Cd = 0): the driver's single solve is the damped forced response.
  Problem problem = straight_bar();
  problem.cable.added_mass_tangential_kg_per_m = 0.5;
  problem.cable.damping = {.tangential_n_s_per_m2 = 0.3, .normal_n_s_per_m2 = 0.2};
  const double period = 1.7, amplitude = 2.0;  // a power of two: forced() is scaled exactly
  SolveRequest request = modes_request(0, 0);
  request.points = 31;
  MotionRequest motion;
  motion.vector = Vec2(1.0, 0.5);
  motion.amplitude_m = amplitude;
  motion.periods_s = {period};
  request.motion = motion;
  request.forced = ForcedRequest{.end = CableEnd::B,
                                 .direction = ForcingDirection::GivenVector,
                                 .vector = motion.vector,
                                 .amplitude_m = amplitude,
                                 .omegas_rad_s = {2.0 * kPi / period}};
  const Solved solved = solve(problem, request, {.elements = 200});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  ASSERT_EQ(solved.output.dynamic_tension.size(), 1u);
  const DynamicTension& t = solved.output.dynamic_tension.front();
  const ForcedResponse& r = solved.output.forced.at(0);
  ASSERT_TRUE(t.converged) << t.diagnostic;
  ASSERT_EQ(t.s_m.size(), r.s_m.size());
  for (Index j = 0; j < r.s_m.size(); ++j) {
    // The driver's modulus, sqrt(re^2 + im^2), of the same complex tension.
    const double re = r.tension_n[j], im = r.tension_imag_n[j];
    EXPECT_EQ(t.amplitude_n[j], std::sqrt(re * re + im * im)) << j;
    EXPECT_EQ(t.phase_deg[j], std::atan2(r.tension_imag_n[j], r.tension_n[j]) * 180.0 / kPi);
    const double motion2 =
        r.u[j] * r.u[j] + r.u_imag[j] * r.u_imag[j] + r.w[j] * r.w[j] + r.w_imag[j] * r.w_imag[j];
    EXPECT_NEAR(t.motion_m[j], std::sqrt(motion2), 1e-15 * std::sqrt(motion2) + 1e-300);
  }
  EXPECT_EQ(t.relative_error_estimate, r.relative_error_estimate);
  EXPECT_EQ(t.normal_damping_n_s_per_m2.cwiseAbs().maxCoeff(), 0.0);
}

// The levels of the straight bar's plan at N elements, ready for fe_drag_forced_response.
struct BarLevels {
  Solved prepared;
  internal::FePlan plan;
  internal::FeLevels levels;
  internal::FeTimings timings;
};

BarLevels bar_levels(const Problem& problem, const SolveRequest& request, int elements) {
  BarLevels out{catena::testing::prepare(problem), {}, {}, {}};
  FeSolverOptions options;
  options.elements = elements;
  out.plan = internal::make_fe_plan(problem, out.prepared.statics, options, 0, 0);
  std::string failure;
  out.levels =
      internal::solve_level_statics(problem, out.prepared.statics, out.plan, out.timings, failure);
  EXPECT_TRUE(failure.empty()) << failure;
  (void)request;
  return out;
}

// A profile with the same velocity scale V everywhere: c_n, c_t uniform.
internal::DragProfile uniform_profile(const Problem& problem, const Vector& stations, double V) {
  internal::DragProfile drag(problem, stations, internal::DragLinearisation::Harmonic);
  const Vector scale = Vector::Constant(stations.size(), V);
  drag.set_velocity_scales(scale, scale);
  return drag;
}

TEST(FeDrag, UniformNormalDragOutOfPlaneMatchesTheDampedString) {
  const Problem problem = bar_with_drag();
  SolveRequest request = modes_request(0, 0);
  request.points = 41;
  BarLevels bar = bar_levels(problem, request, 1000);
  const double T = bar.prepared.statics.tension_n(0.5), e = T / problem.cable.axial_stiffness_n;
  const double M = problem.cable.normal_mass_kg_per_m(), L = problem.cable.length_m;
  const Vector stations = request.stations_m(L);
  const internal::DragProfile drag = uniform_profile(problem, stations, 0.02);
  const double c_n = drag.normal_at(0.5, 0);
  ASSERT_GT(c_n, 0.0);
  const double w1 = kPi / L * std::sqrt(T / (M * (1.0 + e))), d = 1e-2;
  const ForcedRequest forced{.end = CableEnd::B,
                             .direction = ForcingDirection::OutOfPlane,
                             .amplitude_m = d,
                             .omegas_rad_s = {0.5 * w1, w1, 2.5 * w1}};
  const SolveContext context{problem, bar.prepared.statics, bar.prepared.groups, request};
  const internal::ForcedOutcome outcome = internal::fe_drag_forced_response(
      forced, drag, context, bar.plan, bar.levels, {}, bar.timings);
  ASSERT_EQ(outcome.responses.size(), 3u);
  for (const ForcedResponse& r : outcome.responses) {
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    const double w = r.omega_rad_s;
    const Complex k = std::sqrt(Complex(M * w * w, -w * c_n) * (1.0 + e) / T);
    double peak = 0.0, worst = 0.0;
    for (Index j = 0; j < r.s_m.size(); ++j) {
      const Complex exact = d * std::sin(k * r.s_m[j]) / std::sin(k * L);
      peak = std::max(peak, std::abs(exact));
      worst = std::max(worst, std::abs(Complex(r.v[j], r.v_imag[j]) - exact));
    }
    // Out of plane there is no first-order dynamic tension, hence no tension estimate (-1); the
    // Richardson-extrapolated displacements at N = 1000 are good to ~(pi / 2N)^4.
    EXPECT_LE(worst, 1e-9 * peak) << "omega = " << w;
  }
}

TEST(FeDrag, UniformTangentialDragAlongTheBarMatchesTheDampedRodWithinItsEstimate) {
  const Problem problem = bar_with_drag();
  SolveRequest request = modes_request(0, 0);
  request.points = 21;
  BarLevels bar = bar_levels(problem, request, 1000);
  const double EA = problem.cable.axial_stiffness_n, L = problem.cable.length_m;
  const double mt = problem.cable.tangential_mass_kg_per_m();
  const Vector stations = request.stations_m(L);
  const internal::DragProfile drag = uniform_profile(problem, stations, 0.5);
  const double c_t = drag.tangential_at(0.5, 0);
  ASSERT_GT(c_t, 0.0);
  const double w1 = kPi / L * std::sqrt(EA / mt), d = 1e-3;
  const ForcedRequest forced{.end = CableEnd::B,
                             .direction = ForcingDirection::Tangential,
                             .amplitude_m = d,
                             .omegas_rad_s = {0.5 * w1, w1, 1.7 * w1}};
  const SolveContext context{problem, bar.prepared.statics, bar.prepared.groups, request};
  const internal::ForcedOutcome outcome = internal::fe_drag_forced_response(
      forced, drag, context, bar.plan, bar.levels, {}, bar.timings);
  ASSERT_EQ(outcome.responses.size(), 3u);
  for (const ForcedResponse& r : outcome.responses) {
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    const double w = r.omega_rad_s;
    const Complex k = std::sqrt(Complex(mt * w * w, -w * c_t) / EA);
    double peak_u = 0.0, worst_u = 0.0, peak_tension = 0.0, worst_tension = 0.0;
    for (Index j = 0; j < r.s_m.size(); ++j) {
      const double s = r.s_m[j];
      const Complex u = d * std::sin(k * s) / std::sin(k * L);
      const Complex tau = EA * d * k * std::cos(k * s) / std::sin(k * L);
      peak_u = std::max(peak_u, std::abs(u));
      peak_tension = std::max(peak_tension, std::abs(tau));
      worst_u = std::max(worst_u, std::abs(Complex(r.u[j], r.u_imag[j]) - u));
      worst_tension =
          std::max(worst_tension, std::abs(Complex(r.tension_n[j], r.tension_imag_n[j]) - tau));
    }
    const double actual = worst_tension / peak_tension;
    std::printf("omega = %.6g: tension error %.3g, estimate %.3g\n", w, actual,
                r.relative_error_estimate);
    EXPECT_LE(worst_u, 1e-8 * peak_u) << "omega = " << w;
    ASSERT_GE(r.relative_error_estimate, 0.0);
    EXPECT_LE(actual, r.relative_error_estimate) << "omega = " << w;
    EXPECT_LE(r.relative_error_estimate, 1e-5) << "omega = " << w;
    EXPECT_LE(relative_error(r.max_abs_tension_n, peak_tension), r.relative_error_estimate);
  }
}

// A chain-wire-chain mooring line whose bottom chain lies partly on the seabed, with Morison drag
// and tangential added mass on every segment.
Problem chain_wire_chain_on_seabed() {
  Problem p;
  LineSegment chain{.length_m = 350.0,
                    .weight_n_per_m = 1400.0,
                    .axial_stiffness_n = 7.5e8,
                    .mass_kg_per_m = 160.0,
                    .added_mass_kg_per_m = 25.0,
                    .added_mass_tangential_kg_per_m = 12.0,
                    .drag = {.diameter_m = 0.16, .normal = 2.4, .tangential = 1.15}};
  LineSegment wire{.length_m = 500.0,
                   .weight_n_per_m = 60.0,
                   .axial_stiffness_n = 2e8,
                   .mass_kg_per_m = 8.0,
                   .added_mass_kg_per_m = 4.0,
                   .added_mass_tangential_kg_per_m = 0.5,
                   .drag = {.diameter_m = 0.09, .normal = 1.2, .tangential = 0.008}};
  LineSegment top = chain;
  top.length_m = 100.0;
  p.line.segments = {chain, wire, top};
  p.supports.a_m = Vec2(0.0, -150.0);
  p.supports.b_m = Vec2(820.0, 0.0);
  p.seabed = Seabed{.z_m = -150.0,
                    .friction = 0.3,
                    .stiffness_n_per_m2 = 1e5,
                    .tangential_stiffness_n_per_m2 = 1e3};
  return p;
}

MotionRequest irregular_surge(int frequencies) {
  MotionRequest motion;
  motion.vector = Vec2(1.0, 0.0);
  motion.jonswap = JonswapSpectrum{.hs_m = 6.0, .tp_s = 12.0, .gamma = 3.3};
  motion.rao = RaoTable{.omega_rad_s = {0.2, 0.5, 0.8, 1.2, 2.0},
                        .amplitude = {0.9, 0.8, 0.5, 0.2, 0.05},
                        .phase_deg = {0.0, -10.0, -30.0, -60.0, -90.0}};
  motion.frequencies = frequencies;
  motion.tolerance = 1e-8;
  return motion;
}

TEST(FeDrag, DynamicTensionOfAChainWireChainLineOnTheSeabedReachesItsFixedPoint) {
  const Problem problem = chain_wire_chain_on_seabed();
  SolveRequest request = modes_request(0, 0);
  request.motion = irregular_surge(200);
  const auto start = std::chrono::steady_clock::now();
  const Solved solved = solve(problem, request, {});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(solved.statics.has_contact());
  ASSERT_EQ(solved.output.dynamic_tension.size(), 1u) << solved.output.summary.full_report();
  const DynamicTension& t = solved.output.dynamic_tension.front();
  std::printf(
      "chain-wire-chain on the seabed, 200 frequencies: %.3f s (statics included), %d iterations, "
      "residual %.2g, estimate %.2g, fairlead sigma_T %.6g N\n",
      seconds, t.iterations, t.residual, t.relative_error_estimate, t.fairlead.std_n);
  EXPECT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  EXPECT_TRUE(t.converged) << t.diagnostic;
  EXPECT_LE(t.residual, request.motion->tolerance);
  EXPECT_GT(t.fairlead.std_n, 0.0);
  EXPECT_GE(t.relative_error_estimate, 0.0);
  // The drag is where the line moves: zero at the anchor, positive at the fairlead.
  EXPECT_GT(t.normal_damping_n_s_per_m2[t.s_m.size() - 1], 0.0);
}

TEST(FeDrag, RegularOutOfPlaneMotionOfTheSeabedLineReachesItsFixedPoint) {
  // Out of plane: c_n from |v|, no first-order dynamic tension; one fixed point per period.
  const Problem problem = chain_wire_chain_on_seabed();
  SolveRequest request = modes_request(0, 0);
  MotionRequest motion;
  motion.direction = ForcingDirection::OutOfPlane;
  motion.amplitude_m = 3.0;
  motion.periods_s = {8.0, 14.0};
  request.motion = motion;
  const Solved solved = solve(problem, request, {});
  EXPECT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  ASSERT_EQ(solved.output.dynamic_tension.size(), 2u);
  for (const DynamicTension& t : solved.output.dynamic_tension) {
    EXPECT_TRUE(t.converged) << t.diagnostic;
    EXPECT_LE(t.residual, motion.tolerance);
    const Index last = t.s_m.size() - 1;
    EXPECT_NEAR(t.motion_m[last], motion.amplitude_m, 1e-12 * motion.amplitude_m);
    EXPECT_GT(t.normal_damping_n_s_per_m2[last], 0.0);
    EXPECT_EQ(t.tangential_damping_n_s_per_m2.cwiseAbs().maxCoeff(), 0.0);
  }
}

}  // namespace
}  // namespace catena

namespace catena {
namespace {

// The anchor of a vanishing amplitude: the linearised drag vanishes with the velocity, so the
// dynamic tension per unit motion tends to the undamped forced response away from resonance (the
// mooring line's lowest in-plane frequency is 0.38 rad/s; the period 30 s is 0.21 rad/s, below
// it). The drag's damping is in quadrature with the response: the modulus moves as c^2 ~ A^2.
TEST(FeDrag, VanishingAmplitudeTendsToTheUndampedForcedResponse) {
  Problem undamped = catena::testing::mooring_line(Vec2(900.0, 300.0));
  SolveRequest forced_request = modes_request(0, 0);
  forced_request.points = 11;
  forced_request.forced = ForcedRequest{};
  forced_request.forced->end = CableEnd::B;
  forced_request.forced->direction = ForcingDirection::GivenVector;
  forced_request.forced->vector = Vec2(1.0, 0.0);
  forced_request.forced->amplitude_m = 1.0;
  const double omega = 2.0 * M_PI / 30.0;
  forced_request.forced->omegas_rad_s = {omega};
  const Solved reference = solve(undamped, forced_request, {});
  ASSERT_EQ(reference.output.forced.size(), 1u);
  const double tau0 = reference.output.forced[0].max_abs_tension_n;
  ASSERT_GT(tau0, 0.0);

  Problem dragged = undamped;
  dragged.cable.drag = {0.14, 2.4, 1.15};
  auto fairlead_per_metre = [&](double amplitude) {
    SolveRequest request = modes_request(0, 0);
    request.points = 11;
    MotionRequest motion;
    motion.amplitude_m = amplitude;
    motion.periods_s = {30.0};
    request.motion = motion;
    const Solved solved = solve(dragged, request, {});
    EXPECT_EQ(solved.output.dynamic_tension.size(), 1u);
    const DynamicTension& t = solved.output.dynamic_tension.front();
    EXPECT_TRUE(t.converged) << t.diagnostic;
    return t.amplitude_n.maxCoeff() / amplitude;
  };
  // Measured: 1.07e-2 at 0.1 m, 1.07e-4 at 0.01 m (A^2).
  const double change_large = std::abs(fairlead_per_metre(0.1) / tau0 - 1.0);
  const double change_small = std::abs(fairlead_per_metre(0.001) / tau0 - 1.0);
  EXPECT_LT(change_small, 1e-5) << change_large;
  // It vanishes with the amplitude, not at a fixed offset.
  EXPECT_GT(change_large, 5.0 * change_small);
}

}  // namespace
}  // namespace catena
