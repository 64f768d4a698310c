// SPDX-License-Identifier: MIT
// catena check on another program's dynamic tension (include/catena/verification/tension_check.hpp,
// scene_tension_check.hpp) against hand-made Catena results whose profiles are closed forms:
// - a linear sigma(s) (linear interpolation exact), and a complex amplitude linear in s (complex
//   interpolation exact, the modulus not linear): the interpolated values must equal the closed
//   form at the other program's stations;
// - a quadratic profile on coarse stations: the interpolation error estimate must bound (here:
//   equal) the true interpolation error h^2 f'' / 8;
// - a synthetic lumped-mass code T_N(s) = T(s) (1 + c / N^2) (1 + bias) at four node-based
//   resolutions: the study at the fairlead and the anchor must recover order 2 and the bias;
// - the reference choice between two solvers, and what is said when no solver computed it.
#include "catena/verification/tension_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "catena/core/error.hpp"
#include "catena/verification/scene_tension_check.hpp"

namespace catena {
namespace {

constexpr double kLength = 900.0;
constexpr double kTensionAnchor = 2.0e4;
constexpr double kTensionFairlead = 6.0e4;
// Interpolating a linear profile, or a complex amplitude linear in s, is exact up to rounding of
// values ~ 1e5 N.
constexpr double kRoundingN = 1e-8;

// Irregular-motion result with sigma(s) linear from the anchor to the fairlead on `stations`.
DynamicTension linear_std(int stations, double estimate = 1e-6) {
  DynamicTension t;
  t.irregular = true;
  t.s_m = Vector::LinSpaced(stations, 0.0, kLength);
  t.std_n =
      (kTensionAnchor + (kTensionFairlead - kTensionAnchor) * t.s_m.array() / kLength).matrix();
  t.mean_n = Vector::Constant(stations, 1e6);
  t.converged = true;
  t.residual = 1e-10;
  t.iterations = 12;
  t.relative_error_estimate = estimate;
  t.fairlead.s_m = kLength;
  t.fairlead.std_n = kTensionFairlead;
  t.anchor.std_n = kTensionAnchor;
  return t;
}

double sigma_at(double s) {
  return kTensionAnchor + (kTensionFairlead - kTensionAnchor) * s / kLength;
}

TensionReference reference_of(DynamicTension t, const std::string& solver = "shooting") {
  TensionReference r;
  r.solver = solver;
  r.reason = "test";
  r.tension = std::move(t);
  return r;
}

ExternalTensionStation at_s(double s, double value, std::optional<double> resolution = {}) {
  ExternalTensionStation station;
  station.s_m = s;
  station.tension_n = value;
  station.resolution = resolution;
  station.origin = "test s = " + std::to_string(s);
  return station;
}

TEST(TensionCheck, ExactValuesAtOffGridStationsAgreeAndTheFairleadIsFound) {
  ExternalTension other;
  for (double s : {0.0, 137.3, 450.0, 612.9, kLength})
    other.stations.push_back(at_s(s, sigma_at(s)));
  const TensionCheck check = check_external_tension(other, reference_of(linear_std(201)));
  ASSERT_EQ(check.stations.size(), 5u);
  for (const auto& c : check.stations) {
    EXPECT_NEAR(c.catena_n, sigma_at(c.s_m), kRoundingN) << "s = " << c.s_m;
    EXPECT_NEAR(c.difference_n, 0.0, kRoundingN);
    EXPECT_TRUE(c.within);
  }
  ASSERT_TRUE(check.fairlead.has_value());
  EXPECT_DOUBLE_EQ(check.fairlead->s_m, kLength);
  EXPECT_EQ(check.verdict, ModeVerdict::WithinTolerance);
  EXPECT_FALSE(check.any_failure());
}

TEST(TensionCheck, DifferenceBeyondRtolPlusBothUncertaintiesDisagrees) {
  ExternalCheckOptions options;
  options.rtol = 1e-3;
  ExternalTension other;
  other.stations.push_back(at_s(300.0, sigma_at(300.0) * 1.02));  // 2 %: beyond
  other.stations.push_back(at_s(600.0, sigma_at(600.0) * 1.02));
  other.stations.back().uncertainty_n = 0.03 * sigma_at(600.0);  // stated: covers the 2 %
  const TensionCheck check =
      check_external_tension(other, reference_of(linear_std(201, 1e-4)), options);
  ASSERT_EQ(check.stations.size(), 2u);
  EXPECT_FALSE(check.stations[0].within);
  EXPECT_NEAR(*check.stations[0].relative_error, 0.02, 1e-12);
  // allowed = rtol |T| + estimate |T| (+ no interpolation error on a linear profile).
  EXPECT_NEAR(check.stations[0].allowed_n, (1e-3 + 1e-4) * sigma_at(300.0), kRoundingN);
  EXPECT_TRUE(check.stations[1].within);
  EXPECT_FALSE(check.fairlead.has_value());
  EXPECT_EQ(check.verdict, ModeVerdict::BeyondTolerance);
  EXPECT_TRUE(check.any_failure());
}

TEST(TensionCheck, AmplitudeIsInterpolatedAsAComplexAmplitude) {
  // tau(s) = a + i b s: |tau| = sqrt(a^2 + b^2 s^2) is not linear in s, tau is.
  const double a = 3.0e4, b = 50.0;
  DynamicTension t;
  t.period_s = 10.0;
  t.s_m = Vector::LinSpaced(11, 0.0, kLength);
  t.amplitude_n.resize(11);
  t.phase_deg.resize(11);
  for (Index j = 0; j < 11; ++j) {
    const std::complex<double> tau(a, b * t.s_m[j]);
    t.amplitude_n[j] = std::abs(tau);
    t.phase_deg[j] = std::arg(tau) * 180.0 / kPi;
  }
  t.converged = true;
  t.relative_error_estimate = 0.0;
  ExternalTension other;
  other.quantity = TensionQuantity::Amplitude;
  for (double s : {45.0, 333.3, 855.0}) other.stations.push_back(at_s(s, std::hypot(a, b * s)));
  const TensionCheck check = check_external_tension(other, reference_of(t));
  for (const auto& c : check.stations) {
    EXPECT_NEAR(c.catena_n, std::hypot(a, b * c.s_m), kRoundingN) << "s = " << c.s_m;
    EXPECT_NEAR(c.catena_uncertainty_n, 0.0, kRoundingN);
  }
  EXPECT_DOUBLE_EQ(check.period_s, 10.0);
}

TEST(TensionCheck, InterpolationErrorEstimateBoundsTheTrueErrorOfACurvedProfile) {
  // sigma = s^2 on stations 0, 10, ..., 100 (L = 100): at s = 15 linear interpolation gives 250,
  // the truth is 225; the estimate is the second difference 200 / 8 = 25 = h^2 f'' / 8.
  DynamicTension t = linear_std(11, 0.0);
  t.s_m = Vector::LinSpaced(11, 0.0, 100.0);
  t.std_n = t.s_m.array().square().matrix();
  ExternalTension other;
  other.stations.push_back(at_s(15.0, 225.0));
  const TensionCheck check = check_external_tension(other, reference_of(t));
  const auto& c = check.stations.front();
  EXPECT_NEAR(c.catena_n, 250.0, 1e-12);
  EXPECT_NEAR(c.catena_uncertainty_n, 25.0, 1e-12);
  EXPECT_GE(c.catena_uncertainty_n, std::abs(c.catena_n - 225.0) - 1e-12);
  EXPECT_TRUE(c.within);  // the truth differs from Catena's interpolant by no more than its error
}

// A node-based lumped-mass code: T_N = T (1 + c / N^2) (1 + bias) at nodes i = 0..N.
ExternalTension lumped_code(double c, double bias, const std::vector<int>& segments) {
  ExternalTension other;
  for (int n : segments) {
    for (int i = 0; i <= n; ++i) {
      ExternalTensionStation station;
      station.node = i;
      station.nodes = n + 1;
      station.resolution = n;
      const double s = kLength * i / n;
      station.tension_n = sigma_at(s) * (1.0 + c / (double(n) * n)) * (1.0 + bias);
      station.origin = "N = " + std::to_string(n) + " node " + std::to_string(i);
      other.stations.push_back(station);
    }
  }
  return other;
}

TEST(TensionCheck, StudyAtSharedStationsRecoversOrderTwoAndTheBias) {
  const double bias = 0.01;
  const TensionCheck check = check_external_tension(lumped_code(3.0, bias, {10, 20, 40, 80}),
                                                    reference_of(linear_std(2001)));
  ASSERT_TRUE(check.resolution.has_value());
  EXPECT_DOUBLE_EQ(*check.resolution, 80.0);
  EXPECT_EQ(check.stations.size(), 81u);
  // Stations of N = 10 are shared by every finer mesh: 11 studies, anchor and fairlead included.
  ASSERT_EQ(check.studies.size(), 11u);
  EXPECT_EQ(check.studies.front().label, "anchor");
  EXPECT_EQ(check.studies.back().label, "fairlead");
  for (const auto& s : check.studies) {
    ASSERT_TRUE(s.study.trustworthy) << s.label << ": " << s.study.note;
    EXPECT_NEAR(*s.study.observed_order, 2.0, 1e-6) << s.label;
    EXPECT_NEAR(*s.study.bias_relative, bias, 1e-9) << s.label;
    EXPECT_EQ(s.verdict, ModeVerdict::ConvergesToWrongLimit) << s.label;
  }
  EXPECT_EQ(check.verdict, ModeVerdict::ConvergesToWrongLimit);
}

TEST(TensionCheck, UnbiasedCodeConverges) {
  ExternalCheckOptions options;
  options.rtol = 1e-3;
  const TensionCheck check = check_external_tension(lumped_code(3.0, 0.0, {10, 20, 40, 80}),
                                                    reference_of(linear_std(2001)), options);
  for (const auto& s : check.studies) {
    EXPECT_NEAR(*s.study.bias_relative, 0.0, 1e-9) << s.label;
    EXPECT_EQ(s.verdict, ModeVerdict::Converged) << s.label;  // 3 / 80^2 = 4.7e-4 < rtol
  }
  // Stations of the finest mesh without a study are within tolerance on their own.
  EXPECT_EQ(check.verdict, ModeVerdict::WithinTolerance);
  EXPECT_FALSE(check.any_failure());
}

void expect_invalid(const ExternalTension& other, const std::string& part) {
  try {
    validate_external_tension(other, kLength);
    ADD_FAILURE() << "no error, expected one naming " << part;
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(TensionCheck, BadStationsAreRejectedNamingTheRowAndColumn) {
  ExternalTension other;
  other.stations = {at_s(kLength * 1.001, 1.0)};
  other.stations.front().origin = "f.csv row 3";
  expect_invalid(other, "f.csv row 3, column 's_m'");
  other.stations = {at_s(-1.0, 1.0)};
  expect_invalid(other, "column 's_m'");
  other.stations = {at_s(1.0, -1.0)};
  expect_invalid(other, "must be finite and >= 0");
  other.stations = {at_s(1.0, NAN)};
  expect_invalid(other, "must be finite and >= 0");
  other.stations = {at_s(1.0, 1.0, 10.0), at_s(2.0, 1.0)};
  expect_invalid(other, "column 'resolution'");
  other.stations = {at_s(1.0, 1.0), at_s(1.0, 2.0)};
  expect_invalid(other, "a second station at s = 1");
  ExternalTensionStation node;
  node.node = 5;
  node.nodes = 5;
  node.origin = "row 2";
  other.stations = {node};
  expect_invalid(other, "row 2, column 'node'");
  node.nodes.reset();
  other.stations = {node};
  expect_invalid(other, "column 'nodes'");
  node.nodes = 1;
  node.node = 0;
  other.stations = {node};
  expect_invalid(other, "nodes = 1");
  other.stations = {at_s(1.0, 1.0)};
  other.period_s = 0.0;
  expect_invalid(other, "period_s");
  other.period_s.reset();
  other.stations.clear();
  expect_invalid(other, "no stations");
}

SolverOutput declined(const std::string& solver) {
  SolverOutput output;
  output.solver = solver;
  output.summary.termination = Termination::NotApplicable;
  output.summary.message = "dynamic tension: dynamic tension not computed (1 excitations asked)";
  output.summary.warnings.push_back(
      "this method has no damped forced response with linearised drag: dynamic tension not "
      "computed");
  return output;
}

SolverOutput computed(const std::string& solver, double estimate, double scale) {
  SolverOutput output;
  output.solver = solver;
  output.summary.termination = Termination::Converged;
  DynamicTension t = linear_std(101, estimate);
  t.std_n *= scale;
  output.dynamic_tension.push_back(t);
  return output;
}

TEST(TensionReferenceChoice, SaysClearlyWhenNoSolverComputedIt) {
  std::string why;
  const auto reference = tension_reference({declined("shooting"), declined("fe")},
                                           TensionQuantity::StandardDeviation, why);
  EXPECT_FALSE(reference.has_value());
  EXPECT_NE(why.find("no Catena solver computed the dynamic tension"), std::string::npos) << why;
  EXPECT_NE(why.find("shooting: did not compute"), std::string::npos) << why;
  EXPECT_NE(why.find("fe: did not compute"), std::string::npos) << why;
  EXPECT_NE(why.find("no damped forced response with linearised drag"), std::string::npos) << why;
}

TEST(TensionReferenceChoice, SmallerEstimateWinsAndTheOtherConfirms) {
  std::string why;
  const auto reference =
      tension_reference({computed("shooting", 1e-6, 1.0), computed("fe", 1e-8, 1.0 + 2e-7)},
                        TensionQuantity::StandardDeviation, why);
  ASSERT_TRUE(reference.has_value()) << why;
  EXPECT_EQ(reference->solver, "fe");
  EXPECT_NEAR(reference->cross_check_relative, 2e-7 / (1.0 + 2e-7), 1e-12);
  // A fixed point not reached is no reference.
  SolverOutput stuck = computed("fe", 1e-9, 1.0);
  stuck.dynamic_tension.front().converged = false;
  stuck.dynamic_tension.front().diagnostic = "no fixed point within 200 iterations";
  const auto only = tension_reference({computed("shooting", 1e-6, 1.0), stuck},
                                      TensionQuantity::StandardDeviation, why);
  ASSERT_TRUE(only.has_value());
  EXPECT_EQ(only->solver, "shooting");
  EXPECT_LT(only->cross_check_relative, 0.0);
  EXPECT_NE(only->reason.find("no fixed point"), std::string::npos) << only->reason;
  // A regular-motion profile asked of an irregular result is not one.
  EXPECT_FALSE(
      tension_reference({computed("shooting", 1e-6, 1.0)}, TensionQuantity::Amplitude, why));
}

}  // namespace
}  // namespace catena
