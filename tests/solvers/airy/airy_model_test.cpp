// SPDX-License-Identifier: MIT
// Tests of the omega-independent Airy model (src/solvers/airy/airy_model.cpp): the static
// curvature, the three linear fits of alpha^2(s), the travel time and the Airy argument, each
// against the exact statics they approximate.
#include "solvers/airy/airy_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

catena::testing::SolvedProblem taut() {
  return catena::testing::prepare(make_taut_inclined_problem(0.18, 23.46, 38.0, 1.0));
}

AiryModel model_of(const catena::testing::SolvedProblem& s, AiryCurvatureFit fit, int panels = 4) {
  return build_airy_model(s.problem, s.statics, s.groups, fit, panels);
}

TEST(AiryModel, CurvatureIsTheStaticAngleDerivative) {
  // alpha = dphi0/ds with tan phi0 = V/H: by central differences of atan2(V, H) (step 1e-4 L:
  // truncation ~1e-9 relative, rounding ~1e-12).
  const auto s = taut();
  const double L = s.problem.cable.length_m, ds = 1e-4 * L;
  const double H = s.statics.horizontal_force_n();
  for (double xi : {0.1, 0.5, 0.9}) {
    const double angle_ahead = std::atan2(s.statics.vertical_force_n(xi * L + ds), H);
    const double angle_behind = std::atan2(s.statics.vertical_force_n(xi * L - ds), H);
    const double derivative = (angle_ahead - angle_behind) / (2.0 * ds);
    // The statics' V grows with the unstretched coordinate s: dphi0/ds = W0 H / T^2.
    EXPECT_LE(relative_error(static_curvature(s.statics, xi * L), derivative), 1e-7) << xi;
  }
}

TEST(AiryModel, EndValuesAndMassRatioComeFromTheStatics) {
  const auto s = taut();
  const AiryModel model = model_of(s, AiryCurvatureFit::Tangent);
  const double L = s.problem.cable.length_m;
  EXPECT_EQ(model.length, L);
  EXPECT_EQ(model.alpha_end[0], static_curvature(s.statics, 0.0));
  EXPECT_EQ(model.alpha_end[1], static_curvature(s.statics, L));
  EXPECT_DOUBLE_EQ(model.c_end[1], std::sqrt(s.statics.tension_n(L) / model.normal_mass));
  EXPECT_DOUBLE_EQ(model.h, s.groups.mass_ratio);
  EXPECT_DOUBLE_EQ(model.inverse_ea, 1.0 / s.problem.cable.axial_stiffness_n);
}

TEST(AiryModel, TangentFitTouchesAlphaSquaredAtTheChordAnglePoint) {
  const auto s = taut();
  const AiryModel model = model_of(s, AiryCurvatureFit::Tangent);
  const double s_a = s.groups.s_at_chord_angle_m, ds = 1e-4 * s.problem.cable.length_m;
  const double alpha = static_curvature(s.statics, s_a);
  EXPECT_EQ(model.s_ref, s_a);
  EXPECT_DOUBLE_EQ(model.a2_ref, alpha * alpha);
  auto alpha2 = [&](double x) { return std::pow(static_curvature(s.statics, x), 2); };
  const double slope = (alpha2(s_a + ds) - alpha2(s_a - ds)) / (2.0 * ds);
  EXPECT_LE(relative_error(model.a2_slope, slope), 1e-7);
  // A rising chord: tension grows along s, curvature falls, Q0 = -h slope > 0, kappa > 0.
  EXPECT_LT(model.a2_slope, 0.0);
  EXPECT_GT(model.kappa, 0.0);
  EXPECT_LE(relative_error(std::pow(model.kappa, 3), -model.h * model.a2_slope), 1e-14);
}

TEST(AiryModel, SecantFitPassesThroughBothEnds) {
  const auto s = taut();
  const AiryModel model = model_of(s, AiryCurvatureFit::Secant);
  const double L = s.problem.cable.length_m;
  EXPECT_EQ(model.s_ref, 0.0);
  EXPECT_EQ(model.a2_ref, model.alpha_end[0] * model.alpha_end[0]);
  EXPECT_LE(
      relative_error(model.a2_ref + model.a2_slope * L, model.alpha_end[1] * model.alpha_end[1]),
      1e-14);
}

TEST(AiryModel, PaperFitIsEquations17And18) {
  // alpha0 = eps cos(phi_a) / L at mid-span; alpha^2 slope -4 eps sin(phi_a) alpha0^2 / L.
  const auto s = taut();
  const AiryModel model = model_of(s, AiryCurvatureFit::Paper);
  const double L = s.problem.cable.length_m, eps = s.groups.eps, phi = s.groups.chord_angle_rad;
  const double alpha0 = eps * std::cos(phi) / L;
  EXPECT_EQ(model.s_ref, 0.5 * L);
  EXPECT_DOUBLE_EQ(model.a2_ref, alpha0 * alpha0);
  EXPECT_DOUBLE_EQ(model.a2_slope, -4.0 * eps * std::sin(phi) * alpha0 * alpha0 / L);
}

TEST(AiryModel, FallingChordHasANegativeCubeRoot) {
  // The same cable described from its upper end: tension falls along s, so Q0 < 0.
  const auto rising = taut();
  Problem falling = rising.problem;
  const double L = rising.problem.cable.length_m;
  falling.prescribed_forces =
      EndForces{rising.statics.horizontal_force_n(), -rising.statics.vertical_force_n(L)};
  falling.supports.a_m = Vec2::Zero();
  falling.supports.b_m = catenary_end_offset(falling.cable, falling.prescribed_forces->horizontal_n,
                                             falling.prescribed_forces->vertical_a_n);
  const auto s = catena::testing::prepare(falling);
  ASSERT_LT(s.groups.chord_angle_rad, 0.0);
  const AiryModel model = model_of(s, AiryCurvatureFit::Tangent);
  EXPECT_LT(model.kappa, 0.0);
  EXPECT_LE(relative_error(model.kappa, -model_of(rising, AiryCurvatureFit::Tangent).kappa), 1e-10);
}

TEST(AiryModel, TravelTimeIsTheIntegralOfTheSlowness) {
  // Against a composite Simpson rule with 2000 intervals (T is smooth: error ~1e-14 relative)
  // and against itself with 1 and 40 panels (the integrand is analytic: already converged).
  const auto s = taut();
  const double L = s.problem.cable.length_m;
  const AiryModel model = model_of(s, AiryCurvatureFit::Tangent);
  auto slowness = [&](double x) { return std::sqrt(model.normal_mass / s.statics.tension_n(x)); };
  const int n = 2000;
  double simpson = slowness(0.0) + slowness(L);
  for (int i = 1; i < n; ++i) simpson += (i % 2 ? 4.0 : 2.0) * slowness(i * L / n);
  simpson *= L / (3.0 * n);
  EXPECT_LE(relative_error(model.travel_time, simpson), 1e-12);
  EXPECT_LE(
      relative_error(model_of(s, AiryCurvatureFit::Tangent, 1).travel_time, model.travel_time),
      1e-13);
  EXPECT_LE(
      relative_error(model_of(s, AiryCurvatureFit::Tangent, 40).travel_time, model.travel_time),
      1e-13);
}

TEST(AiryModel, AiryArgumentFallsLinearlyAtRateKappa) {
  // -z(s) = -Q(s)/kappa^2 with Q = Q0 (s - s0) and Q0 = kappa^3: d(-z)/ds = -kappa, any omega;
  // omega only shifts it, by -m omega^2 / (EA kappa^2).
  const auto s = taut();
  const AiryModel model = model_of(s, AiryCurvatureFit::Tangent);
  const double L = model.length;
  for (double omega : {0.0, 3.0, 30.0}) {
    const double slope = (airy_argument(model, omega, L) - airy_argument(model, omega, 0.0)) / L;
    EXPECT_LE(relative_error(slope, -model.kappa), 1e-12) << omega;
  }
  const double shift = airy_argument(model, 2.0, 0.0) - airy_argument(model, 0.0, 0.0);
  EXPECT_LE(
      relative_error(shift, -model.mass * 4.0 * model.inverse_ea / (model.kappa * model.kappa)),
      1e-9);
}

}  // namespace
}  // namespace catena::internal
