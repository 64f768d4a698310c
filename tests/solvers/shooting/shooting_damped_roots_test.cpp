// SPDX-License-Identifier: MIT
// Tests of the damped root tools (shooting_damped_roots.hpp) on polynomials with known roots:
// the argument-principle count of a rectangle, Muller's method, the secant polish, the homotopy
// of lambda^2 + t alpha lambda + w0^2 (roots -t alpha/2 +- i sqrt(w0^2 - t^2 alpha^2/4), real
// beyond t alpha = 2 w0) and the real roots on the negative axis.
#include "solvers/shooting/shooting_damped_roots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

namespace catena::internal {
namespace {

using Complex = std::complex<double>;

// D(lambda) = prod (lambda - r) over `roots` (with their conjugates when `conjugate_pairs`), on
// a log scale that moves with lambda (as the shots' does): the tools must not depend on it.
DampedFunction polynomial(std::vector<Complex> roots, bool conjugate_pairs) {
  if (conjugate_pairs) {
    const std::size_t n = roots.size();
    for (std::size_t j = 0; j < n; ++j) {
      if (roots[j].imag() != 0.0) roots.push_back(std::conj(roots[j]));
    }
  }
  return [roots](Complex lambda, double) {
    Complex value = 1.0;
    for (const Complex& r : roots) value *= lambda - r;
    const double scale = std::abs(lambda);
    return DampedValue{value * std::exp(-scale), scale};
  };
}

TEST(ShootingDampedRoots, ArgumentPrincipleCountsTheRectangle) {
  const DampedFunction f = polynomial({{-0.1, 1.0}, {-0.2, 2.0}, {-0.5, 0.0}, {-3.0, 0.5}}, true);
  // -delta_max = -1: the pair at -3 +- 0.5i is outside; top 2.5 holds both pairs, 1.5 one.
  RootCount all = count_roots(f, 0.1, 1.0, 2.5, 1.0);
  ASSERT_TRUE(all.ok) << all.reason;
  EXPECT_EQ(all.roots, 5);
  RootCount lower = count_roots(f, 0.1, 1.0, 1.5, 1.0);
  ASSERT_TRUE(lower.ok) << lower.reason;
  EXPECT_EQ(lower.roots, 3);
  RootCount wide = count_roots(f, 0.1, 4.0, 2.5, 1.0);
  ASSERT_TRUE(wide.ok) << wide.reason;
  EXPECT_EQ(wide.roots, 7);
}

TEST(ShootingDampedRoots, MullerAndSecantConvergeToAComplexRoot) {
  const Complex root(-0.1, 1.0);
  const DampedFunction f = polynomial({root, {-0.2, 2.0}}, true);
  const MullerResult m = muller_root(f, Complex(0.0, 1.0), 1e-3, 1e-12, 1.0, 0.5);
  ASSERT_TRUE(m.converged);
  EXPECT_LT(std::abs(m.root - root), 1e-11);
  const MullerResult s = secant_polish(f, root + 1e-4, m.slope, m.slope_log_scale, 1e-13, 1.0);
  ASSERT_TRUE(s.converged);
  EXPECT_LT(std::abs(s.root - root), 1e-12);
}

// lambda^2 + t alpha lambda + w0^2 with its damping scale t.
struct Oscillator {
  double alpha = 0.0, w0 = 1.0, t = 0.0;
  DampedFunction function() {
    return [this](Complex lambda, double) {
      return DampedValue{lambda * lambda + t * alpha * lambda + w0 * w0, 0.0};
    };
  }
};

TEST(ShootingDampedRoots, HomotopyFollowsTheDampedOscillator) {
  Oscillator oscillator{0.4, 1.0};
  const ContinuedRoot c = continue_root(oscillator.function(), [&](double t) { oscillator.t = t; },
                                        Complex(0.0, 1.0), 1.0, {});
  ASSERT_TRUE(c.ok) << c.reason;
  EXPECT_FALSE(c.went_real);
  EXPECT_LT(std::abs(c.root - Complex(-0.2, std::sqrt(1.0 - 0.04))), 1e-10);
}

TEST(ShootingDampedRoots, HomotopyStopsWhereTheRootBecomesReal) {
  Oscillator oscillator{3.0, 1.0};
  const ContinuedRoot c = continue_root(oscillator.function(), [&](double t) { oscillator.t = t; },
                                        Complex(0.0, 1.0), 1.0, {});
  ASSERT_TRUE(c.ok) << c.reason;
  EXPECT_TRUE(c.went_real);
}

TEST(ShootingDampedRoots, RealRootsOnTheNegativeAxis) {
  const DampedFunction f = polynomial({{-0.3, 0.0}, {-2.0, 0.0}, {-0.1, 1.0}}, true);
  const std::vector<double> roots = real_roots(f, 2.5, 64, 1e-12, 1.0);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], -0.3, 1e-11);
  EXPECT_NEAR(roots[1], -2.0, 1e-11);
}

}  // namespace
}  // namespace catena::internal
