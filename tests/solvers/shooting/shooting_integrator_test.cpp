// SPDX-License-Identifier: MIT
// Tests of the CVODE shot (src/solvers/shooting/shooting_integrator) on a straight horizontal
// string, where the principal solutions are exact: Phi' = b F, F' = -c Phi from Phi = 0, F = 1
// gives F = cos(q x), Phi = (b / q) sin(q x), q = sqrt(b c), separately for the axial and the
// transverse direction. The shot starts at F^ = kappa I, kappa^2 = max(Omega, 1) (the balancing
// of the carried variables), so the returned basis is kappa times the unit-force solution.
#include "solvers/shooting/shooting_integrator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "catena/core/types.hpp"
#include "shooting_test_strings.hpp"

namespace catena::internal {
namespace {

IntegratorSettings tight(double max_condition = 1e2) {
  IntegratorSettings settings;
  settings.relative_tolerance = 1e-12;
  settings.absolute_tolerance = 1e-14;
  settings.max_condition = max_condition;
  return settings;
}

// T = 1 N, EA = 4 N (strain 0.25), L = 1 m, m = M: b_axial = 1/4, b_normal = 5/4, c = Omega^2.
// Axial wavenumber Omega / 2, transverse sqrt(5/4) Omega (scaled).
const ShootingCoefficients kString = testing::horizontal_string(1.0, 1.0, 4.0);

TEST(ShootingIntegrator, OutOfPlaneShotMatchesTheStringSolution) {
  ShootingIntegrator integrator(Plane::OutOfPlane, kString, tight());
  for (double omega : {0.5, 4.0, 11.0}) {
    const Shot shot = integrator.shoot(omega);
    const double q = std::sqrt(1.25) * omega;
    const double kappa = std::sqrt(std::max(omega, 1.0));  // Omega = omega here
    EXPECT_NEAR(shot.y_end(0, 0), kappa * 1.25 / q * std::sin(q), 1e-9 * kappa) << omega;
    EXPECT_NEAR(shot.y_end(1, 0), kappa * std::cos(q), 1e-9 * kappa) << omega;
    EXPECT_EQ(shot.count, static_cast<int>(std::floor(q / kPi))) << omega;
    EXPECT_LT(shot.phase_defect, 1e-6);
  }
  EXPECT_GT(integrator.total_steps(), 0);
  EXPECT_GE(integrator.total_rhs_evaluations(), integrator.total_steps());
}

// The in-plane shot of a horizontal string of axial compliance b_axial = T/EA against the exact
// diagonal frame: counts, and det Phi / sqrt(det G) in the carried variables, where
// Phi~' = kappa^2 b F~ and F~' = -(c / kappa^2) Phi~ from F~ = I, the axial row stretched by
// sigma (axial frame: b_axial -> sigma^2 b_axial) when sigma >= kMinAxialStretch.
void expect_exact_inplane_shots(double ea, double expected_sigma) {
  const ShootingCoefficients string = testing::horizontal_string(1.0, 1.0, ea);
  const double b_axial = 1.0 / ea, b_normal = 1.0 + 1.0 / ea;
  const double sigma = axial_stretch(b_axial, 0.0);
  const double used = sigma >= kMinAxialStretch ? sigma : 1.0;
  EXPECT_DOUBLE_EQ(used, expected_sigma);
  ShootingIntegrator integrator(Plane::InPlane, string, tight());
  for (double omega : {1.0, 3.0, 7.0, 13.0}) {
    const Shot shot = integrator.shoot(omega);
    const double q_axial = std::sqrt(b_axial) * omega, q_normal = std::sqrt(b_normal) * omega;
    const int expected = static_cast<int>(std::floor(q_axial / kPi) + std::floor(q_normal / kPi));
    EXPECT_EQ(shot.count, expected) << omega;
    const double kappa2 = std::max(omega, 1.0);
    const double phi_a = kappa2 * used * used * b_axial / q_axial * std::sin(q_axial);
    const double phi_n = kappa2 * b_normal / q_normal * std::sin(q_normal);
    const double g_a = phi_a * phi_a + std::cos(q_axial) * std::cos(q_axial);
    const double g_n = phi_n * phi_n + std::cos(q_normal) * std::cos(q_normal);
    EXPECT_NEAR(shot.determinant, phi_a * phi_n / std::sqrt(g_a * g_n), 1e-8) << omega;
  }
}

TEST(ShootingIntegrator, InPlaneCountAddsAxialAndTransverseConjugatePoints) {
  expect_exact_inplane_shots(4.0, 1.0);  // sigma = 2 < kMinAxialStretch: physical frame
}

TEST(ShootingIntegrator, AxialFrameKeepsCountsAndTheExactStretchedDeterminant) {
  expect_exact_inplane_shots(100.0, 10.0);  // sigma = 1 / sqrt(1/100) = 10
}

TEST(ShootingIntegrator, AxialStretchBalancesTheAxialRowAndLeavesDeepSagAlone) {
  // 1 / max(sqrt(T_ref / EA), tangent spread), within [1, kMaxAxialStretch].
  EXPECT_DOUBLE_EQ(axial_stretch(1e-10, 1e-6), 1e5);
  EXPECT_DOUBLE_EQ(axial_stretch(1e-14, 1e-3), 1e3);
  EXPECT_DOUBLE_EQ(axial_stretch(1e-3, 0.8), 1.25);
  EXPECT_DOUBLE_EQ(axial_stretch(1e-3, 1.5), 1.0);  // deep sag: nothing to balance
  EXPECT_DOUBLE_EQ(axial_stretch(0.0, 0.0), kMaxAxialStretch);
}

TEST(ShootingIntegrator, StationsMapBackThroughTheReorthonormalisations) {
  // max_condition 2 forces many QR restarts; the solution with Phi(1) = d, combined at the
  // stations through the R factors, must still be the exact d sin(q x) / sin(q).
  ShootingIntegrator integrator(Plane::InPlane, kString, tight(2.0));
  const double omega = 9.0, q_axial = 0.5 * omega, q_normal = std::sqrt(1.25) * omega;
  const std::vector<double> stations = {0.0, 0.1, 0.37, 0.5, 0.8, 1.0};
  const Shot shot = integrator.shoot(omega, 1.0, &stations);
  ASSERT_GT(shot.segment_r.size(), 0u) << "no re-orthonormalisation: the test would prove nothing";
  ASSERT_EQ(shot.station_y.size(), stations.size());
  const Eigen::Vector2d d(0.3, -0.7);
  const Eigen::MatrixXd phi_end = shot.y_end.topRows(2);
  const Eigen::VectorXd c = phi_end.partialPivLu().solve(d);
  for (std::size_t j = 0; j < stations.size(); ++j) {
    const Eigen::VectorXd y = combine_at_station(shot, j, c);
    const double x = stations[j];
    EXPECT_NEAR(y[0], d[0] * std::sin(q_axial * x) / std::sin(q_axial), 1e-8) << x;
    EXPECT_NEAR(y[1], d[1] * std::sin(q_normal * x) / std::sin(q_normal), 1e-8) << x;
  }
  EXPECT_EQ(integrator.total_reorthonormalisations(), static_cast<long>(shot.segment_r.size()));
}

TEST(ShootingIntegrator, ShotFromBIsTheMirrorImage) {
  // A uniform string is symmetric: shot from b, the end frame is the same, and the force is
  // returned with its physical sign (d/ds = -d/dx').
  ShootingIntegrator integrator(Plane::OutOfPlane, kString, tight());
  const Shot from_a = integrator.shoot(3.0);
  const Shot from_b = integrator.shoot(3.0, 1.0, nullptr, true);
  EXPECT_NEAR(from_b.y_end(0, 0), from_a.y_end(0, 0), 1e-10);
  EXPECT_NEAR(from_b.y_end(1, 0), -from_a.y_end(1, 0), 1e-10);
  EXPECT_EQ(from_b.count, from_a.count);
}

TEST(ShootingIntegrator, TooFewStepsThrowShootingFailureNamingMaxSteps) {
  IntegratorSettings settings = tight();
  settings.max_steps = 20;
  ShootingIntegrator integrator(Plane::InPlane, kString, settings);
  try {
    integrator.shoot(200.0);
    FAIL() << "no exception";
  } catch (const ShootingFailure& failure) {
    EXPECT_NE(std::string(failure.what()).find("max_steps"), std::string::npos) << failure.what();
  }
}

}  // namespace
}  // namespace catena::internal
