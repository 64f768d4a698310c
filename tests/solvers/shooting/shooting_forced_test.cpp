// SPDX-License-Identifier: MIT
// Tests of the forced response (src/solvers/shooting/shooting_forced) on a uniform string driven
// at one end, whose response d sin(q s) / sin(q L) is exact, and of its summary: resonances as
// warnings, integration failures as a status with the responses computed so far.
#include "solvers/shooting/shooting_forced.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "shooting_test_strings.hpp"

namespace catena::internal {
namespace {

IntegratorSettings tight() {
  IntegratorSettings settings;
  settings.relative_tolerance = 1e-12;
  settings.absolute_tolerance = 1e-14;
  return settings;
}

const Vector kStations = Vector::LinSpaced(21, 0.0, 1.0);

ForcedRequest drive(ForcingDirection direction, std::vector<double> omegas) {
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = direction;
  forced.amplitude_m = 0.01;
  forced.omegas_rad_s = std::move(omegas);
  return forced;
}

TEST(ShootingForced, OutOfPlaneStringResponseIsExactAndResonanceIsDiagnosed) {
  // T = 1 N, L = 1 m, EA = 4 N: q = sqrt(1.25) omega; the first natural frequency pi / sqrt(1.25).
  const ShootingCoefficients k = testing::horizontal_string(1.0, 1.0, 4.0);
  const double resonance = kPi / std::sqrt(1.25);
  const ForcedOutcome out = shooting_forced_responses(
      k, drive(ForcingDirection::OutOfPlane, {2.0, resonance, 5.0}), kStations, tight());
  EXPECT_EQ(out.summary.termination, Termination::Converged);
  EXPECT_EQ(out.summary.message, "3 of 3 forced frequencies");
  EXPECT_EQ(out.summary.iterations, 3);
  EXPECT_GT(out.summary.operations, 0);
  ASSERT_EQ(out.responses.size(), 3u);
  for (std::size_t i : {0u, 2u}) {
    const ForcedResponse& r = out.responses[i];
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    const double q = std::sqrt(1.25) * r.omega_rad_s;
    for (Index j = 0; j < kStations.size(); ++j) {
      EXPECT_NEAR(r.v[j], 0.01 * std::sin(q * kStations[j]) / std::sin(q), 1e-11) << j;
    }
    EXPECT_EQ(r.max_abs_tension_n, 0.0);
  }
  EXPECT_NE(out.responses[1].diagnostic.find("resonance"), std::string::npos);
  ASSERT_EQ(out.summary.warnings.size(), 1u);
  EXPECT_NE(out.summary.warnings[0].find("resonance"), std::string::npos);
}

TEST(ShootingForced, StraightInextensibleCableMovesOnlyNormally) {
  // Vertical inextensible cable under 1 N: a normal drive is the string response in w (q = omega),
  // an axial drive has no finite response.
  ShootingCoefficients k = testing::horizontal_string(1.0, 1.0);
  k.H = 0.0;
  k.V_A = 1.0;
  bool near = false;
  ShootingIntegrator integrator(Plane::OutOfPlane, k, tight());
  const ForcedResponse normal = shooting_forced_response(
      integrator, k, drive(ForcingDirection::Normal, {}), 2.0, kStations, 1e-12, near);
  ASSERT_TRUE(normal.diagnostic.empty()) << normal.diagnostic;
  for (Index j = 0; j < kStations.size(); ++j) {
    EXPECT_NEAR(normal.w[j], 0.01 * std::sin(2.0 * kStations[j]) / std::sin(2.0), 1e-11) << j;
    EXPECT_EQ(normal.u[j], 0.0);
  }
  const ForcedResponse axial = shooting_forced_response(
      integrator, k, drive(ForcingDirection::Tangential, {}), 2.0, kStations, 1e-12, near);
  EXPECT_NE(axial.diagnostic.find("along its axis"), std::string::npos) << axial.diagnostic;
  EXPECT_EQ(axial.u.size(), 0);
}

TEST(ShootingForced, IntegrationFailureIsAStatusNotAnException) {
  const ShootingCoefficients k = testing::horizontal_string(1.0, 1.0, 4.0);
  IntegratorSettings settings = tight();
  settings.max_steps = 20;
  ForcedOutcome out;
  ASSERT_NO_THROW(out = shooting_forced_responses(k, drive(ForcingDirection::Normal, {300.0}),
                                                  kStations, settings));
  EXPECT_EQ(out.summary.termination, Termination::NumericalFailure);
  EXPECT_TRUE(out.responses.empty());
  EXPECT_NE(out.summary.message.find("0 of 1"), std::string::npos) << out.summary.message;
  EXPECT_NE(out.summary.message.find("max_steps"), std::string::npos) << out.summary.message;
}

TEST(ShootingForced, ResonanceIsDecidedByTheResponsesOwnErrorEstimate) {
  // The response's estimate is rtol / |normalised det|; resonance when it would reach 0.1. With
  // rtol 1e-12: 1e-9 (relative) from the natural frequency the normalised det is ~1e-9, the
  // estimate ~1e-3: a finite, flagged response (the former fixed 1e3 rtol called it resonance);
  // at the natural frequency itself, a resonance.
  const ShootingCoefficients k = testing::horizontal_string(1.0, 1.0, 4.0);
  const double natural = kPi / std::sqrt(1.25);
  const ForcedOutcome out = shooting_forced_responses(
      k, drive(ForcingDirection::OutOfPlane, {natural, natural * (1.0 + 1e-9), 2.0}), kStations,
      tight());
  ASSERT_EQ(out.responses.size(), 3u);
  EXPECT_TRUE(out.responses[0].at_resonance);
  const ForcedResponse& near = out.responses[1];
  ASSERT_TRUE(near.diagnostic.empty()) << near.diagnostic;
  EXPECT_FALSE(near.at_resonance);
  EXPECT_TRUE(near.near_resonance);
  EXPECT_LT(near.relative_error_estimate, 0.1);
  // The exact response 0.01 sin(q s) / sin(q L) within its own estimate.
  const double q = std::sqrt(1.25) * near.omega_rad_s;
  const double peak = 0.01 / std::abs(std::sin(q));
  EXPECT_NEAR(near.v.cwiseAbs().maxCoeff(), peak, 3.0 * near.relative_error_estimate * peak);
  EXPECT_FALSE(out.responses[2].near_resonance);
  EXPECT_FALSE(out.responses[2].at_resonance);
}

}  // namespace
}  // namespace catena::internal
