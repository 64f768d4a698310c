// SPDX-License-Identifier: MIT
// The helpers every solver fills its modes with: frequency units, the shape normalisation of
// include/catena/solvers/modal_result.hpp (scale, sign, ties, the u-normalised axial case), the
// trapezoid rule on the stations and the modal masses built on it.
#include "solvers/common/mode_tools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "catena/statics/problem_builders.hpp"

namespace catena::internal {
namespace {

Vector values(std::initializer_list<double> list) {
  Vector v(static_cast<Index>(list.size()));
  Index i = 0;
  for (double x : list) v[i++] = x;
  return v;
}

// Exact comparison of vectors, with the entries printed when they differ.
void expect_equal(const Vector& actual, const Vector& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (Index i = 0; i < actual.size(); ++i)
    EXPECT_DOUBLE_EQ(actual[i], expected[i]) << "entry " << i;
}

TEST(SetModeFrequency, FillsEveryUnitFromOmega) {
  DimensionlessGroups groups;
  groups.taut_frequency_scale_rad_s = 2.0;  // kL = omega / 2
  groups.gale_frequency_scale_rad_s = 0.5;
  Mode mode;
  set_mode_frequency(mode, 3.0 * kPi, groups);
  EXPECT_DOUBLE_EQ(mode.omega_rad_s, 3.0 * kPi);
  EXPECT_DOUBLE_EQ(mode.frequency_hz, 1.5);
  EXPECT_DOUBLE_EQ(mode.k_l_over_pi, 1.5);
  ASSERT_TRUE(mode.gale_ratio.has_value());
  EXPECT_DOUBLE_EQ(*mode.gale_ratio, 6.0 * kPi);
}

TEST(SetModeFrequency, NoGaleRatioWithoutHorizontalTension) {
  DimensionlessGroups groups;  // gale scale 0: a vertical cable, H = 0
  Mode mode;
  mode.gale_ratio = 1.0;  // a stale value is cleared, not kept
  set_mode_frequency(mode, 2.0, groups);
  EXPECT_FALSE(mode.gale_ratio.has_value());
  EXPECT_DOUBLE_EQ(mode.k_l_over_pi, 2.0 / kPi);  // default scale 1 rad/s
}

TEST(SetModeFrequency, GaleRatioIsOmegaInGalesUnits) {
  // Gale's problems have sqrt(g/a) = 1 rad/s (a = 1 m, W0 = 1 N/m, m = 1 kg/m).
  const Problem problem = make_gale_xi_problem(-0.5, 1.0);
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  Mode mode;
  set_mode_frequency(mode, 2.75, groups);
  ASSERT_TRUE(mode.gale_ratio.has_value());
  EXPECT_NEAR(*mode.gale_ratio, 2.75, 1e-12);
}

TEST(NormaliseInplaneMode, ScalesToUnitMaxWPositiveAtItsPeak) {
  Mode mode;
  mode.w = values({0.0, -4.0, 2.0, 0.0});
  mode.u = values({0.0, 1.0, 3.0, 0.0});
  mode.tension_n = values({10.0, -20.0, 6.0, 2.0});
  const double factor = normalise_inplane_mode(mode);
  EXPECT_DOUBLE_EQ(factor, -0.25);
  EXPECT_EQ(mode.normalised_by, "w");
  expect_equal(mode.w, values({0.0, 1.0, -0.5, 0.0}));
  expect_equal(mode.u, values({0.0, -0.25, -0.75, 0.0}));  // u by the same factor
  expect_equal(mode.tension_n, values({-2.5, 5.0, -1.5, -0.5}));
  EXPECT_DOUBLE_EQ(mode.max_abs_tension_n, 5.0);
}

TEST(NormaliseInplaneMode, TiesGoToTheFirstStation) {
  // Equal peaks of opposite sign (up to 1e-9 relative): the first one is made positive, in every
  // solver alike, so that antisymmetric shapes compare directly.
  Mode mode;
  mode.w = values({0.0, -2.0, 0.5, 2.0 * (1.0 + 1e-12)});
  normalise_inplane_mode(mode);
  EXPECT_DOUBLE_EQ(mode.w[1], 1.0);
  EXPECT_NEAR(mode.w[3], -1.0, 1e-11);
  // A peak larger by more than the tie tolerance wins.
  mode.w = values({0.0, -2.0, 0.5, 2.0 * (1.0 + 1e-6)});
  normalise_inplane_mode(mode);
  EXPECT_DOUBLE_EQ(mode.w[3], 1.0);
  EXPECT_LT(mode.w[1], 0.0);
}

TEST(NormaliseInplaneMode, AxialModeWithoutNormalMotionIsScaledByU) {
  // A straight bar's axial mode: w is rounding noise, so u fixes the scale (normalised_by = "u").
  Mode mode;
  mode.u = values({0.0, -0.5, -1.0, -0.5, 0.0});
  mode.w = values({0.0, 1e-7, 0.0, -1e-7, 0.0});  // 1e-7 <= 1e-6 max|u|
  const double factor = normalise_inplane_mode(mode);
  EXPECT_EQ(mode.normalised_by, "u");
  EXPECT_DOUBLE_EQ(factor, -1.0);
  expect_equal(mode.u, values({0.0, 0.5, 1.0, 0.5, 0.0}));
  expect_equal(mode.w, values({0.0, -1e-7, 0.0, 1e-7, 0.0}));
  EXPECT_DOUBLE_EQ(mode.max_abs_tension_n, -1.0);  // no tension asked: left as "not computed"
}

TEST(NormaliseInplaneMode, ThresholdBetweenUAndWIsOneMillionth) {
  Mode at;
  at.u = values({0.0, 2.0});
  at.w = values({0.0, 2e-6});  // exactly 1e-6 max|u|: still by u
  normalise_inplane_mode(at);
  EXPECT_EQ(at.normalised_by, "u");
  Mode above;
  above.u = values({0.0, 2.0});
  above.w = values({0.0, 2.1e-6});
  normalise_inplane_mode(above);
  EXPECT_EQ(above.normalised_by, "w");
  EXPECT_DOUBLE_EQ(above.w[1], 1.0);
}

TEST(NormaliseInplaneMode, NothingToScaleLeavesTheModeAlone) {
  Mode empty;
  EXPECT_DOUBLE_EQ(normalise_inplane_mode(empty), 1.0);
  Mode zero;
  zero.u = Vector::Zero(3);
  zero.w = Vector::Zero(3);
  EXPECT_DOUBLE_EQ(normalise_inplane_mode(zero), 1.0);
  expect_equal(zero.w, Vector::Zero(3));
}

TEST(NormaliseOutofplaneMode, ScalesByVWithTheSameSignRule) {
  Mode mode;
  mode.v = values({0.0, -0.2, -0.8, -0.4});
  mode.tension_n = values({0.4, 0.0, -0.8, 0.0});
  const double factor = normalise_outofplane_mode(mode);
  EXPECT_DOUBLE_EQ(factor, -1.25);
  EXPECT_EQ(mode.normalised_by, "v");
  expect_equal(mode.v, values({0.0, 0.25, 1.0, 0.5}));
  EXPECT_DOUBLE_EQ(mode.max_abs_tension_n, 1.0);
}

TEST(SetDampedRoot, SplitsLambdaIntoOmegaDecayAndRatio) {
  const DimensionlessGroups groups;
  Mode mode;
  set_damped_root(mode, {-0.3, 4.0}, groups);
  EXPECT_EQ(mode.omega_rad_s, 4.0);
  EXPECT_DOUBLE_EQ(mode.frequency_hz, 4.0 / (2.0 * kPi));
  EXPECT_EQ(mode.decay_rate_1_s, 0.3);
  EXPECT_DOUBLE_EQ(mode.damping_ratio, 0.3 / std::hypot(0.3, 4.0));
  Mode undamped, reference;
  set_damped_root(undamped, {0.0, 2.5}, groups);
  set_mode_frequency(reference, 2.5, groups);
  EXPECT_EQ(undamped.omega_rad_s, reference.omega_rad_s);
  EXPECT_EQ(undamped.k_l_over_pi, reference.k_l_over_pi);
  EXPECT_FALSE(std::signbit(undamped.decay_rate_1_s)) << "no -0 in the JSON";
  EXPECT_EQ(undamped.damping_ratio, 0.0);
  Mode rounding;
  set_damped_root(rounding, {1.5e-25, 2.5}, groups);
  EXPECT_EQ(rounding.decay_rate_1_s, 0.0) << "rounding does not make a mode grow";
  Mode growing;
  set_damped_root(growing, {1e-6, 2.5}, groups);
  EXPECT_EQ(growing.decay_rate_1_s, -1e-6) << "a real growth is kept, for validation to refuse";
}

// A complex shape is scaled by one complex factor: the peak of |w| becomes 1 (real), every
// component keeps its ratio to w, and max |tau| is the modulus.
TEST(NormaliseComplexMode, TurnsThePeakOfTheNamedComponentIntoOne) {
  Mode mode;
  mode.w = values({0.0, 1.0, -2.0});
  mode.w_imag = values({0.0, 1.0, 2.0});
  mode.u = values({1.0, 0.0, 0.0});
  mode.tension_n = values({0.0, 4.0, 0.0});
  const std::complex<double> peak(-2.0, 2.0);
  const double scale = normalise_complex_mode(mode, "w");
  EXPECT_DOUBLE_EQ(scale, 1.0 / std::abs(peak));
  EXPECT_EQ(mode.normalised_by, "w");
  EXPECT_DOUBLE_EQ(mode.w[2], 1.0);
  EXPECT_NEAR(mode.w_imag[2], 0.0, 1e-16);
  const std::complex<double> u0 = std::complex<double>(1.0, 0.0) / peak;
  EXPECT_DOUBLE_EQ(mode.u[0], u0.real());
  ASSERT_EQ(mode.u_imag.size(), 3);
  EXPECT_DOUBLE_EQ(mode.u_imag[0], u0.imag());
  EXPECT_DOUBLE_EQ(mode.max_abs_tension_n, 4.0 / std::abs(peak));
}

TEST(IntegrateOnStations, TrapezoidIsExactForLinearFunctionsOnUnequalSpacing) {
  const Vector s = values({0.0, 0.1, 0.35, 1.0, 1.2});
  const Vector f = (3.0 + 2.0 * s.array()).matrix();
  EXPECT_NEAR(integrate_on_stations(s, f), 3.0 * 1.2 + 1.2 * 1.2, 1e-15);
  // Shifted stations: the same rule on [2, 2.5].
  EXPECT_NEAR(integrate_on_stations(values({2.0, 2.2, 2.5}), values({-1.0, -0.6, 0.0})), -0.25,
              1e-15);
}

TEST(IntegrateOnStations, TrapezoidOfAQuadraticHasItsKnownError) {
  // s^2 on [0, 1] with h = 1/2: 0.375, not 1/3 (the rule's error h^2/12 (b - a) f'' = 1/24).
  EXPECT_DOUBLE_EQ(integrate_on_stations(values({0.0, 0.5, 1.0}), values({0.0, 0.25, 1.0})), 0.375);
}

TEST(IntegrateOnStations, FewerThanTwoStationsIntegrateToZero) {
  EXPECT_EQ(integrate_on_stations(Vector(), Vector()), 0.0);
  EXPECT_EQ(integrate_on_stations(values({1.0}), values({5.0})), 0.0);
}

TEST(ModalMass, InplaneWeighsUByMAndWByTheNormalMass) {
  Mode mode;
  mode.s_m = values({0.0, 1.0, 3.0});
  mode.u = values({0.0, 1.0, 1.0});
  mode.w = values({1.0, 0.0, 2.0});
  // density m u^2 + M w^2 = (5, 2, 22) with m = 2, M = 5; trapezoid: 0.5 (5 + 2) + 1 (2 + 22).
  EXPECT_DOUBLE_EQ(inplane_modal_mass(mode, 2.0, 5.0), 27.5);
}

TEST(ModalMass, OutofplaneWeighsVByTheNormalMass) {
  Mode mode;
  mode.s_m = values({0.0, 1.0, 3.0});
  mode.v = values({1.0, 0.0, 2.0});
  EXPECT_DOUBLE_EQ(outofplane_modal_mass(mode, 5.0), 0.5 * 5.0 + 1.0 * 20.0);
}

TEST(ModalMass, StringModeHasHalfTheCableMass) {
  // v = sin(n pi s / L) on equally spaced stations: the trapezoid rule is exact for sin^2 here, so
  // the modal mass is M L / 2 to rounding.
  const double L = 7.0, M = 3.0;
  Mode mode;
  mode.s_m = Vector::LinSpaced(201, 0.0, L);
  for (int n : {1, 2, 5}) {
    mode.v = (mode.s_m.array() * (n * kPi / L)).sin().matrix();
    EXPECT_NEAR(outofplane_modal_mass(mode, M), 0.5 * M * L, 1e-12) << "n = " << n;
  }
}

}  // namespace
}  // namespace catena::internal

namespace catena::internal {
namespace {

TEST(DropShapeFields, KeepsTheSummaryAndClearsTheShape) {
  Mode mode;
  mode.omega_rad_s = 2.0;
  mode.relative_error_estimate = 1e-9;
  mode.s_m = Vector::LinSpaced(3, 0.0, 1.0);
  mode.u = mode.v = mode.w = mode.tension_n = Vector::Ones(3);
  mode.normalised_by = "w";
  mode.max_abs_tension_n = 5.0;
  mode.modal_mass_kg = 0.5;
  drop_shape_fields(mode);
  EXPECT_EQ(mode.s_m.size() + mode.u.size() + mode.v.size() + mode.w.size() + mode.tension_n.size(),
            0);
  EXPECT_EQ(mode.modal_mass_kg, -1.0);
  EXPECT_EQ(mode.omega_rad_s, 2.0);
  EXPECT_EQ(mode.relative_error_estimate, 1e-9);
  EXPECT_EQ(mode.normalised_by, "w");
  EXPECT_EQ(mode.max_abs_tension_n, 5.0);
}

}  // namespace
}  // namespace catena::internal
