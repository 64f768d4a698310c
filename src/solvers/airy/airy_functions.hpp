// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Airy functions with their exponential factors split off, for the `airy` solver: for x > 0,
///     Ai(x) = ai e^{-zeta},  Ai'(x) = ai_prime e^{-zeta},
///     Bi(x) = bi e^{+zeta},  Bi'(x) = bi_prime e^{+zeta},   zeta = (2/3) x^{3/2};
/// for x <= 0 (oscillatory side) zeta = 0 and the values are the functions themselves.

namespace catena::internal {

struct ScaledAiry {
  double ai = 0.0;
  double ai_prime = 0.0;
  double bi = 0.0;
  double bi_prime = 0.0;
  /// zeta = (2/3) x^{3/2} for x > 0, else 0.
  double zeta = 0.0;
};

/// Above this argument the asymptotic series is used (Boost below): at x = 25, zeta = 83 and the
/// series' terms fall below 1e-17 after 6 terms, while Boost's unscaled values (~1e+/-36) are
/// still far from overflow.
inline constexpr double kAirySeriesThreshold = 25.0;

/// On [kAiryMaclaurinLow, kAiryMaclaurinHigh] the Maclaurin series is used instead of Boost (10x
/// faster, all four functions at once): its terms peak near e^{(2/3)|x|^{3/2}}, so the rounding
/// error relative to the functions' size stays below ~1e-13 there (tested against Boost).
inline constexpr double kAiryMaclaurinLow = -5.0;
inline constexpr double kAiryMaclaurinHigh = 3.0;

/// Elsewhere on [kAiryTaylorLow, kAirySeriesThreshold]: Taylor series about nodes 0.5 apart
/// whose values come from Boost (computed once). Below kAiryTaylorLow: Boost.
inline constexpr double kAiryTaylorLow = -40.0;

/// Scaled Ai, Ai', Bi, Bi' at x (any finite x).
ScaledAiry scaled_airy(double x);

/// The same without the Maclaurin fast path: Boost.Math up to kAirySeriesThreshold, the
/// asymptotic series above it (for tests and comparison).
ScaledAiry scaled_airy_boost(double x);

}  // namespace catena::internal
