// SPDX-License-Identifier: MIT
// The damped modes of the frobenius solver: see frobenius_damped_modes.hpp.
#include "solvers/frobenius/frobenius_damped_modes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <complex>

#include "solvers/common/mode_tools.hpp"

namespace catena::internal {

double gale_drag(double c_n_s_per_m2, const CableUnits& units) {
  return c_n_s_per_m2 / (units.mass_kg_per_m * units.frequency_rad_s);
}

namespace {

std::complex<double> physical(const DampedComplex& lambda, const CableUnits& units) {
  return {static_cast<double>(lambda.real()) * units.frequency_rad_s,
          static_cast<double>(lambda.imag()) * units.frequency_rad_s};
}

void summarise(const DampedRoots& found,
               int count,
               double accuracy_target,
               double worst,
               ModalResult& result) {
  const char* plane = to_string(result.plane);
  // Long double carries 19 digits: a boundary matrix whose series cancel more than 1e11 keeps
  // fewer than the target's.
  const bool digits = found.cancellation <= 1e11;
  const bool converged = static_cast<int>(found.modes.size()) == count && found.complete &&
                         !found.truncated && digits && worst <= accuracy_target;
  SolverSummary& summary = result.summary;
  summary.accuracy_target = accuracy_target;
  summary.termination = converged ? Termination::Converged
                                  : (found.modes.empty() ? Termination::NumericalFailure
                                                         : Termination::NoConvergence);
  summary.message = fmt::format(
      "{}: {} of {} damped {} modes ({} overdamped roots), max relative error estimate of "
      "omega_d and delta {:g} {} {:g}",
      converged ? "Converged" : "Not converged", found.modes.size(), count, plane,
      found.overdamped.size(), worst, converged ? "<=" : "vs", accuracy_target);
  summary.resolution = fmt::format(
      "complex long double series, up to {} terms over {} expansion centres, {} determinant "
      "evaluations",
      found.terms, found.centres, found.evaluations);
  summary.iterations = found.terms;
  summary.operations = found.evaluations;
  summary.max_error_estimate = worst;
  summary.notes = found.notes;
  summary.warnings = found.warnings;
  if (!digits)
    summary.warnings.push_back(fmt::format(
        "the series cancel by {:.3g} at the boundary: complex long double keeps fewer digits "
        "than asked",
        found.cancellation));
  if (found.counted != found.expected)
    summary.warnings.push_back(fmt::format(
        "the argument principle counts {} roots where the continuation found {}: the count of "
        "damped modes is not proved",
        found.counted, found.expected));
}

}  // namespace

ModalResult damped_modal_result(const DampedSetup& setup,
                                int count,
                                const RootSettings& settings,
                                const ModeFieldRequest& fields,
                                const CableUnits& units,
                                const DimensionlessGroups& groups,
                                double accuracy_target) {
  const DampedRoots found = find_damped_roots(setup, count, settings);
  ModalResult result;
  result.plane = setup.plane.inplane ? Plane::InPlane : Plane::OutOfPlane;
  double worst = 0.0;
  for (std::size_t i = 0; i < found.modes.size(); ++i) {
    const DampedRoot& root = found.modes[i];
    Mode mode;
    mode.index = static_cast<int>(i) + 1;
    set_damped_root(mode, physical(root.lambda, units), groups);
    mode.relative_error_estimate = root.omega_error;
    mode.decay_rate_error_estimate = root.delta_error;
    worst = std::max({worst, root.omega_error, root.delta_error});
    add_damped_mode_fields(mode, setup, root.lambda, fields, units);
    result.modes.push_back(mode);
  }
  for (std::size_t i = 0; i < found.overdamped.size(); ++i) {
    const DampedRoot& root = found.overdamped[i];
    Mode mode;
    mode.index = static_cast<int>(i) + 1;
    set_damped_root(mode, physical(root.lambda, units), groups);
    mode.damping_ratio = 1.0;
    mode.relative_error_estimate = root.delta_error;
    mode.decay_rate_error_estimate = root.delta_error;
    add_damped_mode_fields(mode, setup, root.lambda, fields, units);
    result.overdamped.push_back(mode);
  }
  if (found.counted >= 0 && found.counted == found.expected)
    result.proved_count_below_top = static_cast<int>(result.modes.size());
  summarise(found, count, accuracy_target, worst, result);
  return result;
}

}  // namespace catena::internal
