// SPDX-License-Identifier: MIT
// Tests of J0, Y0 in modulus-phase form (src/solvers/airy/airy_bessel_phase.cpp): the two
// branches (Boost below the threshold, Hankel's expansion above) reproduce J0 and Y0, agree with
// each other, keep the phase continuous and increasing, and stay finite for any argument.
#include "solvers/airy/airy_bessel_phase.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <limits>

#include "catena/core/types.hpp"

namespace catena::internal {
namespace {

// J0 and Y0 rebuilt from the form: M = scaled_modulus / sqrt(z), theta = z - pi/4 + phi.
void expect_reproduces_boost(double z, double tolerance) {
  const BesselZeroPhase form = bessel_zero_phase(z);
  const double modulus = form.scaled_modulus / std::sqrt(z);
  const double theta = z - 0.25 * kPi + form.phase_offset;
  const double j0 = boost::math::cyl_bessel_j(0, z);
  const double y0 = boost::math::cyl_neumann(0, z);
  // Absolute in units of M: near a zero of J0 or Y0 only the absolute error is meaningful.
  EXPECT_NEAR(modulus * std::cos(theta), j0, tolerance * modulus) << "z = " << z;
  EXPECT_NEAR(modulus * std::sin(theta), y0, tolerance * modulus) << "z = " << z;
}

TEST(AiryBesselPhase, ReproducesBoostsJ0AndY0OnBothSidesOfTheThreshold) {
  // Below the threshold the form is Boost's own values (rounding only); above it Hankel's
  // expansion, checked against Boost where the rounding of theta ~ z still allows (z <= 200).
  for (double z = 0.001; z < kBesselHankelThreshold; z *= 1.1) expect_reproduces_boost(z, 1e-14);
  for (double z = kBesselHankelThreshold; z <= 200.0; z += 0.37) expect_reproduces_boost(z, 1e-13);
}

TEST(AiryBesselPhase, BranchesMeetAtTheThreshold) {
  const double below = std::nextafter(kBesselHankelThreshold, 0.0);
  const BesselZeroPhase left = bessel_zero_phase(below);
  const BesselZeroPhase right = bessel_zero_phase(kBesselHankelThreshold);
  EXPECT_NEAR(left.phase_offset, right.phase_offset, 1e-14);
  EXPECT_NEAR(left.scaled_modulus, right.scaled_modulus, 1e-14);
}

TEST(AiryBesselPhase, PhaseOffsetRisesFromMinusQuarterPiToZero) {
  // theta' = 2 / (pi z M^2) > 1: phi increases, from -pi/4 at z = 0 to 0 like -1/(8 z).
  double previous = -0.25 * kPi;
  for (double z = 1e-6; z < 1e6; z *= 1.05) {
    const double offset = bessel_zero_phase(z).phase_offset;
    EXPECT_GT(offset, previous) << "z = " << z;
    EXPECT_LT(offset, 0.0) << "z = " << z;
    previous = offset;
  }
  EXPECT_NEAR(bessel_zero_phase(1e6).phase_offset, -1.0 / 8e6, 1e-18);
}

TEST(AiryBesselPhase, ExtremeArgumentsStayFinite) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double z : {0.0, 1e-300, 1e-12, 1e12, 1e300, std::numeric_limits<double>::max(), inf}) {
    const BesselZeroPhase form = bessel_zero_phase(z);
    EXPECT_TRUE(std::isfinite(form.phase_offset)) << "z = " << z;
    EXPECT_TRUE(std::isfinite(form.scaled_modulus)) << "z = " << z;
    EXPECT_GE(form.phase_offset, -0.25 * kPi) << "z = " << z;
    EXPECT_LE(form.phase_offset, 0.0) << "z = " << z;
  }
  EXPECT_EQ(bessel_zero_phase(inf).phase_offset, 0.0);
  EXPECT_DOUBLE_EQ(bessel_zero_phase(inf).scaled_modulus, std::sqrt(2.0 / kPi));
  EXPECT_DOUBLE_EQ(bessel_zero_phase(0.0).phase_offset, -0.25 * kPi);
}

}  // namespace
}  // namespace catena::internal
