// SPDX-License-Identifier: MIT
#pragma once
// Catena's damped modes of a scene for the time-series check: the exact solvers that certify
// references (reference_solvers()) run through the scene runner, the certified reference chosen
// per plane as for the frequency check, and that solver's modes kept with their damping.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/verification/scene.hpp"

namespace catena::internal {

struct DampedReference {
  Plane plane = Plane::InPlane;
  std::string solver;
  std::string reason;
  double cross_check_relative = -1.0;
  /// Lowest first, with damped frequency, damping ratio and the solver's error estimates.
  std::vector<Mode> modes;
};

/// The references of `planes` with `modes[plane]` modes each (capped at kMaxRequestModes). Throws
/// InvalidInput for bad input met while solving. Returns the references, or `error` set (the
/// statics failed, or no exact solver converged in a plane).
std::vector<DampedReference> damped_references(const Scene& scene,
                                               const std::map<Plane, int>& modes,
                                               std::string& error);

/// Catena's own error bounds on a mode's damped frequency [Hz] and damping ratio: the solver's
/// relative estimates times the values (zeta = delta / |lambda| inherits both estimates).
double frequency_error_hz(const Mode& mode);
double damping_ratio_error(const Mode& mode);

}  // namespace catena::internal
