// SPDX-License-Identifier: MIT
// The checks every solver's results pass in the solver skeleton: see result_validation.hpp.
#include "solvers/common/result_validation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <optional>

namespace catena::internal {
namespace {

bool is_estimate(double relative_error) {
  return std::isfinite(relative_error) && (relative_error >= 0.0 || relative_error == -1.0);
}

// -1 means "not asked" for max_abs_tension_n and modal_mass_kg.
bool is_finite_or_unset(double value) {
  return std::isfinite(value) && (value >= 0.0 || value == -1.0);
}

bool arrays_finite(const Mode& mode) {
  return mode.s_m.allFinite() && mode.u.allFinite() && mode.w.allFinite() && mode.v.allFinite() &&
         mode.tension_n.allFinite() && mode.u_imag.allFinite() && mode.w_imag.allFinite() &&
         mode.v_imag.allFinite() && mode.tension_imag_n.allFinite();
}

// A damped root: delta finite and >= 0 (a passive line does not grow), zeta = delta / |lambda|
// in [0, 1] and consistent with omega and delta, and the decay estimate finite and >= 0 or -1.
std::optional<std::string> damping_violation(const Mode& mode) {
  const double delta = mode.decay_rate_1_s;
  const double zeta = mode.damping_ratio;
  if (!std::isfinite(delta) || delta < 0.0)
    return fmt::format("mode {}: decay rate {} 1/s is not finite and >= 0", mode.index, delta);
  const double modulus = std::hypot(delta, mode.omega_rad_s);
  const double expected = modulus > 0.0 ? delta / modulus : 0.0;
  if (!std::isfinite(zeta) || zeta < 0.0 || zeta > 1.0 ||
      std::abs(zeta - expected) > 1e-12 * std::max(1.0, expected))
    return fmt::format("mode {}: damping ratio {} is not delta / |lambda| = {}", mode.index, zeta,
                       expected);
  if (!is_estimate(mode.decay_rate_error_estimate))
    return fmt::format("mode {}: decay-rate error estimate {} is neither finite and >= 0 nor -1",
                       mode.index, mode.decay_rate_error_estimate);
  return std::nullopt;
}

// What is wrong with the mode at `position` (0-based), given the one before it; nullopt if
// nothing.
std::optional<std::string> mode_violation(const Mode& mode,
                                          std::size_t position,
                                          const Mode* previous) {
  const auto expected = static_cast<int>(position) + 1;
  if (mode.index != expected)
    return fmt::format("mode at position {} has index {} (indices must be 1, 2, 3, ...)", expected,
                       mode.index);
  const double omega = mode.omega_rad_s;
  if (!std::isfinite(omega) || !(omega > 0.0))
    return fmt::format("mode {}: omega = {} rad/s is not a finite positive frequency", mode.index,
                       omega);
  if (!std::isfinite(mode.frequency_hz) || !std::isfinite(mode.k_l_over_pi) ||
      (mode.gale_ratio && !std::isfinite(*mode.gale_ratio)))
    return fmt::format("mode {}: a frequency unit conversion of omega = {} rad/s is not finite",
                       mode.index, omega);
  // Within a multiple root the solver proved, the modes share one frequency.
  const bool proved_multiple = previous && mode.multiplicity > 1 && previous->multiplicity > 1 &&
                               omega == previous->omega_rad_s;
  if (previous && !(omega > previous->omega_rad_s) && !proved_multiple)
    return fmt::format(
        "mode {}: omega = {:.12g} rad/s is not above mode {} ({:.12g} rad/s): frequencies must be "
        "strictly ascending",
        mode.index, omega, previous->index, previous->omega_rad_s);
  if (!is_estimate(mode.relative_error_estimate))
    return fmt::format(
        "mode {}: relative error estimate {} is neither finite and >= 0 nor -1 (none)", mode.index,
        mode.relative_error_estimate);
  if (!arrays_finite(mode) || !is_finite_or_unset(mode.max_abs_tension_n) ||
      !is_finite_or_unset(mode.modal_mass_kg))
    return fmt::format("mode {}: its shape, tension or modal mass holds a non-finite value",
                       mode.index);
  return damping_violation(mode);
}

// The first violation of the per-mode rules and of the requested count, with the length of the
// valid prefix.
std::optional<std::string> prefix_violation(const ModalResult& result,
                                            int requested,
                                            std::size_t& prefix) {
  const std::vector<Mode>& modes = result.modes;
  for (prefix = 0; prefix < modes.size(); ++prefix) {
    if (auto why = mode_violation(modes[prefix], prefix, prefix ? &modes[prefix - 1] : nullptr))
      return why;
  }
  if (modes.size() > static_cast<std::size_t>(std::max(requested, 0))) {
    prefix = static_cast<std::size_t>(std::max(requested, 0));
    return fmt::format("{} modes returned where {} were asked", modes.size(), requested);
  }
  return std::nullopt;
}

std::optional<std::string> count_violation(const ModalResult& result) {
  const int proved = result.proved_count_below_top;
  const auto returned = static_cast<int>(result.modes.size());
  if (proved < 0 || proved == returned) return std::nullopt;
  return fmt::format(
      "the counting argument proves {} eigenvalues at or below the top returned frequency, but {} "
      "modes were "
      "returned: a root was skipped or returned twice, so the mode indices are not proved",
      proved, returned);
}

bool response_finite(const ForcedResponse& response) {
  return std::isfinite(response.max_abs_tension_n) && response.max_abs_tension_n >= 0.0 &&
         is_estimate(response.relative_error_estimate) && response.s_m.allFinite() &&
         response.u.allFinite() && response.w.allFinite() && response.v.allFinite() &&
         response.tension_n.allFinite() && response.u_imag.allFinite() &&
         response.w_imag.allFinite() && response.v_imag.allFinite() &&
         response.tension_imag_n.allFinite();
}

// A response without a finite answer keeps its frequency and stations, and says why.
void clear_response(ForcedResponse& response, std::string diagnostic) {
  ForcedResponse cleared;
  cleared.omega_rad_s = response.omega_rad_s;
  cleared.s_m = response.s_m.allFinite() ? response.s_m : Vector();
  cleared.diagnostic = std::move(diagnostic);
  response = std::move(cleared);
}

}  // namespace

void reject_part(SolverSummary& summary, Termination termination, const std::string& reason) {
  const bool worse = summary.termination == Termination::Converged ||
                     summary.termination == Termination::NotApplicable ||
                     (summary.termination == Termination::NoConvergence &&
                      termination == Termination::NumericalFailure);
  if (worse) summary.termination = termination;
  summary.message =
      fmt::format("Result rejected: {} (the solver reported: {})", reason, summary.message);
  summary.warnings.push_back("result rejected: " + reason);
}

void validate_modal_result(ModalResult& result, int requested) {
  if (auto why = count_violation(result)) {
    result.modes.clear();
    reject_part(result.summary, Termination::NumericalFailure, *why);
    return;
  }
  std::size_t prefix = 0;
  if (auto why = prefix_violation(result, requested, prefix)) {
    const std::size_t returned = result.modes.size();
    result.modes.resize(prefix);
    if (result.proved_count_below_top >= 0) result.proved_count_below_top = -1;
    reject_part(
        result.summary, prefix > 0 ? Termination::NoConvergence : Termination::NumericalFailure,
        fmt::format("{}; kept the {} modes below it of {} returned", *why, prefix, returned));
  }
}

double amplitude_mantissa(double amplitude_m) {
  int exponent = 0;
  return std::frexp(amplitude_m, &exponent);
}

void scale_forced_outcome(ForcedOutcome& outcome, double amplitude_m) {
  int exponent = 0;
  const double mantissa = std::frexp(amplitude_m, &exponent);
  const auto scale = [exponent](double x) { return std::ldexp(x, exponent); };
  int overflowed = 0;
  for (ForcedResponse& response : outcome.responses) {
    const bool was_finite = response_finite(response);
    const double per_metre = response.max_abs_tension_n / mantissa;
    for (Vector* values :
         {&response.u, &response.w, &response.v, &response.tension_n, &response.u_imag,
          &response.w_imag, &response.v_imag, &response.tension_imag_n})
      *values = values->unaryExpr(scale);
    response.max_abs_tension_n = scale(response.max_abs_tension_n);
    if (!was_finite || response_finite(response)) continue;
    ++overflowed;
    clear_response(response,
                   fmt::format("the response to amplitude {:.6g} m overflows double precision "
                               "(max |tau| = {:.6g} N per metre of amplitude): not representable",
                               amplitude_m, per_metre));
    outcome.summary.warnings.push_back(fmt::format("forced response at {:.10g} rad/s: {}",
                                                   response.omega_rad_s, response.diagnostic));
  }
  if (overflowed > 0)
    reject_part(outcome.summary, Termination::NoConvergence,
                fmt::format("{} of {} forced responses overflow at amplitude {:.6g} m", overflowed,
                            outcome.responses.size(), amplitude_m));
}

void validate_forced_outcome(ForcedOutcome& outcome) {
  int silent = 0;
  for (ForcedResponse& response : outcome.responses) {
    if (response_finite(response)) continue;
    // A diagnostic already explains the missing answer; its leftover values are only cleared.
    if (!response.diagnostic.empty()) {
      clear_response(response, response.diagnostic);
      continue;
    }
    ++silent;
    clear_response(response,
                   fmt::format("non-finite response without a diagnostic (max |tau| = {})",
                               response.max_abs_tension_n));
    outcome.summary.warnings.push_back(fmt::format("forced response at {:.10g} rad/s: {}",
                                                   response.omega_rad_s, response.diagnostic));
  }
  if (silent > 0)
    reject_part(outcome.summary, Termination::NoConvergence,
                fmt::format("{} of {} forced responses were not finite and had no diagnostic",
                            silent, outcome.responses.size()));
}

}  // namespace catena::internal
