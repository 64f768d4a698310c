// SPDX-License-Identifier: MIT
#include "verification/internal/timeseries_reference.hpp"

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/verification/certified_reference.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena::internal {
namespace {

Scene reference_scene(Scene scene, const std::map<Plane, int>& modes) {
  SolveRequest& request = scene.request;
  const auto count = [&](Plane plane) {
    const auto it = modes.find(plane);
    return it == modes.end() ? 0 : std::min(it->second, kMaxRequestModes);
  };
  request.inplane_modes = count(Plane::InPlane);
  request.outofplane_modes = count(Plane::OutOfPlane);
  request.shapes = false;
  request.tension = false;
  request.forced.reset();
  request.motion.reset();
  std::map<std::string, SolverKnobs> solvers;
  for (const std::string& name : reference_solvers())  // the certified reference's candidates
    solvers[name] = scene.solvers.count(name) ? scene.solvers.at(name) : SolverKnobs{};
  scene.solvers = solvers;
  return scene;
}

}  // namespace

std::vector<DampedReference> damped_references(const Scene& scene,
                                               const std::map<Plane, int>& modes,
                                               std::string& error) {
  SceneRunOptions run;
  run.checks = false;
  const SceneResult solved = run_scene(reference_scene(scene, modes), run);
  if (solved.error_kind == SceneError::BadInput) throw InvalidInput(solved.error);
  error = solved.error;
  if (!error.empty()) return {};
  std::vector<DampedReference> references;
  for (const auto& [plane, count] : modes) {
    std::string why;
    const auto certified = certified_reference(solved.outputs, plane, why);
    if (!certified) {
      error = "no certified reference: " + why;
      return {};
    }
    // certified_reference() keeps what the frequency check compares; the damping is in the
    // chosen solver's own modes.
    const auto output =
        std::find_if(solved.outputs.begin(), solved.outputs.end(),
                     [&](const SolverOutput& o) { return o.solver == certified->solver; });
    const auto& result = plane == Plane::InPlane ? output->inplane : output->outofplane;
    references.push_back({plane, certified->solver, certified->reason,
                          certified->cross_check_relative, result->modes});
  }
  return references;
}

double frequency_error_hz(const Mode& mode) {
  return std::max(mode.relative_error_estimate, 0.0) * mode.frequency_hz;
}

double damping_ratio_error(const Mode& mode) {
  if (mode.damping_ratio == 0.0) return 0.0;
  // zeta = delta / sqrt(delta^2 + omega^2): its relative error is at most the sum of those of
  // delta and omega. A solver without a separate decay-rate estimate gives omega's for both.
  const double omega = std::max(mode.relative_error_estimate, 0.0);
  const double delta =
      mode.decay_rate_error_estimate >= 0.0 ? mode.decay_rate_error_estimate : omega;
  return (delta + omega) * mode.damping_ratio;
}

}  // namespace catena::internal
