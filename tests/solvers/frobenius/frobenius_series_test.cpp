// SPDX-License-Identifier: MIT
// Tests of the general Frobenius engine on ODEs with known series: Airy (ordinary point) and
// Bessel (regular singular point, roots differing by an integer, and the logarithmic case).
#include "solvers/frobenius/frobenius_series.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/airy.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/bessel_prime.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

#include "solvers/frobenius/frobenius_catenary.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {
using catena::testing::relative_error;

// y'' - x y = 0
PolynomialOde<double> airy_ode() { return PolynomialOde<double>{{{0.0, -1.0}, {}, {1.0}}}; }

// x^2 y'' + x y' + (x^2 - nu^2) y = 0
template <class Real>
PolynomialOde<Real> bessel_ode(Real nu) {
  return PolynomialOde<Real>{
      {{-nu * nu, Real(0), Real(1)}, {Real(0), Real(1)}, {Real(0), Real(0), Real(1)}}};
}

TEST(FrobeniusSeriesTest, AiryOrdinaryPointRootsAreZeroAndOne) {
  const auto roots = indicial_roots(airy_ode());
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_DOUBLE_EQ(roots[0], 0.0);
  EXPECT_DOUBLE_EQ(roots[1], 1.0);
}

TEST(FrobeniusSeriesTest, AiryFunctionsFromTheGeneratedRecurrence) {
  const ShiftTable<double> table(airy_ode());
  const auto f = frobenius_series(table, 0.0, 80);  // 1 + x^3/6 + ...
  const auto g = frobenius_series(table, 1.0, 80);  // x + x^4/12 + ...
  EXPECT_DOUBLE_EQ(f.a[3], 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(f.a[1], 0.0);
  EXPECT_DOUBLE_EQ(g.a[3], 1.0 / 12.0);
  const double ai0 = boost::math::airy_ai(0.0), aip0 = boost::math::airy_ai_prime(0.0);
  const double bi0 = boost::math::airy_bi(0.0), bip0 = boost::math::airy_bi_prime(0.0);
  for (double x : {-3.0, -1.2, 0.0, 0.4, 1.0, 2.0}) {
    const auto fv = evaluate_series(f, x, 1, 0.5);
    const auto gv = evaluate_series(g, x, 1, 0.5);
    const double ai = ai0 * fv.derivative[0] + aip0 * gv.derivative[0];
    const double bi = bi0 * fv.derivative[0] + bip0 * gv.derivative[0];
    const double aip = ai0 * fv.derivative[1] + aip0 * gv.derivative[1];
    EXPECT_LT(std::abs(ai - boost::math::airy_ai(x)), 1e-14 * std::max(1.0, std::abs(ai))) << x;
    EXPECT_LT(std::abs(bi - boost::math::airy_bi(x)), 1e-14 * std::max(1.0, std::abs(bi))) << x;
    EXPECT_LT(std::abs(aip - boost::math::airy_ai_prime(x)), 1e-14 * std::max(1.0, std::abs(aip)))
        << x;
  }
}

TEST(FrobeniusSeriesTest, TaylorShiftGivesTheSameAiryAtAnotherCentre) {
  // Expand about x = 2 (t = x - 2): the shifted ODE is y'' - (t + 2) y = 0.
  const auto shifted = airy_ode().shifted(2.0);
  ASSERT_EQ(shifted.p[0].size(), 2u);
  EXPECT_DOUBLE_EQ(shifted.p[0][0], -2.0);
  EXPECT_DOUBLE_EQ(shifted.p[0][1], -1.0);
  const ShiftTable<double> table(shifted);
  const auto b0 = frobenius_series(table, 0.0, 60);
  const auto b1 = frobenius_series(table, 1.0, 60);
  const double y0 = boost::math::airy_ai(2.0), y1 = boost::math::airy_ai_prime(2.0);
  for (double x : {1.3, 2.0, 2.9}) {
    const double value = y0 * evaluate_series(b0, x - 2.0, 0, 0.5).derivative[0] +
                         y1 * evaluate_series(b1, x - 2.0, 0, 0.5).derivative[0];
    EXPECT_LT(relative_error(value, boost::math::airy_ai(x)), 1e-14) << x;
  }
}

TEST(FrobeniusSeriesTest, BesselIndicialRootsAndSeries) {
  for (double nu : {1.0 / 3.0, 0.5, 2.5}) {
    const auto ode = bessel_ode(nu);
    const auto roots = indicial_roots(ode);
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0], -nu, 1e-12);
    EXPECT_NEAR(roots[1], nu, 1e-12);
    const ShiftTable<double> table(ode);
    const auto series = frobenius_series(table, nu, 60);
    const double norm = 1.0 / (std::pow(2.0, nu) * std::tgamma(nu + 1.0));
    for (double x : {0.1, 1.0, 3.0, 6.0}) {
      const auto v = evaluate_series(series, x, 1, 0.5);
      EXPECT_LT(std::abs(norm * v.derivative[0] - boost::math::cyl_bessel_j(nu, x)), 1e-14)
          << nu << " " << x;
      EXPECT_LT(std::abs(norm * v.derivative[1] - boost::math::cyl_bessel_j_prime(nu, x)), 1e-14)
          << nu << " " << x;
    }
    // The smaller root: J_{-nu}, including nu = 1/2 and 5/2 (roots differ by an integer, no log).
    const auto minus = frobenius_series(table, -nu, 60);
    const double norm_minus = 1.0 / (std::pow(2.0, -nu) * std::tgamma(1.0 - nu));
    for (double x : {0.5, 2.0, 5.0}) {
      const double value = norm_minus * evaluate_series(minus, x, 0, 0.5).derivative[0];
      EXPECT_LT(std::abs(value - boost::math::cyl_bessel_j(-nu, x)),
                1e-13 * std::max(1.0, std::abs(value)))
          << nu << " " << x;
    }
  }
}

TEST(FrobeniusSeriesTest, BesselIntegerOrderSmallerRootIsReportedAsLogarithmic) {
  const ShiftTable<double> table(bessel_ode(1.0));
  EXPECT_THROW(frobenius_series(table, -1.0, 20), std::domain_error);
  const auto j1 = frobenius_series(table, 1.0, 60);
  EXPECT_LT(std::abs(0.5 * evaluate_series(j1, 2.0, 0, 0.5).derivative[0] -
                     boost::math::cyl_bessel_j(1.0, 2.0)),
            1e-15);
}

TEST(FrobeniusSeriesTest, QuadPrecisionBesselCoefficientsAreExact) {
  // a_{2k} = (-1)^k / (4^k k! (nu+1)(nu+2)...(nu+k)), computed independently in quad precision.
  using Quad = boost::multiprecision::cpp_bin_float_quad;
  const Quad nu = Quad(1) / 3;
  const ShiftTable<Quad> table(bessel_ode<Quad>(nu));
  const auto series = frobenius_series(table, nu, 40);
  Quad expected = 1;
  for (int k = 0; 2 * k < 40; ++k) {
    if (k > 0) expected *= Quad(-1) / (Quad(4) * k * (nu + k));
    EXPECT_LT(static_cast<double>(abs(series.a[2 * k] - expected) / abs(expected)), 1e-31) << k;
    if (2 * k + 1 < 40) {
      EXPECT_EQ(series.a[2 * k + 1], Quad(0));
    }
  }
}

TEST(FrobeniusSeriesTest, AdaptiveSeriesStopsAtTheTolerance) {
  const ShiftTable<double> table(airy_ode());
  bool converged = false;
  const auto s = adaptive_series(table, 0.0, 1.0, 1e-16, 400, converged);
  EXPECT_TRUE(converged);
  EXPECT_LT(s.a.size(), 60u);
  const auto v = evaluate_series(s, 1.0, 0, 0.5);
  const double f = v.derivative[0];
  EXPECT_GT(f, 1.0);
}

TEST(FrobeniusSeriesTest, AnOrdinaryPointCloseToASingularOneIsNotAResonance) {
  // Regression: the forced response's basis at high Omega starts its second expansion at
  // eta ~ 1e-8, where the whole leading coefficient eta^2 (1+eta)(2+eta)^2 is ~1e-16. The
  // recurrence's lead there is small but not zero; judged against an absolute 1e-9 it was taken
  // for a resonance and the series threw "logarithmic solution".
  const PolynomialOde<double> ode = catenary_ode<double>(true, 1e8, 1.0).shifted(1e-8);
  const ShiftTable<double> table(ode);
  bool converged = false;
  // The unit solution of exponent 3 (as the basis builds it): its next coefficient has lead Q(4).
  const auto series = adaptive_series(table, 3.0, 1e-9, 1e-15, 400, converged);
  EXPECT_TRUE(converged);
  ASSERT_GE(series.a.size(), 2u);
  EXPECT_TRUE(std::isfinite(series.a[1]));
  EXPECT_NE(series.a[1], 0.0);
  // True resonances (the indicial roots 0..3 of an ordinary point) are still recognised.
  EXPECT_TRUE(is_resonant_index(table, table.q(0, 2.0), 2.0));
  EXPECT_FALSE(is_resonant_index(table, table.q(0, 4.0), 4.0));
}

TEST(FrobeniusSeriesTest, ValuesAloneEqualTheTrackedValues) {
  // SeriesErrors::Skipped leaves out the largest terms and the truncation estimate only: the
  // values are the same sums, bit for bit, and the error fields stay 0.
  const ShiftTable<long double> table(catenary_ode<long double>(true, 30.0L, 1.0L));
  bool converged = false;
  const auto s = adaptive_series(table, 0.5L, 0.8L, 1e-18, 400, converged);
  ASSERT_TRUE(converged);
  for (const long double x : {0.05L, 0.1L, 0.45L, 0.79L}) {
    const auto tracked = evaluate_series(s, x, 3, 0.5L);
    const auto values = evaluate_series(s, x, 3, 0.5L, SeriesErrors::Skipped);
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_EQ(values.derivative[k], tracked.derivative[k])
          << "x = " << static_cast<double>(x) << ", k = " << k;
      EXPECT_EQ(values.largest_term[k], 0.0L);
      EXPECT_EQ(values.truncation[k], 0.0L);
    }
    EXPECT_GT(tracked.largest_term[0], 0.0L);
  }
  EXPECT_THROW(evaluate_series(s, 0.1L, 4, 0.5L), std::domain_error);
}

}  // namespace
}  // namespace catena::internal
