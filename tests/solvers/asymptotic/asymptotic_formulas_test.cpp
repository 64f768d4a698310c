// SPDX-License-Identifier: MIT
// Grinfogel's closed-form in-plane shapes (Grinfogel 1984; docs/reference/references.md), eqs.
// (34), (28) and (37): the fixed end s = 0, the far end at a root of eq. (21), Irvine's shapes of
// the horizontal cable (phi = 0, where both formulas reduce to them), the scaling of u with eps,
// and the mirror used for a falling chord.
#include "solvers/asymptotic/asymptotic_formulas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/solvers/asymptotic_solver.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using Formula = AsymptoticShapeFormula;

Vector stations(int n, double length_m) { return Vector::LinSpaced(n, 0.0, length_m); }

double deg(double degrees) { return degrees * kPi / 180.0; }

struct Case {
  double eps, phi_deg, lambda2;
};
const std::vector<Case> kCases = {{0.1, 30.0, 1.0},  {0.1, 30.0, 100.0},     {0.3, 60.0, 10.0},
                                  {0.01, 60.0, 1.0}, {0.3, 30.0, kInfinity}, {0.1, 0.0, 10.0}};

TEST(AsymptoticFormulas, BothShapesVanishAtTheFixedEndSEqualsZero) {
  // Eqs. (28), (34) and (37) are built with w(0) = u(0) = 0 (the near-end boundary condition), for
  // any kL, not only at the roots of eq. (21).
  for (const auto& c : kCases) {
    for (double kl : {1.3, 4.2, 9.0}) {
      for (Formula formula : {Formula::Eq34, Formula::Eq28}) {
        const auto shape = asymptotic_mode_shape(stations(11, 2.0), 2.0, kl, c.eps, deg(c.phi_deg),
                                                 c.lambda2, formula);
        const double scale = shape.w.cwiseAbs().maxCoeff();
        EXPECT_LE(std::abs(shape.w[0]), 1e-14 * scale) << c.eps << " " << c.phi_deg << " kL " << kl;
        EXPECT_EQ(shape.u[0], 0.0);
      }
    }
  }
}

TEST(AsymptoticFormulas, ZerothOrderShapeMissesTheFarEndByEqTwentyOneWithoutTheCrossOverTerm) {
  // w28(L) = -4 sin(kL/2) [cos(kL/2) (kL/2) (k^2L^2/lambda^2 - 1) + sin(kL/2)], i.e. -4 times
  // eq. (21) without its cross-over term (eq. 21 at eps = 0), for any kL. At a root of eq. (21) the
  // zeroth-order shape therefore misses w(L) = 0 by exactly -(49/16) e1^2 cos kL, e1 = eps sin phi.
  for (const auto& c : kCases) {
    const double phi = deg(c.phi_deg);
    for (double kl : {1.3, 4.2, 9.0}) {
      const auto shape =
          asymptotic_mode_shape(stations(5, 1.0), 1.0, kl, c.eps, phi, c.lambda2, Formula::Eq28);
      EXPECT_NEAR(shape.w[4], -4.0 * grinfogel_eq21(kl, 0.0, phi, c.lambda2),
                  1e-13 * shape.w.cwiseAbs().maxCoeff());
    }
    const double e1 = c.eps * std::sin(phi);
    for (double kl : grinfogel_eq21_roots(4, c.eps, phi, c.lambda2)) {
      // Enough stations to see the amplitude (kL near 4 pi has nodes at every quarter).
      const auto shape =
          asymptotic_mode_shape(stations(41, 1.0), 1.0, kl, c.eps, phi, c.lambda2, Formula::Eq28);
      EXPECT_NEAR(shape.w[40], -(49.0 / 16.0) * e1 * e1 * std::cos(kl),
                  1e-12 * shape.w.cwiseAbs().maxCoeff())
          << c.eps << " " << c.phi_deg << " kL " << kl;
    }
  }
}

TEST(AsymptoticFormulas, FirstOrderShapeMeetsTheFarEndToSecondOrderInE1) {
  // Eq. (34) is the expansion to O(e1) plus the near-cross-over O(e1^2) bracket: at a root of
  // eq. (21) the end condition w(L) = 0 holds to O(e1^2) relative to the shape's amplitude.
  for (const auto& c : kCases) {
    const double phi = deg(c.phi_deg);
    const double e1 = c.eps * std::sin(phi);
    for (double kl : grinfogel_eq21_roots(4, c.eps, phi, c.lambda2)) {
      const auto shape =
          asymptotic_mode_shape(stations(201, 1.0), 1.0, kl, c.eps, phi, c.lambda2, Formula::Eq34);
      const double amplitude = shape.w.cwiseAbs().maxCoeff();
      EXPECT_LE(std::abs(shape.w[200]), 4.0 * e1 * e1 * amplitude + 1e-12 * amplitude)
          << c.eps << " " << c.phi_deg << " kL " << kl;
    }
  }
  // ... and the miss is really second order: a tenth of eps, a hundredth of the miss.
  const auto miss = [](double eps) {
    const double phi = deg(30.0), kl = grinfogel_eq21_roots(2, eps, phi, 100.0)[1];
    const auto shape =
        asymptotic_mode_shape(stations(3, 1.0), 1.0, kl, eps, phi, 100.0, Formula::Eq34);
    return shape.w[2] / shape.w.cwiseAbs().maxCoeff();
  };
  EXPECT_NEAR(miss(0.1) / miss(0.01), 100.0, 10.0);
}

TEST(AsymptoticFormulas, HorizontalCableGivesIrvinesSymmetricShape) {
  // phi = 0: e1 = 0, eq. (34) is eq. (28), and eq. (21) is Irvine's tan(kL/2) = kL/2 - (4/lambda^2)
  // (kL/2)^3. The symmetric mode is Irvine's 1 - cos(k s) - tan(kL/2) sin(k s), times -(1 - cos
  // kL).
  for (double lambda2 : {1.0, 10.0, 100.0}) {
    const std::vector<double> roots = grinfogel_eq21_roots(4, 0.1, 0.0, lambda2);
    for (double kl : roots) {
      const double x = 0.5 * kl;
      if (std::abs(std::sin(x)) < 1e-6) continue;  // antisymmetric (kL = 2 n pi): next test
      ASSERT_NEAR(std::tan(x), x - 4.0 * x * x * x / lambda2, 1e-9 * (1.0 + std::abs(std::tan(x))));
      const Vector s = stations(41, 3.0);
      const auto w34 = asymptotic_mode_shape(s, 3.0, kl, 0.1, 0.0, lambda2, Formula::Eq34);
      const auto w28 = asymptotic_mode_shape(s, 3.0, kl, 0.1, 0.0, lambda2, Formula::Eq28);
      for (Index j = 0; j < s.size(); ++j) {
        EXPECT_EQ(w34.w[j], w28.w[j]);
        EXPECT_EQ(w34.u[j], w28.u[j]);
        const double theta = kl * s[j] / 3.0;
        const double irvine = 1.0 - std::cos(theta) - std::tan(x) * std::sin(theta);
        EXPECT_NEAR(w34.w[j], -(1.0 - std::cos(kl)) * irvine, 1e-9 * w34.w.cwiseAbs().maxCoeff())
            << "lambda^2 " << lambda2 << " kL " << kl << " s " << s[j];
      }
      // Both ends fixed, in both directions.
      EXPECT_LE(std::abs(w34.w[40]), 1e-9 * w34.w.cwiseAbs().maxCoeff());
      EXPECT_LE(std::abs(w34.u[40]), 1e-12 * w34.u.cwiseAbs().maxCoeff());
      EXPECT_DOUBLE_EQ(w34.slow_amplitude, 1.0 - std::cos(kl));
    }
  }
}

TEST(AsymptoticFormulas, HorizontalCableGivesIrvinesAntisymmetricShape) {
  // kL = 2 pi: no net stretching; w is Irvine's sin(2 pi s / L), of amplitude kL (1 -
  // k^2L^2/lambda^2).
  const double kl = 2.0 * kPi, lambda2 = 10.0;
  const Vector s = stations(33, 1.0);
  const auto shape = asymptotic_mode_shape(s, 1.0, kl, 0.2, 0.0, lambda2, Formula::Eq34);
  const double amplitude = kl * (1.0 - kl * kl / lambda2);
  for (Index j = 0; j < s.size(); ++j) {
    EXPECT_NEAR(shape.w[j], amplitude * std::sin(kl * s[j]), 1e-13 * std::abs(amplitude)) << s[j];
  }
  EXPECT_NEAR(shape.slow_amplitude, 0.0, 1e-15);
}

TEST(AsymptoticFormulas, TangentialShapeScalesWithEpsCosPhiOverKL) {
  // u = eq. (37) eps cos(phi) / kL; at phi = 0 nothing else depends on eps: w is unchanged and u
  // doubles with eps.
  const Vector s = stations(17, 1.0);
  const auto a = asymptotic_mode_shape(s, 1.0, 4.2, 0.1, 0.0, 10.0, Formula::Eq34);
  const auto b = asymptotic_mode_shape(s, 1.0, 4.2, 0.2, 0.0, 10.0, Formula::Eq34);
  for (Index j = 0; j < s.size(); ++j) {
    EXPECT_EQ(a.w[j], b.w[j]);
    EXPECT_NEAR(b.u[j], 2.0 * a.u[j], 1e-15 * a.u.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(a.u.cwiseAbs().maxCoeff(), 0.0);
}

TEST(AsymptoticFormulas, SlowAmplitudeIsOneMinusCosKLPlusSevenQuartersE1) {
  const auto shape =
      asymptotic_mode_shape(stations(3, 1.0), 1.0, kPi, 0.1, deg(30.0), 10.0, Formula::Eq34);
  EXPECT_NEAR(shape.slow_amplitude, 2.0 + 1.75 * 0.05,
              1e-15);  // 1 - cos(pi) = 2, e1 = 0.1 sin 30 deg
  const auto falling =
      asymptotic_mode_shape(stations(3, 1.0), 1.0, kPi, 0.1, deg(-30.0), 10.0, Formula::Eq34);
  EXPECT_EQ(falling.slow_amplitude, shape.slow_amplitude);  // e1 = eps |sin phi|
}

TEST(AsymptoticFormulas, FallingChordIsTheRisingOneMirrored) {
  // The formulas are written with s from the lower end: for phi < 0 the shape is that of |phi|
  // read from the other end, with both displacements reversed (s -> L - s, u -> -u, w -> -w).
  const Vector s = stations(21, 1.0);
  const Vector mirrored = Vector::Ones(s.size()) - s;
  for (Formula formula : {Formula::Eq34, Formula::Eq28}) {
    for (double kl : {3.3, 6.2, 8.9}) {
      const auto falling = asymptotic_mode_shape(s, 1.0, kl, 0.2, deg(-40.0), 50.0, formula);
      const auto rising = asymptotic_mode_shape(mirrored, 1.0, kl, 0.2, deg(40.0), 50.0, formula);
      for (Index j = 0; j < s.size(); ++j) {
        EXPECT_EQ(falling.w[j], -rising.w[j]) << kl << " " << s[j];
        EXPECT_EQ(falling.u[j], -rising.u[j]) << kl << " " << s[j];
      }
      // So the falling chord is fixed at its far (lower) end exactly, as the rising one at s = 0.
      EXPECT_LE(std::abs(falling.w[20]), 1e-14 * falling.w.cwiseAbs().maxCoeff());
      EXPECT_EQ(falling.u[20], 0.0);
    }
  }
}

TEST(AsymptoticFormulas, FirstAxialModeIsTheBarMode) {
  // pi lambda / (eps cos(phi) sqrt(h)); none for an inextensible cable.
  const double eps = 0.2, phi = 0.3, lambda2 = 50.0, h = 0.8;
  EXPECT_LE(catena::testing::relative_error(first_axial_k_l(eps, phi, lambda2, h),
                                            kPi * std::sqrt(lambda2 / h) / (eps * std::cos(phi))),
            1e-15);
  EXPECT_TRUE(std::isinf(first_axial_k_l(eps, phi, kInfinity, h)));
}

}  // namespace
}  // namespace catena::internal
