// Scaled Airy functions: Boost.Math below kAirySeriesThreshold, the large-argument asymptotic
// series above it (DLMF 9.7.5-9.7.8, coefficients u_k, v_k of DLMF 9.7.2). Bi's exponentially
// small recessive part (relative e^{-2 zeta} < 1e-72 at the threshold) is dropped.
#include "solvers/internal/airy_functions.hpp"

#include <boost/math/special_functions/airy.hpp>
#include <cmath>

namespace catena::internal {

ScaledAiry scaled_airy(double x) {
  ScaledAiry out;
  if (x <= 0.0) {
    out.ai = boost::math::airy_ai(x);
    out.ai_prime = boost::math::airy_ai_prime(x);
    out.bi = boost::math::airy_bi(x);
    out.bi_prime = boost::math::airy_bi_prime(x);
    return out;
  }
  const double root = std::sqrt(x);
  out.zeta = 2.0 / 3.0 * x * root;
  if (x <= kAirySeriesThreshold) {
    const double grow = std::exp(out.zeta);
    const double decay = 1.0 / grow;
    out.ai = boost::math::airy_ai(x) * grow;
    out.ai_prime = boost::math::airy_ai_prime(x) * grow;
    out.bi = boost::math::airy_bi(x) * decay;
    out.bi_prime = boost::math::airy_bi_prime(x) * decay;
    return out;
  }
  // Sums over k of (+-1)^k u_k / zeta^k and (+-1)^k v_k / zeta^k; the terms decrease until
  // k ~ 2 zeta > 166, far beyond the 1e-17 cut.
  double u = 1.0;
  double power = 1.0;
  double sum_u_plus = 1.0, sum_u_minus = 1.0, sum_v_plus = 1.0, sum_v_minus = 1.0;
  for (int k = 1; k < 60; ++k) {
    u *= (6.0 * k - 5.0) * (6.0 * k - 3.0) * (6.0 * k - 1.0) / ((2.0 * k - 1.0) * 216.0 * k);
    const double v = -(6.0 * k + 1.0) / (6.0 * k - 1.0) * u;
    power /= out.zeta;
    const double sign = (k % 2) ? -1.0 : 1.0;
    sum_u_plus += u * power;
    sum_u_minus += sign * u * power;
    sum_v_plus += v * power;
    sum_v_minus += sign * v * power;
    if (std::abs(u * power) < 1e-18 && std::abs(v * power) < 1e-18) break;
  }
  const double quarter = std::sqrt(root);  // x^{1/4}
  const double inv_sqrt_pi = 0.56418958354775628694807945156077259;
  out.ai = 0.5 * inv_sqrt_pi / quarter * sum_u_minus;
  out.ai_prime = -0.5 * inv_sqrt_pi * quarter * sum_v_minus;
  out.bi = inv_sqrt_pi / quarter * sum_u_plus;
  out.bi_prime = inv_sqrt_pi * quarter * sum_v_plus;
  return out;
}

}  // namespace catena::internal
