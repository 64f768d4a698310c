// SPDX-License-Identifier: MIT
#include "catena/verification/certified_reference.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/solvers/solver_registry.hpp"

namespace catena {
namespace {

const ModalResult* plane_result(const SolverOutput& output, Plane plane) {
  const auto& result = plane == Plane::InPlane ? output.inplane : output.outofplane;
  return result ? &*result : nullptr;
}

// The largest estimate over the modes; infinite when a mode has none.
double largest_estimate(const ModalResult& result) {
  double largest = 0.0;
  for (const Mode& mode : result.modes) {
    largest = std::max(
        largest, mode.relative_error_estimate < 0.0 ? INFINITY : mode.relative_error_estimate);
  }
  return largest;
}

CertifiedReference make_reference(const SolverOutput& output,
                                  const ModalResult& result,
                                  Plane plane) {
  CertifiedReference reference;
  reference.plane = plane;
  reference.solver = output.solver;
  for (const Mode& mode : result.modes) {
    reference.modes.push_back({mode.index, mode.omega_rad_s, mode.relative_error_estimate, mode.s_m,
                               mode.u, mode.w, mode.v, mode.tension_n});
  }
  return reference;
}

double largest_disagreement(const ModalResult& a, const ModalResult& b) {
  double largest = 0.0;
  const std::size_t n = std::min(a.modes.size(), b.modes.size());
  for (std::size_t i = 0; i < n; ++i) {
    largest = std::max(largest, std::abs(a.modes[i].omega_rad_s / b.modes[i].omega_rad_s - 1.0));
  }
  return largest;
}

}  // namespace

std::optional<CertifiedReference> certified_reference(const std::vector<SolverOutput>& outputs,
                                                      Plane plane,
                                                      std::string& why) {
  const SolverOutput* best = nullptr;
  const ModalResult* best_result = nullptr;
  const ModalResult* other_result = nullptr;
  double best_estimate = INFINITY;
  std::vector<std::string> reports;
  // The solvers that may certify a reference, most accurate at their defaults first: the order
  // breaks ties (SolverEntry::certifies_references).
  for (const std::string& name : reference_solvers()) {
    const auto output = std::find_if(outputs.begin(), outputs.end(),
                                     [&](const SolverOutput& o) { return o.solver == name; });
    const ModalResult* result = output == outputs.end() ? nullptr : plane_result(*output, plane);
    if (!result) {
      reports.push_back(fmt::format(
          "{}: did not run ({})", name,
          output == outputs.end() ? std::string("not requested") : output->summary.message));
      continue;
    }
    if (result->summary.termination != Termination::Converged || result->modes.empty()) {
      reports.push_back(fmt::format("{}: {} ({})", name, to_string(result->summary.termination),
                                    result->summary.message));
      continue;
    }
    const double estimate = largest_estimate(*result);
    reports.push_back(fmt::format("{}: converged, {} modes, largest estimate {:.2g}", name,
                                  result->modes.size(), estimate));
    if (estimate < best_estimate || !best) {
      if (best_result) other_result = best_result;
      best = &*output;
      best_result = result;
      best_estimate = estimate;
    } else {
      other_result = result;
    }
  }
  std::string joined;
  for (const auto& report : reports) joined += (joined.empty() ? "" : "; ") + report;
  if (!best) {
    why = fmt::format("no exact solver converged in {}: {}", to_string(plane), joined);
    return std::nullopt;
  }
  CertifiedReference reference = make_reference(*best, *best_result, plane);
  reference.reason = fmt::format("{} (the converged solver with the smaller estimate) -- {}",
                                 best->solver, joined);
  if (other_result)
    reference.cross_check_relative = largest_disagreement(*best_result, *other_result);
  return reference;
}

}  // namespace catena
