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

/// Scaled Ai, Ai', Bi, Bi' at x (any finite x).
ScaledAiry scaled_airy(double x);

}  // namespace catena::internal
