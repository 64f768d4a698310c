// SPDX-License-Identifier: MIT
// The checks every solver's results pass in the solver skeleton: each mode rule, the valid prefix
// kept, the status and message; forced responses scaled by the amplitude, overflow and silent
// non-finite values turned into diagnostics.
#include "solvers/common/result_validation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace catena::internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Modes 1..count at omega = 1, 2, ... rad/s with estimates 1e-9, all counted.
ModalResult valid_result(int count) {
  ModalResult result;
  for (int i = 1; i <= count; ++i) {
    Mode mode;
    mode.index = i;
    mode.omega_rad_s = i;
    mode.frequency_hz = i / 6.283185307179586;
    mode.relative_error_estimate = 1e-9;
    result.modes.push_back(mode);
  }
  result.proved_count_below_top = count;
  result.summary.termination = Termination::Converged;
  result.summary.message = "Converged: all";
  return result;
}

struct Violation {
  std::string name;
  std::function<void(ModalResult&)> apply;
  std::size_t kept;        // the valid prefix
  std::string in_message;  // names the mode and the property
};

void expect_rejected(const Violation& violation) {
  ModalResult result = valid_result(4);
  result.proved_count_below_top = -1;  // count rule tested separately
  violation.apply(result);
  validate_modal_result(result, 4);
  EXPECT_EQ(result.modes.size(), violation.kept) << violation.name;
  EXPECT_EQ(result.summary.termination,
            violation.kept > 0 ? Termination::NoConvergence : Termination::NumericalFailure)
      << violation.name;
  EXPECT_NE(result.summary.message.find(violation.in_message), std::string::npos)
      << violation.name << ": " << result.summary.message;
  EXPECT_NE(result.summary.message.find("Converged: all"), std::string::npos)
      << "keeps the solver's own words";
  ASSERT_FALSE(result.summary.warnings.empty()) << violation.name;
}

TEST(ValidateModalResult, AValidResultIsUntouched) {
  ModalResult result = valid_result(5);
  validate_modal_result(result, 5);
  EXPECT_EQ(result.modes.size(), 5u);
  EXPECT_EQ(result.summary.termination, Termination::Converged);
  EXPECT_EQ(result.summary.message, "Converged: all");
  EXPECT_TRUE(result.summary.warnings.empty());
  // Fewer than asked is the solver's own business (its status says so): not a violation.
  ModalResult fewer = valid_result(3);
  validate_modal_result(fewer, 6);
  EXPECT_EQ(fewer.summary.termination, Termination::Converged);
}

TEST(ValidateModalResult, EachViolatedPropertyIsNamedAndTheValidPrefixKept) {
  const std::vector<Violation> violations = {
      {"negative omega",
       [](ModalResult& r) {
         r.modes[2].omega_rad_s = -0.525;
         r.modes[3].omega_rad_s = 4;
       },
       2, "mode 3: omega = -0.525 rad/s is not a finite positive frequency"},
      {"zero omega first", [](ModalResult& r) { r.modes[0].omega_rad_s = 0.0; }, 0, "mode 1"},
      {"NaN omega", [](ModalResult& r) { r.modes[1].omega_rad_s = std::nan(""); }, 1, "mode 2"},
      {"infinite omega", [](ModalResult& r) { r.modes[3].omega_rad_s = kInf; }, 3, "mode 4"},
      {"descending", [](ModalResult& r) { r.modes[2].omega_rad_s = 1.5; }, 2, "strictly ascending"},
      {"tie", [](ModalResult& r) { r.modes[3].omega_rad_s = 3.0; }, 3,
       "mode 4: omega = 3 rad/s is not above mode 3"},
      {"index gap", [](ModalResult& r) { r.modes[1].index = 3; }, 1, "indices must be 1, 2, 3"},
      {"NaN estimate", [](ModalResult& r) { r.modes[1].relative_error_estimate = std::nan(""); }, 1,
       "mode 2: relative error estimate"},
      {"negative estimate other than -1",
       [](ModalResult& r) { r.modes[2].relative_error_estimate = -0.5; }, 2,
       "neither finite and >= 0 nor -1"},
      {"non-finite Hz", [](ModalResult& r) { r.modes[0].frequency_hz = kInf; }, 0,
       "unit conversion"},
      {"non-finite shape", [](ModalResult& r) { r.modes[1].w = Vector::Constant(3, std::nan("")); },
       1, "mode 2: its shape"},
      {"non-finite tension", [](ModalResult& r) { r.modes[3].max_abs_tension_n = kInf; }, 3,
       "mode 4: its shape"},
      {"non-finite imaginary shape",
       [](ModalResult& r) { r.modes[2].w_imag = Vector::Constant(3, kInf); }, 2,
       "mode 3: its shape"},
      {"growing mode", [](ModalResult& r) { r.modes[1].decay_rate_1_s = -0.1; }, 1,
       "mode 2: decay rate -0.1"},
      {"damping ratio not delta / |lambda|",
       [](ModalResult& r) {
         r.modes[0].decay_rate_1_s = 0.1;
         r.modes[0].damping_ratio = 0.2;
       },
       0, "mode 1: damping ratio 0.2"},
      {"NaN decay estimate",
       [](ModalResult& r) { r.modes[3].decay_rate_error_estimate = std::nan(""); }, 3,
       "decay-rate error estimate"},
  };
  for (const Violation& violation : violations) expect_rejected(violation);
}

TEST(ValidateModalResult, EqualFrequenciesAreAcceptedOnlyWithinAProvedMultipleRoot) {
  ModalResult result = valid_result(4);
  result.modes[2].omega_rad_s = 2.0;
  result.modes[1].multiplicity = result.modes[2].multiplicity = 2;
  validate_modal_result(result, 4);
  EXPECT_EQ(result.summary.termination, Termination::Converged) << result.summary.message;
  EXPECT_EQ(result.modes.size(), 4u);
  ModalResult one_sided = valid_result(4);
  one_sided.modes[2].omega_rad_s = 2.0;
  one_sided.modes[2].multiplicity = 2;
  validate_modal_result(one_sided, 4);
  EXPECT_EQ(one_sided.modes.size(), 2u);
}

TEST(ValidateModalResult, NoneAsAnEstimateIsAccepted) {
  ModalResult result = valid_result(3);
  result.modes[1].relative_error_estimate = -1.0;
  validate_modal_result(result, 3);
  EXPECT_EQ(result.summary.termination, Termination::Converged);
}

TEST(ValidateModalResult, MoreModesThanAskedKeepsThoseAsked) {
  ModalResult result = valid_result(5);
  result.proved_count_below_top = -1;
  validate_modal_result(result, 3);
  EXPECT_EQ(result.modes.size(), 3u);
  EXPECT_EQ(result.summary.termination, Termination::NoConvergence);
  EXPECT_NE(result.summary.message.find("5 modes returned where 3 were asked"), std::string::npos);
}

// The counting argument must cover exactly the returned set; when it does not, a root was skipped
// somewhere below the top and no index is known to be right.
TEST(ValidateModalResult, ACountThatDoesNotCoverTheReturnedSetFailsThePlane) {
  for (int proved : {3, 5}) {
    ModalResult result = valid_result(4);
    result.proved_count_below_top = proved;
    validate_modal_result(result, 4);
    EXPECT_TRUE(result.modes.empty());
    EXPECT_EQ(result.summary.termination, Termination::NumericalFailure);
    EXPECT_NE(result.summary.message.find(std::to_string(proved) + " eigenvalues"),
              std::string::npos);
  }
}

TEST(ValidateModalResult, AWorseStatusIsKept) {
  ModalResult result = valid_result(3);
  result.summary.termination = Termination::NumericalFailure;
  result.modes[2].omega_rad_s = -1.0;
  result.proved_count_below_top = -1;
  validate_modal_result(result, 3);
  EXPECT_EQ(result.summary.termination, Termination::NumericalFailure);
}

ForcedOutcome unit_outcome(double unit_tension_n) {
  ForcedOutcome outcome;
  ForcedResponse response;
  response.omega_rad_s = 0.1;
  response.s_m = Vector::LinSpaced(3, 0.0, 2.0);
  response.u = Vector::Constant(3, 0.5);
  response.w = Vector::Constant(3, 1.0);
  response.tension_n = Vector::Constant(3, unit_tension_n);
  response.max_abs_tension_n = unit_tension_n;
  response.relative_error_estimate = 1e-8;
  outcome.responses.push_back(response);
  outcome.summary.termination = Termination::Converged;
  outcome.summary.message = "1 of 1 forced frequencies";
  return outcome;
}

TEST(ScaleForcedOutcome, ScalesByThePowerOfTwoLeftOutOfTheMantissa) {
  // 0.75 m = 0.75 x 2^0, 3 m = 0.75 x 2^2: the response at 0.75 scaled by 4, exactly.
  EXPECT_EQ(amplitude_mantissa(0.75), 0.75);
  EXPECT_EQ(amplitude_mantissa(3.0), 0.75);
  EXPECT_EQ(amplitude_mantissa(0.01), 0.64);
  ForcedOutcome outcome = unit_outcome(0.3);
  scale_forced_outcome(outcome, 3.0);
  const ForcedResponse& response = outcome.responses[0];
  EXPECT_EQ(response.max_abs_tension_n, 1.2);
  EXPECT_EQ(response.tension_n[1], 1.2);
  EXPECT_EQ(response.u[0], 2.0);
  EXPECT_EQ(response.w[2], 4.0);
  EXPECT_EQ(response.s_m[2], 2.0);
  EXPECT_EQ(response.relative_error_estimate, 1e-8);
  EXPECT_EQ(outcome.summary.termination, Termination::Converged);
}

TEST(ScaleForcedOutcome, AnOverflowBecomesADiagnosticNamingTheAmplitude) {
  // 1e308 = 0.5563 x 2^1024: a response of 10 N at the mantissa is 1.8e309 N.
  ForcedOutcome outcome = unit_outcome(10.0);
  scale_forced_outcome(outcome, 1e308);
  const ForcedResponse& response = outcome.responses[0];
  EXPECT_NE(response.diagnostic.find("amplitude 1e+308 m overflows"), std::string::npos)
      << response.diagnostic;
  EXPECT_EQ(response.tension_n.size(), 0);
  EXPECT_EQ(response.max_abs_tension_n, 0.0);
  EXPECT_EQ(response.s_m.size(), 3);
  EXPECT_EQ(outcome.summary.termination, Termination::NoConvergence);
  // 0.5 N and 0.5 m at the mantissa are still representable: 9.0e307.
  ForcedOutcome small = unit_outcome(0.5);
  small.responses[0].w.setConstant(0.5);
  scale_forced_outcome(small, 1e308);
  EXPECT_TRUE(small.responses[0].diagnostic.empty());
  EXPECT_DOUBLE_EQ(small.responses[0].max_abs_tension_n, 0.5 / amplitude_mantissa(1e308) * 1e308);
}

TEST(ValidateForcedOutcome, ASilentNonFiniteResponseGetsADiagnostic) {
  ForcedOutcome outcome = unit_outcome(1.0);
  outcome.responses[0].w[1] = std::nan("");
  validate_forced_outcome(outcome);
  EXPECT_NE(outcome.responses[0].diagnostic.find("non-finite response without a diagnostic"),
            std::string::npos);
  EXPECT_EQ(outcome.responses[0].w.size(), 0);
  EXPECT_EQ(outcome.summary.termination, Termination::NoConvergence);
}

TEST(ValidateForcedOutcome, ADiagnosedResponseKeepsItsDiagnosticAndStatus) {
  ForcedOutcome outcome = unit_outcome(kInf);
  outcome.responses[0].diagnostic = "resonance";
  validate_forced_outcome(outcome);
  EXPECT_EQ(outcome.responses[0].diagnostic, "resonance");
  EXPECT_EQ(outcome.responses[0].max_abs_tension_n, 0.0);
  EXPECT_EQ(outcome.summary.termination, Termination::Converged);
  ForcedOutcome fine = unit_outcome(2.0);
  validate_forced_outcome(fine);
  EXPECT_TRUE(fine.responses[0].diagnostic.empty());
  EXPECT_EQ(fine.responses[0].max_abs_tension_n, 2.0);
}

}  // namespace
}  // namespace catena::internal
