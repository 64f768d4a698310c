// SPDX-License-Identifier: MIT
// catena check's comparison logic (include/catena/verification/external_check.hpp) on synthetic
// "other programs" built from a known reference: a biased code f(N) = f_ref (1 - c h^2) + bias
// with h = 1/N, an unbiased one, shapes that swap two close modes. Expected values are the
// construction's own parameters (order 2, the bias), so the test fails if the extrapolation or
// the pairing is wrong.
#include "catena/verification/external_check.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/error.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

constexpr double kLength = 100.0;

// A reference of `count` modes omega_k = 0.5 k rad/s, shapes sin(k pi s / L) on 201 stations.
CertifiedReference sine_reference(Plane plane, int count, std::vector<double> omegas = {}) {
  CertifiedReference reference;
  reference.plane = plane;
  reference.solver = "shooting";
  for (int k = 1; k <= count; ++k) {
    ReferenceMode mode;
    mode.index = k;
    mode.omega_rad_s = omegas.empty() ? 0.5 * k : omegas[static_cast<std::size_t>(k - 1)];
    mode.relative_error_estimate = 1e-10;
    mode.s_m = Vector::LinSpaced(201, 0.0, kLength);
    Vector& shape = plane == Plane::InPlane ? mode.w : mode.v;
    shape = (mode.s_m.array() * k * kPi / kLength).sin().matrix();
    reference.modes.push_back(mode);
  }
  return reference;
}

// The other program's mode `mode` at resolutions N: f_ref (1 - c / N^2) + bias.
std::vector<ExternalMode> biased_code(
    int mode, double reference, double c, double bias, const std::vector<double>& resolutions) {
  std::vector<ExternalMode> out;
  for (double n : resolutions) {
    ExternalMode row;
    row.mode = mode;
    row.resolution = n;
    row.omega_rad_s = reference * (1.0 - c / (n * n)) + bias;
    row.origin = "synthetic N = " + std::to_string(n);
    out.push_back(row);
  }
  return out;
}

TEST(ExternalCheck, BiasedCodeRecoversOrderTwoAndItsBias) {
  const CertifiedReference reference = sine_reference(Plane::InPlane, 4);
  for (const std::vector<double>& resolutions :
       {std::vector<double>{10, 20, 40, 80}, {12, 20, 35, 60}}) {
    const double f_ref = reference.modes[2].omega_rad_s;
    const double bias =
        0.02 * f_ref;  // 2 %: a lumped-mass code converging cleanly to a wrong limit
    const ExternalCheck check =
        check_external_results(biased_code(3, f_ref, 2.0, bias, resolutions), {reference});
    ASSERT_EQ(check.modes.size(), 1u);
    const ModeComparison& mode = check.modes[0];
    ASSERT_TRUE(mode.study.has_value());
    ASSERT_TRUE(mode.study->trustworthy) << mode.study->note;
    EXPECT_NEAR(*mode.study->observed_order, 2.0, 1e-6);
    EXPECT_NEAR(*mode.study->coarser_order, 2.0, 1e-6);
    const double recovered_bias = *mode.study->limit_omega_rad_s - f_ref;
    EXPECT_LE(std::abs(recovered_bias - bias), 1e-3 * bias)
        << "recovered " << recovered_bias << ", built " << bias;
    EXPECT_NEAR(*mode.study->bias_relative, 0.02, 1e-3 * 0.02);
    EXPECT_EQ(mode.verdict, ModeVerdict::ConvergesToWrongLimit) << mode.study->note;
    EXPECT_TRUE(check.any_failure());
  }
}

TEST(ExternalCheck, UnbiasedCodeIsConvergedOrNotYetWithinTolerance) {
  const CertifiedReference reference = sine_reference(Plane::InPlane, 4);
  const double f_ref = reference.modes[1].omega_rad_s;
  const std::vector<double> resolutions = {10, 20, 40, 80};
  // c = 2: the finest error is 2 / 6400 = 3.1e-4 <= rtol 1e-3.
  const ExternalCheck converged =
      check_external_results(biased_code(2, f_ref, 2.0, 0.0, resolutions), {reference});
  EXPECT_EQ(converged.modes[0].verdict, ModeVerdict::Converged);
  EXPECT_NEAR(converged.modes[0].resolutions.back().relative_error, -2.0 / 6400.0, 1e-12);
  EXPECT_LE(std::abs(*converged.modes[0].study->bias_relative), 1e-9);
  EXPECT_FALSE(converged.any_failure());
  // c = 20: the finest error is 3.1e-3 > 1e-3, but the limit is right.
  const ExternalCheck not_yet =
      check_external_results(biased_code(2, f_ref, 20.0, 0.0, resolutions), {reference});
  EXPECT_EQ(not_yet.modes[0].verdict, ModeVerdict::NotYetWithinTolerance);
  EXPECT_TRUE(not_yet.any_failure());
}

TEST(ExternalCheck, ExactCodeAtEveryResolutionIsConverged) {
  const CertifiedReference reference = sine_reference(Plane::OutOfPlane, 2);
  std::vector<ExternalMode> rows = biased_code(1, 0.5, 0.0, 0.0, {10, 20, 40});
  for (auto& row : rows) row.plane = Plane::OutOfPlane;
  const ExternalCheck check = check_external_results(rows, {reference});
  ASSERT_TRUE(check.modes[0].study->trustworthy);
  EXPECT_FALSE(check.modes[0].study->observed_order.has_value());
  EXPECT_EQ(check.modes[0].verdict, ModeVerdict::Converged);
}

TEST(ExternalCheck, OscillatingSequenceIsInconclusive) {
  const CertifiedReference reference = sine_reference(Plane::InPlane, 2);
  std::vector<ExternalMode> rows = biased_code(1, 0.5, 2.0, 0.0, {10, 20, 40, 80});
  rows[2].omega_rad_s = 0.5 * (1.0 + 5e-3);  // up, then down: no order fits
  const ExternalCheck check = check_external_results(rows, {reference});
  EXPECT_FALSE(check.modes[0].study->trustworthy);
  EXPECT_EQ(check.modes[0].verdict,
            ModeVerdict::WithinTolerance);  // judged on the finest value only
}

TEST(ExternalCheck, SingleResolutionIsJudgedAgainstRtol) {
  const CertifiedReference reference = sine_reference(Plane::InPlane, 3);
  ExternalMode row;
  row.mode = 2;
  row.omega_rad_s = 1.0 * (1.0 + 2e-3);
  ExternalCheckOptions options;
  EXPECT_EQ(check_external_results({row}, {reference}, options).modes[0].verdict,
            ModeVerdict::BeyondTolerance);
  options.rtol = 3e-3;
  EXPECT_EQ(check_external_results({row}, {reference}, options).modes[0].verdict,
            ModeVerdict::WithinTolerance);
}

// Two close modes (1.000 and 1.001 rad/s): the other program numbers them by its own frequencies,
// which put its mode 1 nearer Catena's mode 1, but its mode 1 has Catena's mode 2's shape.
TEST(ExternalCheck, MacPairingSwapsTwoCloseModes) {
  const CertifiedReference reference = sine_reference(Plane::InPlane, 3, {1.000, 1.001, 2.0});
  auto other = [&](int mode, double omega, int shape_of) {
    ExternalMode row;
    row.mode = mode;
    row.omega_rad_s = omega;
    ExternalShape shape;
    shape.s_m = Vector::LinSpaced(41, 0.0, kLength);
    shape.w = -3.0 *
              (shape.s_m.array() * shape_of * kPi / kLength).sin().matrix();  // any scale, any sign
    row.shape = shape;
    return row;
  };
  const std::vector<ExternalMode> rows = {other(1, 1.0002, 2), other(2, 1.0009, 1)};
  const ExternalCheck by_mac = check_external_results(rows, {reference});
  EXPECT_EQ(by_mac.modes[0].reference_index, 2) << by_mac.modes[0].pairing;
  EXPECT_EQ(by_mac.modes[1].reference_index, 1) << by_mac.modes[1].pairing;
  EXPECT_NEAR(*by_mac.modes[0].resolutions[0].mac, 1.0, 1e-6);
  std::vector<ExternalMode> without_shapes = rows;
  for (auto& row : without_shapes) row.shape.reset();
  const ExternalCheck by_frequency = check_external_results(without_shapes, {reference});
  EXPECT_EQ(by_frequency.modes[0].reference_index, 1);
  EXPECT_EQ(by_frequency.modes[1].reference_index, 2);
}

TEST(ExternalCheck, TensionIsComparedAfterScalingToCatena) {
  CertifiedReference reference = sine_reference(Plane::InPlane, 1);
  ReferenceMode& ref = reference.modes[0];
  ref.tension_n = 1000.0 * (ref.s_m.array() * kPi / kLength).cos().matrix();
  ExternalMode row;
  row.omega_rad_s = 0.5;
  ExternalShape shape;
  shape.s_m = Vector::LinSpaced(11, 0.0, kLength);
  shape.w = 0.25 * (shape.s_m.array() * kPi / kLength).sin().matrix();
  shape.tension_n = 250.0 * 1.01 * (shape.s_m.array() * kPi / kLength).cos().matrix();  // 1 % high
  row.shape = shape;
  const ExternalCheck check = check_external_results({row}, {reference});
  EXPECT_NEAR(*check.modes[0].resolutions[0].tension_relative, 0.01, 1e-4);
}

TEST(ExternalCheck, RejectsDuplicatesMixedResolutionsAndMissingReference) {
  const CertifiedReference reference = sine_reference(Plane::InPlane, 2);
  std::vector<ExternalMode> rows = biased_code(1, 0.5, 1.0, 0.0, {10, 20});
  rows[1].resolution = 10.0;
  testing::expect_invalid([&] { validate_external_results(rows); }, "duplicate");
  rows[1].resolution.reset();
  testing::expect_invalid([&] { validate_external_results(rows); }, "mixes");
  rows = biased_code(1, 0.5, 1.0, 0.0, {10});
  rows[0].plane = Plane::OutOfPlane;
  testing::expect_invalid([&] { check_external_results(rows, {reference}); }, "out-of-plane");
  rows[0].plane = Plane::InPlane;
  rows[0].shape =
      ExternalShape{Vector::LinSpaced(3, 0.0, 2 * kLength), {}, Vector::Ones(3), {}, {}};
  testing::expect_invalid([&] { check_external_results(rows, {reference}); }, "outside");
  ExternalCheckOptions options;
  options.rtol = 0.0;
  testing::expect_invalid([&] { options.validate(); }, "rtol");
}

TEST(ExternalCheck, ModesBeyondWhatCatenaSolvesAreRefusedBeforeAnySolve) {
  std::vector<ExternalMode> rows = biased_code(1000000, 1.0, 0.0, 0.0, {10.0});
  try {
    validate_external_results(rows);
    FAIL() << "mode 1000000 accepted";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("mode = 1000000"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("at most 1000"), std::string::npos) << error.what();
  }
  rows = biased_code(1000, 1.0, 0.0, 0.0, {10.0});
  EXPECT_NO_THROW(validate_external_results(rows));
}

}  // namespace
}  // namespace catena
