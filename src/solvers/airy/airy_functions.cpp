// SPDX-License-Identifier: MIT
// Scaled Airy functions. Reference path (scaled_airy_boost): Boost.Math below
// kAirySeriesThreshold, the large-argument asymptotic series above it (DLMF 9.7.5-9.7.8,
// coefficients u_k, v_k of DLMF 9.7.2; Bi's recessive part, relative e^{-2 zeta} < 1e-72 at the
// threshold, is dropped). Fast path (scaled_airy): Maclaurin series near 0, and elsewhere in
// [kAiryTaylorLow, kAirySeriesThreshold] Taylor series about tabulated nodes whose values come
// from the reference path; Boost calls cost 1-3 us each, the series ~0.05 us.
#include "solvers/airy/airy_functions.hpp"

#include <algorithm>
#include <boost/math/special_functions/airy.hpp>
#include <cmath>
#include <vector>

namespace catena::internal {

namespace {

// Maclaurin series: Ai = c1 f - c2 g, Bi = sqrt(3)(c1 f + c2 g) with f = sum a_k x^{3k},
// g = sum b_k x^{3k+1}, a_k = a_{k-1} / (3k (3k-1)), b_k = b_{k-1} / (3k (3k+1)) (from y'' = x y).
ScaledAiry maclaurin_airy(double x) {
  constexpr double c1 = 0.35502805388781723926;  // Ai(0)
  constexpr double c2 = 0.25881940379280679840;  // -Ai'(0)
  constexpr double sqrt3 = 1.7320508075688772935;
  const double x3 = x * x * x;
  double a = 1.0, b = x;  // current terms of f and g
  double f = 1.0, g = x;
  double fp = 0.0, gp = 1.0;  // f', g'
  for (int k = 1; k < 60; ++k) {
    const double three_k = 3.0 * k;
    a *= x3 / (three_k * (three_k - 1.0));
    b *= x3 / (three_k * (three_k + 1.0));
    f += a;
    g += b;
    // f' term: 3k a_k x^{3k-1} = a_{k} * 3k / x; written without dividing by x.
    fp += a * three_k / (x == 0.0 ? 1.0 : x);
    gp += b * (three_k + 1.0) / (x == 0.0 ? 1.0 : x);
    if (std::abs(a) + std::abs(b) < 1e-18 * (std::abs(f) + std::abs(g))) break;
  }
  if (x == 0.0) {
    fp = 0.0;
    gp = 1.0;
  }
  ScaledAiry out;
  out.ai = c1 * f - c2 * g;
  out.bi = sqrt3 * (c1 * f + c2 * g);
  out.ai_prime = c1 * fp - c2 * gp;
  out.bi_prime = sqrt3 * (c1 * fp + c2 * gp);
  if (x > 0.0) {
    out.zeta = 2.0 / 3.0 * x * std::sqrt(x);
    const double grow = std::exp(out.zeta);
    out.ai *= grow;
    out.ai_prime *= grow;
    out.bi /= grow;
    out.bi_prime /= grow;
  }
  return out;
}

// Nodes every 0.5 on [kAiryTaylorLow, kAirySeriesThreshold] with the scaled values there, built
// once (thread-safe static initialisation).
constexpr double kNodeSpacing = 0.5;

const std::vector<ScaledAiry>& taylor_nodes() {
  static const std::vector<ScaledAiry> nodes = [] {
    std::vector<ScaledAiry> values;
    const int count = static_cast<int>((kAirySeriesThreshold - kAiryTaylorLow) / kNodeSpacing) + 1;
    for (int i = 0; i < count; ++i)
      values.push_back(scaled_airy_boost(kAiryTaylorLow + i * kNodeSpacing));
    return values;
  }();
  return nodes;
}

// Taylor series about the nearest node x0 (|h| <= 0.25) with the derivatives from y'' = x y:
// y^(n+2) = x0 y^(n) + n y^(n-1). The terms fall like (|h| sqrt|x0|)^n / n! <= 1.4^n / n!.
// The exponential scale of the node is carried to x by e^{-+(zeta(x) - zeta(x0))}.
ScaledAiry taylor_airy(double x) {
  const auto& nodes = taylor_nodes();
  const auto index = static_cast<std::size_t>(std::lround((x - kAiryTaylorLow) / kNodeSpacing));
  const ScaledAiry& node = nodes[std::min(index, nodes.size() - 1)];
  const double x0 =
      kAiryTaylorLow + static_cast<double>(std::min(index, nodes.size() - 1)) * kNodeSpacing;
  const double h = x - x0;
  // Derivatives d[n] of (scaled) Ai and Bi at x0, kept three deep for the recurrence.
  double a_prev = 0.0, a0 = node.ai, a1 = node.ai_prime;  // y^(n-1), y^(n), y^(n+1)
  double b_prev = 0.0, b0 = node.bi, b1 = node.bi_prime;
  double ai = a0, ai_prime = a1, bi = b0, bi_prime = b1;
  double power = 1.0;  // h^n / n!
  for (int n = 0; n < 60; ++n) {
    // y^(n+2) from y^(n), y^(n-1).
    const double a2 = x0 * a0 + n * a_prev;
    const double b2 = x0 * b0 + n * b_prev;
    power *= h / (n + 1);
    ai += a1 * power;
    bi += b1 * power;
    ai_prime += a2 * power;
    bi_prime += b2 * power;
    a_prev = a0;
    a0 = a1;
    a1 = a2;
    b_prev = b0;
    b0 = b1;
    b1 = b2;
    const double size = std::abs(ai) + std::abs(bi) + std::abs(ai_prime) + std::abs(bi_prime);
    if (std::abs(power) * (std::abs(a1) + std::abs(b1) + std::abs(a0) + std::abs(b0)) <
        1e-18 * size)
      break;
  }
  ScaledAiry out;
  out.zeta = x > 0.0 ? 2.0 / 3.0 * x * std::sqrt(x) : 0.0;
  const double shift = out.zeta - node.zeta;
  const double decay = std::exp(shift);  // Ai scaled by e^{+zeta}: multiply by e^{zeta - zeta0}
  const double grow = 1.0 / decay;
  out.ai = ai * decay;
  out.ai_prime = ai_prime * decay;
  out.bi = bi * grow;
  out.bi_prime = bi_prime * grow;
  return out;
}

}  // namespace

ScaledAiry scaled_airy(double x) {
  if (x >= kAiryMaclaurinLow && x <= kAiryMaclaurinHigh) return maclaurin_airy(x);
  if (x >= kAiryTaylorLow && x <= kAirySeriesThreshold) return taylor_airy(x);
  return scaled_airy_boost(x);
}

ScaledAiry scaled_airy_boost(double x) {
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
