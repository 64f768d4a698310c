// SPDX-License-Identifier: MIT
// Tests of the first-order modal damping shared by the analytic models (modal_damping.hpp).
//
// Compared with closed forms: the quadrature of sin^2; proportional damping (delta = alpha/2 for
// any shape); the taut string with uniform normal damping (delta = c_n / 2M); the Kelvin-Voigt bar
// m lambda^2 + (EA + c_a lambda) k^2 = 0 (its mode fed to the formula gives the exact root); the
// seabed dashpot under half a sine; the overdamped pair -alpha/2 +- sqrt(alpha^2/4 - omega0^2).
#include "solvers/common/modal_damping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

// Quotients of two quadratures on the same nodes: a few ulp.
constexpr double kRelTolRounding = 1e-14;

DampedSection section(double m, double added, double ea) {
  DampedSection s;
  s.mass_kg_per_m = m;
  s.normal_mass_kg_per_m = m + added;
  s.axial_stiffness_n = ea;
  return s;
}

Vector sampled(const Vector& s, double length, double k_l, double phase = 0.0) {
  return s.unaryExpr([&](double x) { return std::sin(k_l * x / length + phase); });
}

TEST(DampingQuadrature, IntegratesOscillatingSquaresToRounding) {
  const double length = 7.0;
  for (int n : {1, 5, 30}) {
    const DampingQuadrature q = damping_quadrature(length, n * kPi);
    ASSERT_EQ(q.s_m.size(), q.weights.size());
    for (Index j = 1; j < q.s_m.size(); ++j) ASSERT_GT(q.s_m[j], q.s_m[j - 1]);
    EXPECT_GT(q.s_m[0], 0.0);
    EXPECT_LT(q.s_m[q.s_m.size() - 1], length);
    const Vector v = sampled(q.s_m, length, n * kPi);
    // int_0^L sin^2(n pi s / L) ds = L/2; int_0^L 1 ds = L.
    EXPECT_LE(relative_error(q.weights.dot(v.cwiseAbs2()), 0.5 * length), kRelTolRounding) << n;
    EXPECT_LE(relative_error(q.weights.sum(), length), kRelTolRounding);
  }
}

TEST(ModalDamping, ProportionalDampingGivesHalfAlphaForAnyShape) {
  DampedSection s = section(3.0, 2.0, 1e6);
  const double alpha = 0.37;
  s.damping.tangential_n_s_per_m2 = alpha * s.mass_kg_per_m;
  s.damping.normal_n_s_per_m2 = alpha * s.normal_mass_kg_per_m;
  const DampingQuadrature q = damping_quadrature(10.0, 4.0 * kPi);
  InplaneModeSamples mode;
  mode.u = sampled(q.s_m, 10.0, 3.1, 0.2);
  mode.w = sampled(q.s_m, 10.0, 4.0 * kPi) + 0.3 * q.s_m;
  mode.tension_n = Vector::Constant(q.s_m.size(), 5e3);  // c_a = 0: no contribution
  EXPECT_LE(relative_error(inplane_decay_rate(q, mode, s), 0.5 * alpha), kRelTolRounding);
  EXPECT_EQ(nonproportional_rate_1_s(Plane::InPlane, s, 2.0), 0.0);
}

TEST(ModalDamping, TautStringWithUniformNormalDampingOutOfPlane) {
  DampedSection s = section(3.0, 2.0, kInfinity);
  s.damping.normal_n_s_per_m2 = 0.8;
  s.damping.tangential_n_s_per_m2 = 5.0;  // no tangential motion out of plane: no effect
  const DampingQuadrature q = damping_quadrature(2.0, 3.0 * kPi);
  const double expected = 0.8 / (2.0 * 5.0);
  EXPECT_LE(relative_error(outofplane_decay_rate(q, sampled(q.s_m, 2.0, 3.0 * kPi), s), expected),
            kRelTolRounding);
  EXPECT_EQ(nonproportional_rate_1_s(Plane::OutOfPlane, s, 1.0), 0.0);
}

TEST(ModalDamping, KelvinVoigtBarModeGivesTheExactRoot) {
  // Bar: u = sin(k s), eps = k cos(k s), tau = EA eps; m lambda^2 + (EA + c_a lambda) k^2 = 0.
  const double length = 3.0, m = 2.0, ea = 50.0, c_a = 0.4;
  DampedSection s = section(m, 0.0, ea);
  s.damping.axial_n_s = c_a;
  for (int n : {1, 2, 7}) {
    const double k = n * kPi / length;
    const DampingQuadrature q = damping_quadrature(length, k * length);
    InplaneModeSamples mode;
    mode.u = sampled(q.s_m, length, k * length);
    mode.w = Vector::Zero(q.s_m.size());
    mode.tension_n = ea * k * q.s_m.unaryExpr([&](double x) { return std::cos(k * x); });
    const double delta = inplane_decay_rate(q, mode, s);
    // Roots of m lambda^2 + c_a k^2 lambda + EA k^2 = 0.
    const std::complex<double> disc(c_a * c_a * k * k * k * k - 4.0 * m * ea * k * k, 0.0);
    const std::complex<double> lambda = (-c_a * k * k + std::sqrt(disc)) / (2.0 * m);
    EXPECT_LE(relative_error(delta, -lambda.real()), kRelTolRounding) << n;
    const double omega0 = std::sqrt(ea / m) * k;
    EXPECT_LE(relative_error(std::sqrt(omega0 * omega0 - delta * delta), lambda.imag()),
              kRelTolRounding)
        << n;
  }
}

TEST(ModalDamping, SeabedDashpotActsOnTheGroundedPartOnly) {
  const double length = 4.0, c_s = 1.5;
  DampedSection s = section(1.0, 1.0, kInfinity);
  s.seabed_damping_n_s_per_m2 = c_s;
  const DampingQuadrature q = damping_quadrature(length, 0.0);  // 8 panels: L/2 is a panel end
  InplaneModeSamples mode;
  mode.u = Vector::Zero(q.s_m.size());
  mode.w = sampled(q.s_m, length, kPi);
  mode.grounded_vertical = q.s_m.unaryExpr(
      [&](double x) { return x < 0.5 * length ? std::sin(kPi * x / length) : 0.0; });
  // int_0^{L/2} sin^2 = L/4 of int_0^L sin^2 = L/2: delta = c_s / (4 M).
  EXPECT_LE(relative_error(inplane_decay_rate(q, mode, s), c_s / 8.0), kRelTolRounding);
}

ModalResult undamped_plane(const std::vector<double>& omegas, double estimate) {
  ModalResult result;
  result.plane = Plane::InPlane;
  result.proved_count_below_top = static_cast<int>(omegas.size());
  result.summary.termination = Termination::Converged;
  for (std::size_t i = 0; i < omegas.size(); ++i) {
    Mode mode;
    mode.index = static_cast<int>(i) + 1;
    mode.omega_rad_s = omegas[i];
    mode.relative_error_estimate = estimate;
    mode.w = Vector::Constant(3, 1.0);
    result.modes.push_back(mode);
  }
  return result;
}

TEST(ModalDamping, OverdampedRootsAreListedApartAndTheRestReindexed) {
  const double alpha = 3.0;  // delta = 1.5 > omega0 = 1 only for the first mode
  DampedSection s = section(1.0, 1.0, kInfinity);
  s.damping.tangential_n_s_per_m2 = alpha * 1.0;
  s.damping.normal_n_s_per_m2 = alpha * 2.0;
  ModalResult result = undamped_plane({1.0, 2.0, 3.0}, 1e-3);
  apply_perturbed_damping(Plane::InPlane, result, {1.5, 1.5, 1.5}, s, DimensionlessGroups{});
  ASSERT_EQ(result.modes.size(), 2u);
  ASSERT_EQ(result.overdamped.size(), 2u);
  EXPECT_EQ(result.proved_count_below_top, -1);
  for (int i = 0; i < 2; ++i) {
    const Mode& mode = result.modes[i];
    const double omega0 = i + 2.0;
    EXPECT_EQ(mode.index, i + 1);
    EXPECT_LE(relative_error(mode.omega_rad_s, std::sqrt(omega0 * omega0 - 2.25)), kRelTolRounding);
    EXPECT_EQ(mode.decay_rate_1_s, 1.5);
    EXPECT_LE(relative_error(mode.damping_ratio, 1.5 / omega0), kRelTolRounding);
    EXPECT_EQ(mode.decay_rate_error_estimate, kDecayRoundingEstimate);  // proportional: exact
    // omega0's model error, amplified by omega0^2 / omega_d^2, and delta's rounding.
    EXPECT_LE(relative_error(mode.relative_error_estimate,
                             (1e-3 * omega0 * omega0 + 2.25 * kDecayRoundingEstimate) /
                                 (omega0 * omega0 - 2.25)),
              1e-14);
    EXPECT_EQ(mode.w_imag.size(), 3);
  }
  const double root = std::sqrt(2.25 - 1.0);
  EXPECT_LE(relative_error(result.overdamped[0].decay_rate_1_s, 1.5 - root), kRelTolRounding);
  EXPECT_LE(relative_error(result.overdamped[1].decay_rate_1_s, 1.5 + root), kRelTolRounding);
  for (const Mode& mode : result.overdamped) {
    EXPECT_EQ(mode.omega_rad_s, 0.0);
    EXPECT_EQ(mode.damping_ratio, 1.0);
  }
  EXPECT_EQ(result.overdamped[0].index, 1);
  EXPECT_EQ(result.overdamped[1].index, 2);
}

TEST(ModalDamping, NonProportionalEstimatesGrowWithTheDamping) {
  DampedSection s = section(1.0, 1.0, kInfinity);
  double previous = 0.0;
  for (double c_n : {1e-4, 1e-3, 1e-2}) {
    s.damping.normal_n_s_per_m2 = c_n;  // c_t = 0: non-proportional, D = (c_n / M) / 2
    ModalResult result = undamped_plane({1.0, 2.0, 3.0}, 1e-6);
    const double delta = 0.4 * c_n;
    apply_perturbed_damping(Plane::InPlane, result, {delta, delta, delta}, s,
                            DimensionlessGroups{});
    ASSERT_EQ(result.summary.termination, Termination::Converged);
    ASSERT_EQ(result.modes.size(), 3u);
    const Mode& first = result.modes[0];
    // D = |0 - c_n/M| / 2; coupling to mode 2 at gap 1: kappa = D / 2.
    const double rate = 0.25 * c_n, kappa = 0.5 * rate;
    EXPECT_NEAR(first.decay_rate_error_estimate,
                rate / (2.0 * delta) * (2.0 * std::sqrt(1e-6) + kappa), 1e-13);
    EXPECT_GT(first.decay_rate_error_estimate, previous);
    previous = first.decay_rate_error_estimate;
    EXPECT_GT(first.relative_error_estimate, 1e-6);
  }
}

TEST(ModalDamping, DeclinesWhereThePerturbationIsNotMeaningful) {
  DampedSection s = section(1.0, 1.0, kInfinity);
  s.damping.normal_n_s_per_m2 = 2.0;  // D = 0.5 1/s against a gap of 1 rad/s: kappa = 0.25
  ModalResult ok = undamped_plane({1.0, 2.0}, 1e-6);
  apply_perturbed_damping(Plane::InPlane, ok, {0.4, 0.4}, s, DimensionlessGroups{});
  EXPECT_EQ(ok.summary.termination, Termination::Converged);
  s.damping.normal_n_s_per_m2 = 3.0;  // kappa = 0.375 > 0.3
  ModalResult declined = undamped_plane({1.0, 2.0}, 1e-6);
  apply_perturbed_damping(Plane::InPlane, declined, {0.6, 0.6}, s, DimensionlessGroups{});
  EXPECT_EQ(declined.summary.termination, Termination::NotApplicable);
  EXPECT_TRUE(declined.modes.empty());
  EXPECT_TRUE(declined.overdamped.empty());
  EXPECT_NE(declined.summary.message.find("exact solver"), std::string::npos);
}

}  // namespace
}  // namespace catena::internal
