// SPDX-License-Identifier: MIT
// Tests of the out-of-plane string of linear tension (src/solvers/airy/airy_tension_string.cpp):
// the uniform-string limit, the roots against the plain Bessel determinant and against an
// independent Runge-Kutta integration of (P v')' + M omega^2 v = 0, the count, the shapes' zeros,
// orientation, extreme arguments and the min-max bound.
#include "solvers/airy/airy_tension_string.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

constexpr int kBits = 52;

TensionString string_of(double p_a, double p_b, double length = 2.0, double mass = 3.0) {
  return TensionString{length, mass, p_a, p_b};
}

Vector stations(double length, int count) { return Vector::LinSpaced(count, 0.0, length); }

// Sign changes of v strictly inside the cable (end values excluded).
int interior_zeros(const Vector& v) {
  int zeros = 0;
  for (Index j = 2; j + 1 < v.size(); ++j) zeros += (v[j] > 0.0) != (v[j - 1] > 0.0);
  return zeros;
}

// v(L) of (P v')' + M omega^2 v = 0, v(0) = 0, P v'(0) = 1, by classical Runge-Kutta in (v, P v').
double runge_kutta_end_value(const TensionString& string, double omega, int steps) {
  const double h = string.length / steps;
  const double slope = (string.stiffness_b - string.stiffness_a) / string.length;
  auto rate = [&](double s, double v, double force) {
    return std::pair<double, double>{force / (string.stiffness_a + slope * s),
                                     -string.normal_mass * omega * omega * v};
  };
  double v = 0.0, force = 1.0;
  for (int i = 0; i < steps; ++i) {
    const double s = i * h;
    const auto k1 = rate(s, v, force);
    const auto k2 = rate(s + 0.5 * h, v + 0.5 * h * k1.first, force + 0.5 * h * k1.second);
    const auto k3 = rate(s + 0.5 * h, v + 0.5 * h * k2.first, force + 0.5 * h * k2.second);
    const auto k4 = rate(s + h, v + h * k3.first, force + h * k3.second);
    v += h / 6.0 * (k1.first + 2.0 * k2.first + 2.0 * k3.first + k4.first);
    force += h / 6.0 * (k1.second + 2.0 * k2.second + 2.0 * k3.second + k4.second);
  }
  return v;
}

TEST(AiryTensionString, UniformTensionIsTheSineStringExactly) {
  // P' = 0: z = inf, the Bessel phases vanish and omega_n = n pi sqrt(P/M) / L, v = sin(n pi s/L).
  const TensionString string = string_of(50.0, 50.0);
  const Vector s = stations(string.length, 101);
  for (int n = 1; n <= 6; ++n) {
    const double omega = string_frequency(string, n, kBits);
    EXPECT_LE(relative_error(omega, n * kPi / string.length * std::sqrt(50.0 / 3.0)), 1e-12) << n;
    const Vector v = string_mode_shape(string, omega, s);
    const double amplitude = std::sqrt(2.0 / kPi) * std::pow(50.0, -0.25);  // sqrt(z) M(z) P^(-1/4)
    for (Index j = 0; j < s.size(); ++j) {
      EXPECT_NEAR(v[j] / amplitude, std::sin(n * kPi * s[j] / string.length), 1e-12) << n;
    }
  }
}

TEST(AiryTensionString, VanishingSlopeTendsToTheStringOfItsTravelTime) {
  // P_B = P_A (1 + d): z ~ 1/d is huge, yet no phase difference of large numbers is formed: the
  // frequencies approach n pi / tau smoothly (the Bessel correction is O(d^2)), no NaN.
  for (double d : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 1e-300}) {
    const TensionString string = string_of(50.0, 50.0 * (1.0 + d));
    const double tau = string_travel_time(string, string.length);
    for (int n = 1; n <= 4; ++n) {
      const double omega = string_frequency(string, n, kBits);
      ASSERT_TRUE(std::isfinite(omega));
      EXPECT_LE(relative_error(omega, n * kPi / tau), std::max(1e-12, d * d)) << "d " << d;
    }
  }
}

TEST(AiryTensionString, RootsAreZerosOfTheBesselDeterminantCountedInOrder) {
  // The plain determinant J0(z_A) Y0(z_B) - J0(z_B) Y0(z_A) from Boost (moderate z, where it is
  // well conditioned): the n-th root is a zero of it, and a dense scan from 0 finds exactly n
  // sign changes up to it (the n-th root is the n-th mode).
  const TensionString string = string_of(10.0, 40.0);
  const double c = 2.0 * std::sqrt(string.normal_mass) * string.length / (40.0 - 10.0);
  auto det = [&](double omega) {
    const double za = omega * c * std::sqrt(10.0), zb = omega * c * std::sqrt(40.0);
    using boost::math::cyl_bessel_j;
    using boost::math::cyl_neumann;
    return cyl_bessel_j(0, za) * cyl_neumann(0, zb) - cyl_bessel_j(0, zb) * cyl_neumann(0, za);
  };
  for (int n = 1; n <= 5; ++n) {
    const double omega = string_frequency(string, n, kBits);
    const double za = omega * c * std::sqrt(10.0);
    EXPECT_LE(std::abs(det(omega)), 1e-13 * (2.0 / kPi) / za) << n;  // M_A M_B ~ 2 / (pi z)
    int sign_changes = 0;
    double previous = det(1e-3 * omega);
    for (double w = 2e-3 * omega; w < omega * (1.0 - 1e-9); w += 1e-3 * omega) {
      const double current = det(w);
      sign_changes += (current > 0.0) != (previous > 0.0);
      previous = current;
    }
    EXPECT_EQ(sign_changes, n - 1) << n;
  }
}

TEST(AiryTensionString, FrequenciesMatchAnIndependentRungeKuttaIntegration) {
  // A steep string (P_B / P_A = 9) integrated without Bessel functions: v(L) changes sign across
  // the root, within 1e-10 relative of it.
  const TensionString string = string_of(10.0, 90.0);
  for (int n = 1; n <= 4; ++n) {
    const double omega = string_frequency(string, n, kBits);
    const double below = runge_kutta_end_value(string, omega * (1.0 - 1e-10), 20000);
    const double above = runge_kutta_end_value(string, omega * (1.0 + 1e-10), 20000);
    EXPECT_LT(below * above, 0.0) << n;
  }
}

TEST(AiryTensionString, ModeNHasNMinusOneInteriorZerosAndFixedEnds) {
  for (const TensionString& string :
       {string_of(10.0, 90.0), string_of(90.0, 10.0), string_of(5.0, 5.0001)}) {
    const Vector s = stations(string.length, 401);
    for (int n = 1; n <= 6; ++n) {
      const Vector v = string_mode_shape(string, string_frequency(string, n, kBits), s);
      const double scale = v.cwiseAbs().maxCoeff();
      EXPECT_EQ(v[0], 0.0);
      EXPECT_LE(std::abs(v[s.size() - 1]) / scale, 1e-12) << n;
      EXPECT_EQ(interior_zeros(v), n - 1) << n;
    }
  }
}

TEST(AiryTensionString, FallingTensionGivesTheSameFrequenciesAndMirroredShapes) {
  const TensionString rising = string_of(10.0, 90.0);
  const TensionString falling = string_of(90.0, 10.0);
  const Vector s = stations(rising.length, 201);
  for (int n = 1; n <= 4; ++n) {
    const double omega = string_frequency(rising, n, kBits);
    EXPECT_LE(relative_error(string_frequency(falling, n, kBits), omega), 1e-14) << n;
    const Vector up = string_mode_shape(rising, omega, s);
    const Vector down = string_mode_shape(falling, omega, s);
    const double ratio = down[1] / up[s.size() - 2];  // v_down(s) = ratio v_up(L - s)
    for (Index j = 0; j < s.size(); ++j) {
      EXPECT_NEAR(down[j], ratio * up[s.size() - 1 - j], 1e-10 * up.cwiseAbs().maxCoeff()) << n;
    }
  }
}

TEST(AiryTensionString, ExtremeArgumentsGiveNoNaN) {
  // Tiny and huge Bessel arguments: a tension ratio of 1e8 (z_A ~ 1e-4 z_B) and a high mode.
  for (const TensionString& string :
       {string_of(1e-6, 1e2), string_of(1e2, 1e-6), string_of(1.0, 1.0 + 1e-13)}) {
    const Vector s = stations(string.length, 51);
    for (int n : {1, 2, 500}) {
      const double omega = string_frequency(string, n, kBits);
      ASSERT_TRUE(std::isfinite(omega) && omega > 0.0);
      EXPECT_TRUE(string_mode_shape(string, omega, s).allFinite()) << n;
    }
  }
}

TEST(AiryTensionString, FitHalvesTheSecantsDeviationAndBoundsIt) {
  // T is convex in s (T'' = W0^2 H^2 / T^3), so P lies below its secant by up to about
  // T'' L^2 / (8 T) = eps^2 cos^2(phi) / 8; the fit lowers the secant by half of that, leaving
  // +-eps^2 cos^2(phi) / 16, and every sampled deviation lies within the returned bound.
  const auto s = catena::testing::prepare(make_taut_inclined_problem(0.2, 30.0, 50.0, 1.0));
  const TensionString secant = secant_tension_string(s.statics);
  EXPECT_EQ(secant.stiffness_a, outofplane_stiffness(s.statics, 0.0));
  EXPECT_EQ(secant.stiffness_b, outofplane_stiffness(s.statics, s.problem.cable.length_m));
  const FittedTensionString fitted = fit_tension_string(s.statics);
  const double expected = 0.2 * 0.2 * 0.75 / 16.0;
  EXPECT_NEAR(fitted.deviation, expected, 0.1 * expected);
  EXPECT_NEAR(fitted.string.stiffness_b / fitted.string.stiffness_a,
              secant.stiffness_b / secant.stiffness_a, 1e-15);
  EXPECT_LT(fitted.string.stiffness_a, secant.stiffness_a);
  const double length = s.problem.cable.length_m;
  double largest = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double x = length * i / 1000.0;
    const double linear = fitted.string.stiffness_a +
                          (fitted.string.stiffness_b - fitted.string.stiffness_a) * i / 1000.0;
    largest = std::max(largest, std::abs(outofplane_stiffness(s.statics, x) / linear - 1.0));
  }
  EXPECT_LE(largest, fitted.deviation);
  EXPECT_GE(largest, fitted.deviation / 1.02);
}

TEST(AiryTensionString, MinMaxBound) {
  EXPECT_NEAR(linear_tension_error_bound(1e-4), 0.5e-4, 1e-8);
  EXPECT_EQ(linear_tension_error_bound(0.0), 0.0);
  EXPECT_TRUE(std::isinf(linear_tension_error_bound(1.0)));
}

}  // namespace
}  // namespace catena::internal
