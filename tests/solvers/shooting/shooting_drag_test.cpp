// SPDX-License-Identifier: MIT
// Tests of the `shooting` solver's linear solve inside the drag linearisation
// (docs/explanation/methods/shooting.md, "Drag and dynamic tension"), each against an independent
// value:
//  - a profile that adds no drag: the damped forced response of forced(), bit for bit;
//  - the tangential added mass: the undamped axial bar u = A sin(ks)/sin(kL), k^2 = (m + ma_t)
//    w^2 / EA, tau = EA u' (closed form);
//  - a uniform drag profile: the out-of-plane taut string v = A sin(ks)/sin(kL),
//    k^2 = (1+e)/T (M w^2 - i w c_n), and the axial bar with k^2 = ((m + ma_t) w^2 - i w c_t)/EA,
//    tau = EA u' (closed forms), within the response's own estimate;
//  - the damped forced response of a line lying on the seabed (a string and a bar on a damped
//    Winkler foundation with drag, closed forms), with a stiff foundation (1000 e-folds) too;
//  - coefficients varying along the grounded run (friction, a kinked profile): within the
//    estimate of the response at rtol 1e-13;
//  - a chain-wire-chain line resting on the seabed, irregular motion (the cost figure of the docs)
//    and regular motion in both planes: the fixed points converge with honest estimates.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "solvers/common/drag_profile.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_damped_forced.hpp"
#include "solvers/shooting/shooting_damped_integrator.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;
using internal::DampedShootingIntegrator;
using internal::DragLinearisation;
using internal::DragProfile;
using internal::ForcedOutcome;
using internal::IntegratorSettings;
using internal::ShootingCoefficients;

constexpr double kRtol = 1e-10;

IntegratorSettings settings(double rtol = kRtol) {
  IntegratorSettings s;
  s.relative_tolerance = rtol;
  s.absolute_tolerance = rtol / 100.0;
  return s;
}

// sin(q s) / sin(q L) for complex q without overflow: sinh(p s) / sinh(p L), p = -i q with
// Re p >= 0, as e^{p (s - L)} (1 - e^{-2 p s}) / (1 - e^{-2 p L}).
Complex sine_ratio(Complex q2, double s, double L) {
  Complex p = std::sqrt(-q2);
  if (p.real() < 0.0) p = -p;
  if (std::abs(p) * L < 1e-3) return s / L;
  return std::exp(p * (s - L)) * (1.0 - std::exp(-2.0 * p * s)) / (1.0 - std::exp(-2.0 * p * L));
}
// Its derivative with respect to s.
Complex sine_ratio_derivative(Complex q2, double s, double L) {
  Complex p = std::sqrt(-q2);
  if (p.real() < 0.0) p = -p;
  return p * std::exp(p * (s - L)) * (1.0 + std::exp(-2.0 * p * s)) /
         (1.0 - std::exp(-2.0 * p * L));
}

// Straight cable along x of tension T (weight 1e-9 N/m, the damped solver test's cable), with the
// drag of diameter d, normal Cd and tangential CdAx, and the tangential added mass ma_t.
Problem straight_cable(double T, double EA, double cd, double cd_axial, double ma_t) {
  Problem problem;
  const double L = 10.0;
  problem.cable.length_m = L;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = EA;
  problem.cable.mass_kg_per_m = 1.0;
  problem.cable.added_mass_kg_per_m = 0.5;
  problem.cable.added_mass_tangential_kg_per_m = ma_t;
  problem.cable.drag = MorisonDrag{0.05, cd, cd_axial};
  problem.supports.b_m = Vec2(L * (1.0 + T / EA), 0.0);
  return problem;
}

// Stations 0, L/20, ..., L.
Vector stations_of(double L) { return Vector::LinSpaced(21, 0.0, L); }

// The damped forced response of `solved` driven at b by `forced`, with `profile` added.
ForcedOutcome with_drag(const testing::SolvedProblem& solved,
                        const ForcedRequest& forced,
                        const DragProfile& profile,
                        double rtol = kRtol) {
  const ShootingCoefficients k = ShootingCoefficients::from_statics(solved.statics);
  DampedShootingIntegrator integrator(internal::damped_forced_plane(k, forced), k, settings(rtol));
  integrator.set_drag(&profile);
  return internal::shooting_damped_forced_responses(integrator, k, forced, profile.stations(),
                                                    settings(rtol), true);
}

ForcedRequest drive(ForcingDirection direction, double amplitude, double omega) {
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = direction;
  forced.amplitude_m = amplitude;
  forced.omegas_rad_s = {omega};
  return forced;
}

// A profile of uniform velocity scales V_n, V_t on `problem`.
DragProfile uniform_profile(const Problem& problem, const Vector& stations, double vn, double vt) {
  DragProfile profile(problem, stations, DragLinearisation::Harmonic);
  profile.set_velocity_scales(Vector::Constant(stations.size(), vn),
                              Vector::Constant(stations.size(), vt));
  return profile;
}

// Every station of `got` (real and imaginary parts) against `want(s)`; returns the largest error
// relative to the largest modulus.
template <class Want>
double largest_error(const Vector& s, const Vector& re, const Vector& im, Want want) {
  double worst = 0.0, scale = 0.0;
  for (Index j = 0; j < s.size(); ++j) {
    const Complex w = want(s[j]);
    scale = std::max(scale, std::abs(w));
    worst = std::max(worst, std::abs(Complex(re[j], im[j]) - w));
  }
  return worst / scale;
}

TEST(ShootingDrag, ProfileWithoutDragIsTheDampedForcedResponse) {
  Problem problem = testing::mooring_line(Vec2(900.0, 300.0));
  problem.cable.damping.normal_n_s_per_m2 = 8.0;
  problem.cable.damping.tangential_n_s_per_m2 = 1.2;
  const testing::SolvedProblem solved = testing::prepare(problem);
  const Vector stations = stations_of(problem.cable.length_m);
  const ForcedRequest forced = drive(ForcingDirection::Normal, 1.0, 0.4);
  // Drag coefficients zero: the profile adds nothing whatever the velocity scales.
  const DragProfile profile = uniform_profile(problem, stations, 1.0, 1.0);
  ASSERT_FALSE(profile.has_drag());
  const ForcedOutcome a = with_drag(solved, forced, profile);
  const ShootingCoefficients k = ShootingCoefficients::from_statics(solved.statics);
  const ForcedOutcome b =
      internal::shooting_damped_forced_responses(k, forced, stations, settings());
  ASSERT_EQ(a.responses.size(), 1u) << a.summary.message;
  ASSERT_EQ(b.responses.size(), 1u) << b.summary.message;
  for (Index j = 0; j < stations.size(); ++j) {
    EXPECT_EQ(a.responses[0].tension_n[j], b.responses[0].tension_n[j]);
    EXPECT_EQ(a.responses[0].tension_imag_n[j], b.responses[0].tension_imag_n[j]);
    EXPECT_EQ(a.responses[0].w[j], b.responses[0].w[j]);
    EXPECT_EQ(a.responses[0].u_imag[j], b.responses[0].u_imag[j]);
  }
  EXPECT_EQ(a.responses[0].relative_error_estimate, b.responses[0].relative_error_estimate);
}

TEST(ShootingDrag, TangentialAddedMassIsTheAxialBarsInertia) {
  const double T = 2000.0, EA = 2e4, ma_t = 0.7, A = 0.01, omega = 20.0;
  const Problem problem = straight_cable(T, EA, 0.0, 0.0, ma_t);
  SolveRequest request = testing::modes_request(0, 0);
  request.points = 21;
  request.forced = drive(ForcingDirection::Tangential, A, omega);
  const testing::SolvedProblem solved =
      testing::solve_problem(solve_shooting, problem, request, ShootingSolverOptions{});
  ASSERT_EQ(solved.output.forced.size(), 1u) << solved.output.summary.full_report();
  const ForcedResponse& r = solved.output.forced[0];
  ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
  const double L = problem.cable.length_m, q2 = (1.0 + ma_t) * omega * omega / EA;
  const Vector zero = Vector::Zero(r.s_m.size());
  const double u_error =
      largest_error(r.s_m, r.u, zero, [&](double s) { return A * sine_ratio(q2, s, L); });
  const double tau_error = largest_error(
      r.s_m, r.tension_n, zero, [&](double s) { return EA * A * sine_ratio_derivative(q2, s, L); });
  std::printf("axial bar with ma_t: u error %.2e, tension error %.2e, estimate %.2e\n", u_error,
              tau_error, r.relative_error_estimate);
  EXPECT_LT(u_error, 1e-7);
  EXPECT_LT(tau_error, 1e-7);
  // Without ma_t the closed form is another one: the test can fail.
  const double q2_plain = omega * omega / EA;
  EXPECT_GT(std::abs(A * sine_ratio(q2_plain, 0.5 * L, L) - A * sine_ratio(q2, 0.5 * L, L)),
            1e-3 * A);
}

TEST(ShootingDrag, UniformDragOnATautStringAndAnAxialBarMatchesTheClosedForms) {
  const double T = 2000.0, EA = 2e4, ma_t = 0.3, A = 0.01, omega = 14.0;
  const Problem problem = straight_cable(T, EA, 1.2, 0.8, ma_t);
  const testing::SolvedProblem solved = testing::prepare(problem);
  const double L = problem.cable.length_m, e = solved.statics.tension_n(0.5 * L) / EA;
  const double T0 = solved.statics.tension_n(0.5 * L);
  const Vector stations = stations_of(L);
  const DragProfile profile = uniform_profile(problem, stations, 3.0, 2.0);
  const double c_n = profile.normal_at(0.5 * L, 0), c_t = profile.tangential_at(0.5 * L, 0);
  ASSERT_GT(c_n, 0.0);
  ASSERT_GT(c_t, 0.0);
  // Out of plane: the string.
  {
    const ForcedOutcome out =
        with_drag(solved, drive(ForcingDirection::OutOfPlane, A, omega), profile);
    ASSERT_EQ(out.responses.size(), 1u) << out.summary.message;
    const ForcedResponse& r = out.responses[0];
    const Complex q2 = (1.0 + e) / T0 * Complex(1.5 * omega * omega, -omega * c_n);
    const double error =
        largest_error(r.s_m, r.v, r.v_imag, [&](double s) { return A * sine_ratio(q2, s, L); });
    std::printf("string, uniform c_n = %.4g: error %.2e, estimate %.2e\n", c_n, error,
                r.relative_error_estimate);
    EXPECT_LT(error, r.relative_error_estimate);
    EXPECT_LT(r.relative_error_estimate, 1e-7);
  }
  // Along the cable: the bar, with the tangential added mass.
  {
    const ForcedOutcome out =
        with_drag(solved, drive(ForcingDirection::Tangential, A, omega), profile);
    ASSERT_EQ(out.responses.size(), 1u) << out.summary.message;
    const ForcedResponse& r = out.responses[0];
    const Complex q2 = Complex((1.0 + ma_t) * omega * omega, -omega * c_t) / EA;
    const double u_error =
        largest_error(r.s_m, r.u, r.u_imag, [&](double s) { return A * sine_ratio(q2, s, L); });
    const double tau_error = largest_error(r.s_m, r.tension_n, r.tension_imag_n, [&](double s) {
      return EA * A * sine_ratio_derivative(q2, s, L);
    });
    std::printf("bar, uniform c_t = %.4g: u error %.2e, tension error %.2e, estimate %.2e\n", c_t,
                u_error, tau_error, r.relative_error_estimate);
    EXPECT_LT(std::max(u_error, tau_error), r.relative_error_estimate);
    EXPECT_LT(r.relative_error_estimate, 1e-7);
  }
}

// A taut line of length L lying on the seabed from A to B (shooting_seabed_test's), with section
// damping, the seabed's dashpot, the tangential added mass and drag.
struct GroundedString {
  double L = 100.0, EA = 5e6, H = 1e5, m = 10.0, ma = 2.0, ma_t = 1.0, W = 50.0;
  double k_s = 2e4, k_t = 5e3, c_s = 300.0, c_n = 4.0, c_t = 1.0, friction = 0.0;

  Problem problem() const {
    Problem p;
    p.cable = {L, W, EA, m, ma};
    p.cable.added_mass_tangential_kg_per_m = ma_t;
    p.cable.damping.normal_n_s_per_m2 = c_n;
    p.cable.damping.tangential_n_s_per_m2 = c_t;
    p.cable.drag = MorisonDrag{0.1, 1.2, 0.5};
    p.supports.a_m = Vec2(0.0, -50.0);
    p.supports.b_m = Vec2(L * (1.0 + H / EA), -50.0);
    p.seabed = Seabed{-50.0, friction, k_s, k_t, c_s};
    return p;
  }
  testing::SolvedProblem solved() const {
    const Problem p = problem();
    testing::SolvedProblem s{
        p, StaticSolution(p.as_line(), p.supports.a_m, *p.seabed, H, L), {}, {}};
    s.groups = compute_dimensionless_groups(s.problem, s.statics);
    return s;
  }
};

// Forced at B, the line on the seabed is a string or a bar on a damped foundation:
// y = A sin(q s)/sin(q L), q^2 = (w^2 mass - i w c - k - i w c_s) / stiffness. Stations every
// L/20 and at 1, 0.2, 0.05 and 0.01 m from B (where a stiff foundation's response lives). Returns
// the largest number of RHS evaluations of a direction's response (estimate included).
long expect_grounded_closed_forms(const GroundedString& g, double omega, double max_estimate) {
  const testing::SolvedProblem solved = g.solved();
  EXPECT_TRUE(solved.statics.has_contact());
  Vector stations(25);
  stations << stations_of(g.L).head(20), g.L - 1.0, g.L - 0.2, g.L - 0.05, g.L - 0.01, g.L;
  const DragProfile profile = uniform_profile(solved.problem, stations, 0.5, 0.3);
  const double drag_n = profile.normal_at(0.5 * g.L, 0),
               drag_t = profile.tangential_at(0.5 * g.L, 0);
  const double string_stiffness = g.H / (1.0 + g.H / g.EA);
  const double M = g.m + g.ma;
  struct Case {
    ForcingDirection direction;
    Complex q2;
  };
  const Complex i(0.0, 1.0);
  const Case cases[] = {
      {ForcingDirection::OutOfPlane,
       (omega * omega * M - i * omega * (g.c_n + drag_n) - g.k_t) / string_stiffness},
      {ForcingDirection::Normal,
       (omega * omega * M - i * omega * (g.c_n + drag_n + g.c_s) - g.k_s) / string_stiffness},
      {ForcingDirection::Tangential,
       (omega * omega * (g.m + g.ma_t) - i * omega * (g.c_t + drag_t) - g.k_t) / g.EA}};
  long operations = 0;
  for (const Case& c : cases) {
    const ForcedOutcome out = with_drag(solved, drive(c.direction, 0.01, omega), profile);
    EXPECT_EQ(out.responses.size(), 1u) << out.summary.message;
    if (out.responses.size() != 1u) continue;
    const ForcedResponse& r = out.responses[0];
    EXPECT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    operations = std::max(operations, out.summary.operations);
    const bool out_of_plane = c.direction == ForcingDirection::OutOfPlane;
    const Vector& re = out_of_plane ? r.v : c.direction == ForcingDirection::Normal ? r.w : r.u;
    const Vector& im = out_of_plane                              ? r.v_imag
                       : c.direction == ForcingDirection::Normal ? r.w_imag
                                                                 : r.u_imag;
    const double error =
        largest_error(r.s_m, re, im, [&](double s) { return 0.01 * sine_ratio(c.q2, s, g.L); });
    std::printf("seabed k_s = %.3g, direction %d: error %.2e, estimate %.2e, %ld RHS evaluations\n",
                g.k_s, static_cast<int>(c.direction), error, r.relative_error_estimate,
                out.summary.operations);
    EXPECT_LT(error, r.relative_error_estimate);
    EXPECT_LT(r.relative_error_estimate, max_estimate);
  }
  return operations;
}

TEST(ShootingDrag, DampedLineOnTheSeabedIsAStringAndABarOnADampedFoundation) {
  expect_grounded_closed_forms(GroundedString{}, 45.0, 1e-7);
}

TEST(ShootingDrag, DampedLineOnAStiffSeabedIsExactAtACostIndependentOfTheStiffness) {
  const long soft = expect_grounded_closed_forms(GroundedString{}, 45.0, 1e-7);
  GroundedString g;
  g.k_s = 1e9;  // sqrt(k_s / T) L = 10,000 e-folds under the line (vertical), 2,000 along
  g.k_t = 1e8;
  const long stiff = expect_grounded_closed_forms(g, 45.0, 1e-7);
  EXPECT_LT(stiff, 2 * soft);
}

// Coefficients varying along the grounded run (friction: T(s) linear; a drag profile ramping
// along s, kinked at every station): the response within its estimate of the same response at
// rtol 1e-13 (no closed form here; the step of the run is exact only for frozen coefficients).
TEST(ShootingDrag, VaryingCoefficientsOnTheSeabedStayWithinTheEstimate) {
  GroundedString g;
  g.friction = 0.8;  // T from H at B down to H - 0.8 W L = 0.96 H at A
  g.k_s = 2e6;
  const testing::SolvedProblem solved = g.solved();
  ASSERT_TRUE(solved.statics.has_contact());
  const Vector stations = stations_of(g.L);
  DragProfile profile(solved.problem, stations, DragLinearisation::Stochastic);
  Vector vn = Vector::LinSpaced(stations.size(), 0.1, 2.0), vt = vn.cwiseSqrt();
  vn[7] = 3.0;  // a kink inside the run
  profile.set_velocity_scales(vn, vt);
  for (ForcingDirection direction :
       {ForcingDirection::OutOfPlane, ForcingDirection::Normal, ForcingDirection::Tangential}) {
    const ForcedOutcome out = with_drag(solved, drive(direction, 0.01, 45.0), profile);
    const ForcedOutcome ref = with_drag(solved, drive(direction, 0.01, 45.0), profile, 1e-13);
    ASSERT_EQ(out.responses.size(), 1u) << out.summary.message;
    ASSERT_EQ(ref.responses.size(), 1u) << ref.summary.message;
    const ForcedResponse &r = out.responses[0], &q = ref.responses[0];
    const bool out_of_plane = direction == ForcingDirection::OutOfPlane;
    const bool normal = direction == ForcingDirection::Normal;
    const Vector& re = out_of_plane ? r.v : normal ? r.w : r.u;
    const Vector& im = out_of_plane ? r.v_imag : normal ? r.w_imag : r.u_imag;
    const Vector& re_ref = out_of_plane ? q.v : normal ? q.w : q.u;
    const Vector& im_ref = out_of_plane ? q.v_imag : normal ? q.w_imag : q.u_imag;
    double worst = 0.0, scale = 0.0;
    for (Index j = 0; j < stations.size(); ++j) {
      scale = std::max(scale, std::abs(Complex(re_ref[j], im_ref[j])));
      worst = std::max(worst, std::abs(Complex(re[j] - re_ref[j], im[j] - im_ref[j])));
    }
    std::printf("varying coefficients, direction %d: change %.2e, estimate %.2e\n",
                static_cast<int>(direction), worst / scale, r.relative_error_estimate);
    EXPECT_LT(worst / scale, r.relative_error_estimate);
    EXPECT_LT(r.relative_error_estimate, 1e-7);
  }
}

// Chain-wire-chain line, its bottom chain partly on the seabed, with Morison drag.
Problem chain_wire_chain_on_the_seabed() {
  Problem problem;
  LineSegment chain;
  chain.length_m = 400.0;
  chain.weight_n_per_m = 1200.0;
  chain.axial_stiffness_n = 8e8;
  chain.mass_kg_per_m = 150.0;
  chain.added_mass_kg_per_m = 20.0;
  chain.added_mass_tangential_kg_per_m = 10.0;
  chain.drag = MorisonDrag{0.15, 2.4, 1.15};
  LineSegment wire;
  wire.length_m = 500.0;
  wire.weight_n_per_m = 60.0;
  wire.axial_stiffness_n = 2e8;
  wire.mass_kg_per_m = 8.0;
  wire.added_mass_kg_per_m = 4.0;
  wire.drag = MorisonDrag{0.08, 1.2, 0.008};
  LineSegment top = chain;
  top.length_m = 100.0;
  problem.line.segments = {chain, wire, top};
  problem.supports.a_m = Vec2(0.0, -200.0);
  problem.supports.b_m = Vec2(880.0, 0.0);
  Seabed seabed;
  seabed.z_m = -200.0;
  seabed.stiffness_n_per_m2 = 3e6;
  seabed.damping_n_s_per_m2 = 1e4;
  problem.seabed = seabed;
  return problem;
}

TEST(ShootingDrag, IrregularMotionOfAChainWireChainLineOnTheSeabedConverges) {
  const Problem problem = chain_wire_chain_on_the_seabed();
  SolveRequest request = testing::modes_request(0, 0);
  request.points = 41;
  MotionRequest motion;
  motion.direction = ForcingDirection::GivenVector;
  motion.vector = Vec2(1.0, 0.0);
  motion.jonswap = JonswapSpectrum{6.0, 12.0, 3.3};
  motion.rao = RaoTable{{0.1, 0.5, 1.0, 2.0}, {0.9, 0.6, 0.2, 0.05}, {0.0, 10.0, 20.0, 30.0}};
  motion.frequencies = 200;
  motion.tolerance = 1e-8;
  request.motion = motion;
  const testing::SolvedProblem prepared = testing::prepare(problem);
  ASSERT_TRUE(prepared.statics.has_contact());
  const auto start = std::chrono::steady_clock::now();
  const testing::SolvedProblem solved =
      testing::solve_problem(solve_shooting, problem, request, ShootingSolverOptions{});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(solved.output.dynamic_tension.size(), 1u) << solved.output.summary.full_report();
  const DynamicTension& t = solved.output.dynamic_tension[0];
  std::printf(
      "chain-wire-chain on the seabed, 200 frequencies: fairlead sigma_T %.6g N, anchor %.6g N, "
      "%d iterations, residual %.2e, estimate %.2e, %.2f s (statics included)\n",
      t.fairlead.std_n, t.anchor.std_n, t.iterations, t.residual, t.relative_error_estimate,
      seconds);
  EXPECT_TRUE(t.converged) << t.diagnostic;
  EXPECT_LE(t.residual, 1e-8);
  EXPECT_GT(t.fairlead.std_n, 0.0);
  EXPECT_GT(t.relative_error_estimate, 0.0);
  EXPECT_LT(t.relative_error_estimate, 1e-6);
  // Drag on the grounded part too (its velocity is small but not zero).
  EXPECT_GT(t.normal_damping_n_s_per_m2.maxCoeff(), 0.0);
}

// Regular motion of the same line, out of plane and in plane, two periods each: every fixed point
// converges; in plane the tension amplitude grows with the motion's velocity (8 s against 14 s);
// out of plane the linear dynamic tension is zero and the drag is normal only.
TEST(ShootingDrag, RegularMotionOfTheLineOnTheSeabedConvergesInBothPlanes) {
  const Problem problem = chain_wire_chain_on_the_seabed();
  for (ForcingDirection direction : {ForcingDirection::OutOfPlane, ForcingDirection::GivenVector}) {
    SolveRequest request = testing::modes_request(0, 0);
    request.points = 21;
    MotionRequest motion;
    motion.direction = direction;
    motion.vector = Vec2(1.0, 0.0);
    motion.amplitude_m = 2.0;
    motion.periods_s = {8.0, 14.0};
    request.motion = motion;
    const testing::SolvedProblem solved =
        testing::solve_problem(solve_shooting, problem, request, ShootingSolverOptions{});
    ASSERT_EQ(solved.output.dynamic_tension.size(), 2u) << solved.output.summary.full_report();
    for (const DynamicTension& t : solved.output.dynamic_tension) {
      std::printf(
          "regular, direction %d, period %g s: fairlead amplitude %.6g N, %d iterations, "
          "residual %.2e, estimate %.2e\n",
          static_cast<int>(direction), t.period_s, t.fairlead.amplitude_n, t.iterations, t.residual,
          t.relative_error_estimate);
      EXPECT_TRUE(t.converged) << t.diagnostic;
      EXPECT_GT(t.relative_error_estimate, 0.0);
      EXPECT_LT(t.relative_error_estimate, 1e-6);
    }
    const DynamicTension &fast = solved.output.dynamic_tension[0],
                         &slow = solved.output.dynamic_tension[1];
    if (direction == ForcingDirection::OutOfPlane) {
      EXPECT_EQ(fast.fairlead.amplitude_n, 0.0);
      EXPECT_GT(fast.normal_damping_n_s_per_m2.maxCoeff(), 0.0);
      EXPECT_EQ(fast.tangential_damping_n_s_per_m2.maxCoeff(), 0.0);
    } else {
      EXPECT_GT(fast.fairlead.amplitude_n, slow.fairlead.amplitude_n);
    }
  }
}

}  // namespace
}  // namespace catena
