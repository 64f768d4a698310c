// SPDX-License-Identifier: MIT
// Tests of the scaled Airy functions (src/solvers/airy/airy_functions.cpp) against Boost.Math's
// unscaled Ai, Bi, Ai', Bi' and the Wronskian Ai Bi' - Ai' Bi = 1/pi, up to arguments 1e6.
#include "solvers/airy/airy_functions.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/airy.hpp>
#include <cmath>

#include "catena/core/types.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;

TEST(ScaledAiry, MatchesBoostAcrossTheSeriesThreshold) {
  // Boost's values are still representable up to x = 40 (Ai ~ 1e-74): compare the series branch
  // with them. Boost's own accuracy is a few ulp; 1e-13 allows for the exp() of zeta ~ 170.
  constexpr double kRelTol = 1e-13;
  for (double x :
       {internal::kAirySeriesThreshold - 1.0, internal::kAirySeriesThreshold + 1e-3, 30.0, 40.0}) {
    const internal::ScaledAiry a = internal::scaled_airy(x);
    const double grow = std::exp(a.zeta);
    EXPECT_LE(relative_error(a.ai / grow, boost::math::airy_ai(x)), kRelTol) << x;
    EXPECT_LE(relative_error(a.ai_prime / grow, boost::math::airy_ai_prime(x)), kRelTol) << x;
    EXPECT_LE(relative_error(a.bi * grow, boost::math::airy_bi(x)), kRelTol) << x;
    EXPECT_LE(relative_error(a.bi_prime * grow, boost::math::airy_bi_prime(x)), kRelTol) << x;
  }
}

TEST(ScaledAiry, MaclaurinFastPathMatchesBoost) {
  // Error measured against the size of the functions (their envelope |x|^(-1/4)/sqrt(pi) and
  // |x|^(1/4)/sqrt(pi) for the derivatives, at least 1), not pointwise near the zeros of Ai.
  constexpr double kTol = 2e-13;
  for (double x = internal::kAiryMaclaurinLow; x <= internal::kAiryMaclaurinHigh; x += 0.01) {
    const internal::ScaledAiry fast = internal::scaled_airy(x);
    const internal::ScaledAiry ref = internal::scaled_airy_boost(x);
    const double size = std::max(1.0, std::pow(std::abs(x), 0.25));
    EXPECT_NEAR(fast.ai, ref.ai, kTol * size) << x;
    EXPECT_NEAR(fast.bi, ref.bi, kTol * size) << x;
    EXPECT_NEAR(fast.ai_prime, ref.ai_prime, kTol * size) << x;
    EXPECT_NEAR(fast.bi_prime, ref.bi_prime, kTol * size) << x;
    EXPECT_EQ(fast.zeta, ref.zeta);
  }
}

TEST(ScaledAiry, TaylorFastPathMatchesBoost) {
  // Nodes every 0.5 from Boost; Taylor to |h| <= 0.25. Same envelope-relative measure.
  constexpr double kTol = 2e-13;
  for (double x = internal::kAiryTaylorLow; x <= internal::kAirySeriesThreshold; x += 0.0137) {
    const internal::ScaledAiry fast = internal::scaled_airy(x);
    const internal::ScaledAiry ref = internal::scaled_airy_boost(x);
    const double size = std::max(1.0, std::pow(std::abs(x), 0.25));
    EXPECT_NEAR(fast.ai, ref.ai, kTol * size) << x;
    EXPECT_NEAR(fast.bi, ref.bi, kTol * size) << x;
    EXPECT_NEAR(fast.ai_prime, ref.ai_prime, kTol * size) << x;
    EXPECT_NEAR(fast.bi_prime, ref.bi_prime, kTol * size) << x;
  }
}

TEST(ScaledAiry, WronskianHoldsWhereTheUnscaledFunctionsOverflow) {
  // Ai Bi' - Ai' Bi = 1/pi: the exponents cancel, so the scaled values must satisfy it exactly.
  for (double x : {-50.0, -3.0, 0.0, 0.5, 5.0, 24.0, 26.0, 100.0, 1e3, 1e4, 1e6}) {
    const internal::ScaledAiry a = internal::scaled_airy(x);
    const double wronskian = a.ai * a.bi_prime - a.ai_prime * a.bi;
    EXPECT_LE(relative_error(wronskian, 1.0 / kPi), 1e-13) << "x " << x;
  }
}

}  // namespace
}  // namespace catena
