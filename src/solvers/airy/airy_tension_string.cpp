// SPDX-License-Identifier: MIT
// The out-of-plane string of linear tension, solved by Bessel functions of order zero (see
// airy_tension_string.hpp and docs/explanation/methods/airy.md).
#include "solvers/airy/airy_tension_string.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>

#include "solvers/airy/airy_bessel_phase.hpp"

namespace catena::internal {
namespace {

double slope(const TensionString& string) {
  return (string.stiffness_b - string.stiffness_a) / string.length;
}

double linear_stiffness(const TensionString& string, double s) {
  return string.stiffness_a + slope(string) * s;
}

// z / omega = 2 sqrt(M P) / |P'| at stiffness P: +inf for a uniform string.
double bessel_scale(const TensionString& string, double stiffness) {
  const double magnitude = std::abs(slope(string));
  if (magnitude == 0.0) return std::numeric_limits<double>::infinity();
  return 2.0 * std::sqrt(string.normal_mass * stiffness) / magnitude;
}

// phi(z) at z = omega c; omega c = inf for c = inf (omega > 0).
double phase_offset(double omega, double scale) {
  return bessel_zero_phase(omega * scale).phase_offset;
}

}  // namespace

double outofplane_stiffness(const StaticSolution& statics, double s) {
  return statics.tension_n(s) / (1.0 + statics.strain(s));
}

TensionString secant_tension_string(const StaticSolution& statics) {
  const CableProperties& cable = statics.cable();
  TensionString string;
  string.length = cable.length_m;
  string.normal_mass = cable.normal_mass_kg_per_m();
  string.stiffness_a = outofplane_stiffness(statics, 0.0);
  string.stiffness_b = outofplane_stiffness(statics, cable.length_m);
  return string;
}

FittedTensionString fit_tension_string(const StaticSolution& statics, int samples) {
  FittedTensionString fitted{secant_tension_string(statics), 0.0};
  TensionString& string = fitted.string;
  double low = 0.0;  // the ends lie on the secant: the range includes 0
  double high = 0.0;
  for (int i = 1; i < samples; ++i) {
    const double s = string.length * i / samples;
    const double deviation = outofplane_stiffness(statics, s) / linear_stiffness(string, s) - 1.0;
    low = std::min(low, deviation);
    high = std::max(high, deviation);
  }
  // P / ((1 + c) P_sec) - 1 = (d - c) / (1 + c) spans +-(high - low) / (2 (1 + c)).
  const double scale = 1.0 + 0.5 * (low + high);
  string.stiffness_a *= scale;
  string.stiffness_b *= scale;
  fitted.deviation = 1.01 * 0.5 * (high - low) / scale;
  return fitted;
}

double string_travel_time(const TensionString& string, double s) {
  // int_0^s sqrt(M / (P_A + P' x)) dx = 2 sqrt(M) (sqrt(P(s)) - sqrt(P_A)) / P'
  //                                   = 2 sqrt(M) s / (sqrt(P(s)) + sqrt(P_A)).
  return 2.0 * std::sqrt(string.normal_mass) * s /
         (std::sqrt(linear_stiffness(string, s)) + std::sqrt(string.stiffness_a));
}

double string_phase_residual(const TensionString& string, double omega, int n) {
  const double low = std::min(string.stiffness_a, string.stiffness_b);
  const double high = std::max(string.stiffness_a, string.stiffness_b);
  const double tau = string_travel_time(string, string.length);
  return omega * tau + phase_offset(omega, bessel_scale(string, high)) -
         phase_offset(omega, bessel_scale(string, low)) - n * kPi;
}

double string_frequency(const TensionString& string, int n, int tolerance_bits) {
  // phi rises from -pi/4 to 0, so phi(z_hi) - phi(z_lo) lies in [0, pi/4): the root has
  // omega tau in ((n - 1/4) pi, n pi].
  const double tau = string_travel_time(string, string.length);
  const double low = (n - 0.25) * kPi / tau;
  const double high = n * kPi / tau;
  auto residual = [&](double omega) { return string_phase_residual(string, omega, n); };
  const double at_high = residual(high);
  if (at_high <= 0.0) return high;  // uniform string: the bracket's end is the root
  boost::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      residual, low, high, residual(low), at_high,
      boost::math::tools::eps_tolerance<double>(tolerance_bits), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

Vector string_mode_shape(const TensionString& string, double omega, const Vector& stations_m) {
  // theta(z(s)) - theta(z_A) = sign(P') omega tau(s) + phi(z(s)) - phi(z_A).
  const double direction = slope(string) < 0.0 ? -1.0 : 1.0;
  const double offset_a = phase_offset(omega, bessel_scale(string, string.stiffness_a));
  Vector v(stations_m.size());
  for (Index j = 0; j < stations_m.size(); ++j) {
    const double s = stations_m[j];
    const double stiffness = linear_stiffness(string, s);
    const BesselZeroPhase bessel = bessel_zero_phase(omega * bessel_scale(string, stiffness));
    const double phase =
        direction * omega * string_travel_time(string, s) + bessel.phase_offset - offset_a;
    v[j] = std::pow(stiffness, -0.25) * bessel.scaled_modulus * std::sin(phase);
  }
  return v;
}

double linear_tension_error_bound(double delta) {
  if (!(delta < 1.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / std::sqrt(1.0 - delta) - 1.0;
}

}  // namespace catena::internal
