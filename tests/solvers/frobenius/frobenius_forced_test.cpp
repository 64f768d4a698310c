// SPDX-License-Identifier: MIT
// Tests of the frobenius solver's forced response: the driven end's displacement in Gale's units
// and the response's end conditions in each direction.
#include "solvers/frobenius/frobenius_forced.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "solvers/frobenius/frobenius_root_scan.hpp"
#include "solvers/frobenius/frobenius_test_support.hpp"

namespace catena::internal {
namespace {

using catena::testing::frobenius_plane;

FieldStations stations_between(double sigma1, double sigma2, int points) {
  FieldStations out;
  out.s_m = Vector::LinSpaced(points, 0.0, 1.0);
  for (int i = 0; i < points; ++i)
    out.sigma.push_back(sigma1 + (sigma2 - sigma1) * i / (points - 1));
  return out;
}

TEST(FrobeniusForcedTest, EndDisplacementIsInUnitsOfTheCatenaryParameter) {
  ForcedRequest forced;
  forced.amplitude_m = 0.03;
  forced.direction = ForcingDirection::Tangential;
  EndDisplacement end = forced_end_displacement(forced, 0.5, 2.0);
  EXPECT_DOUBLE_EQ(end.u, 0.015);
  EXPECT_EQ(end.v, 0.0);
  forced.direction = ForcingDirection::Normal;
  end = forced_end_displacement(forced, 0.5, 2.0);
  EXPECT_EQ(end.u, 0.0);
  EXPECT_DOUBLE_EQ(end.v, 0.015);
}

TEST(FrobeniusForcedTest, AGivenVectorIsResolvedOnTheEndsTangentAndNormal) {
  // At sigma = 0.75 the tangent is (0.8, 0.6) and the normal (-0.6, 0.8).
  ForcedRequest forced;
  forced.amplitude_m = 1.0;
  forced.direction = ForcingDirection::GivenVector;
  forced.vector = Vec2(4.0, 3.0);  // along the tangent, not unit
  EndDisplacement end = forced_end_displacement(forced, 0.75, 1.0);
  EXPECT_NEAR(end.u, 1.0, 1e-15);
  EXPECT_NEAR(end.v, 0.0, 1e-15);
  forced.vector = Vec2(1.0, 0.0);
  end = forced_end_displacement(forced, 0.75, 1.0);
  EXPECT_NEAR(end.u, 0.8, 1e-15);
  EXPECT_NEAR(end.v, -0.6, 1e-15);
}

TEST(FrobeniusForcedTest, InPlaneResponseMeetsItsEndConditions) {
  const PlaneSetup base = frobenius_plane(true, -0.4, 1.3);
  ForcedRequest forced;
  forced.end = CableEnd::A;
  forced.direction = ForcingDirection::GivenVector;
  forced.vector = Vec2(0.0, 1.0);
  forced.amplitude_m = 0.02;
  forced.omegas_rad_s = {0.7, 2.9};
  const FieldStations stations = stations_between(-0.4, 1.3, 41);
  ForcedWork work;
  const auto responses = frobenius_forced_responses(base, forced, stations, CableUnits{}, work);
  ASSERT_EQ(responses.size(), 2u);
  const EndDisplacement end = forced_end_displacement(forced, -0.4, 1.0);
  for (const ForcedResponse& r : responses) {
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    ASSERT_EQ(r.u.size(), 41);
    EXPECT_NEAR(r.u(0), end.u, 1e-12);
    EXPECT_NEAR(r.w(0), end.v, 1e-12);
    EXPECT_NEAR(r.u(40), 0.0, 1e-12);
    EXPECT_NEAR(r.w(40), 0.0, 1e-12);
    EXPECT_NEAR(r.max_abs_tension_n, r.tension_n.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(r.v.size(), 0);
  }
}

TEST(FrobeniusForcedTest, OutOfPlaneResponseMeetsItsEndConditions) {
  const PlaneSetup base = frobenius_plane(true, -0.4, 1.3);
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::OutOfPlane;
  forced.amplitude_m = 0.05;
  forced.omegas_rad_s = {1.1};
  ForcedWork work;
  const auto responses =
      frobenius_forced_responses(base, forced, stations_between(-0.4, 1.3, 21), CableUnits{}, work);
  ASSERT_EQ(responses.size(), 1u);
  const ForcedResponse& r = responses.front();
  ASSERT_EQ(r.v.size(), 21);
  EXPECT_NEAR(r.v(0), 0.0, 1e-12);
  EXPECT_NEAR(r.v(20), 0.05, 1e-12);
  EXPECT_EQ(r.u.size(), 0);
}

// The catenary of Gale's Table C-2 (h/b = 0, sag 0.70: sigma = +-2.16351), forced tangentially at
// b with 0.01 a.
ForcedRequest gale_tangential(std::vector<double> omegas) {
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::Tangential;
  forced.amplitude_m = 0.01;
  forced.omegas_rad_s = std::move(omegas);
  return forced;
}
constexpr double kGaleSigma = 2.1635070912;

TEST(FrobeniusForcedTest, HighFrequencyBasisBoundsThePhaseOfEachExpansion) {
  // Omega = 100 turns through about 170 rad of phase from the apex to an end: a single expansion
  // would sum terms of e^170. With the wave limit every expansion spans at most 8 rad, so the
  // basis has more centres as Omega grows, and each series stays short.
  PlaneSetup setup = frobenius_plane(true, -kGaleSigma, kGaleSigma);
  setup.settings.max_phase_per_expansion = kForcedPhasePerExpansion;
  const CatenaryBasis<long double> low(true, 3.0L, 1.0L, setup.eta_max, setup.settings);
  const CatenaryBasis<long double> high(true, 100.0L, 1.0L, setup.eta_max, setup.settings);
  EXPECT_TRUE(low.converged() && high.converged() && high.covers());
  EXPECT_GE(high.num_centres(), 170 / (2 * 8));
  EXPECT_GT(high.num_centres(), 4 * low.num_centres());
  EXPECT_LE(high.num_centres(), forced_centres_needed(setup, 100.0));
}

TEST(FrobeniusForcedTest, HighFrequencyResponseIsFiniteAndNotAResonance) {
  // Regression: at Omega = 40 the response was 97.15 (the series' cancellation ate long double's
  // digits; fe and shooting agree on 35.96) and from 50 up it was called a resonance (the scaled
  // determinant falls like Omega^-10 away from any natural frequency). Reference values: shooting
  // at rtol 1e-10 (verification/scenes/gale/gale-c-2-high-frequency-hb0.00-sag0.70.toml), which
  // agrees with this response to 2e-10.
  const PlaneSetup base = frobenius_plane(true, -kGaleSigma, kGaleSigma);
  FieldStations stations = stations_between(-kGaleSigma, kGaleSigma, 201);
  ForcedWork work;
  const auto responses = frobenius_forced_responses(base, gale_tangential({40.0, 100.0}), stations,
                                                    CableUnits{}, work);
  ASSERT_EQ(responses.size(), 2u);
  const double expected[] = {35.9645157, 224.385362};
  for (std::size_t i = 0; i < 2; ++i) {
    const ForcedResponse& r = responses[i];
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    EXPECT_FALSE(r.at_resonance);
    EXPECT_NEAR(r.max_abs_tension_n, expected[i], 1e-6 * expected[i]);
    EXPECT_GT(r.relative_error_estimate, 0.0);
    EXPECT_LT(r.relative_error_estimate, 1e-5);
  }
  EXPECT_GT(work.centres, 4);
  EXPECT_GT(work.terms, 0);
}

TEST(FrobeniusForcedTest, ForcingAtItsOwnNaturalFrequencyIsAResonanceAndNearItIsFlagged) {
  // In-plane mode 1 of the Gale C-2 catenary, Omega = 1.33593302107 (the solver's own root, to
  // 1e-13).
  const PlaneSetup base = frobenius_plane(true, -kGaleSigma, kGaleSigma);
  const PlaneRoots found = find_frequencies(base, 1, RootSettings{});
  ASSERT_EQ(found.roots.size(), 1u);
  const double natural = found.roots[0].omega;
  EXPECT_NEAR(natural, 1.33593302107, 1e-10);
  ForcedWork work;
  const auto responses =
      frobenius_forced_responses(base, gale_tangential({natural, natural * (1.0 + 7e-9)}),
                                 stations_between(-kGaleSigma, kGaleSigma, 51), CableUnits{}, work);
  ASSERT_EQ(responses.size(), 2u);
  EXPECT_TRUE(responses[0].at_resonance);
  EXPECT_NE(responses[0].diagnostic.find("resonance"), std::string::npos);
  EXPECT_EQ(responses[0].tension_n.size(), 0);
  // 7e-9 (relative) away, far beyond the root's accuracy: a finite, flagged response.
  EXPECT_TRUE(responses[1].diagnostic.empty()) << responses[1].diagnostic;
  EXPECT_TRUE(responses[1].near_resonance);
  EXPECT_GT(responses[1].max_abs_tension_n, 1e5);
  EXPECT_LT(responses[1].relative_error_estimate, 1e-2);
}

TEST(FrobeniusForcedTest, AFrequencyBeyondTheSeriesIsDeclinedWithAReasonNotCalledAResonance) {
  // Regression: at 1e9 the tension came back null without a word.
  const PlaneSetup base = frobenius_plane(true, -kGaleSigma, kGaleSigma);
  ForcedWork work;
  const auto responses =
      frobenius_forced_responses(base, gale_tangential({1e9}),
                                 stations_between(-kGaleSigma, kGaleSigma, 11), CableUnits{}, work);
  ASSERT_EQ(responses.size(), 1u);
  EXPECT_FALSE(responses[0].at_resonance);
  EXPECT_NE(responses[0].diagnostic.find("beyond the frobenius series"), std::string::npos)
      << responses[0].diagnostic;
  EXPECT_GT(forced_centres_needed(base, 1e9), kForcedMaxCentres);
}

}  // namespace
}  // namespace catena::internal
