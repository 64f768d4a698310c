// SPDX-License-Identifier: MIT
// The fuzz target (see scene_fuzz_target.hpp).
#include "scene_fuzz_target.hpp"

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/io/findings_reader.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena::fuzz {
namespace {

void clamp_integer_knob(SolverKnobs& knobs, const char* name, long cap) {
  const auto found = knobs.find(name);
  if (found == knobs.end()) return;
  if (const long* value = std::get_if<long>(&found->second)) found->second = std::min(*value, cap);
}

/// The scene with its request and resolution clamped to `limits` (see FuzzLimits).
Scene cheap_scene(Scene scene, const FuzzLimits& limits) {
  SolveRequest& request = scene.request;
  request.inplane_modes = std::min(request.inplane_modes, limits.max_modes_per_plane);
  request.outofplane_modes = std::min(request.outofplane_modes, limits.max_modes_per_plane);
  request.points = std::min(request.points, limits.max_points);
  if (request.forced && request.forced->omegas_rad_s.size() > limits.max_forcing_frequencies) {
    request.forced->omegas_rad_s.resize(limits.max_forcing_frequencies);
  }
  for (auto& [name, knobs] : scene.solvers) {
    clamp_integer_knob(knobs, "elements", limits.max_fe_elements);
    clamp_integer_knob(knobs, "max_steps", limits.max_shooting_steps);
    clamp_integer_knob(knobs, "max_terms", limits.max_frobenius_terms);
  }
  return scene;
}

void check_modes(const std::optional<ModalResult>& result,
                 const std::string& solver,
                 std::vector<std::string>& violations) {
  if (!result || !result->summary.is_usable()) return;
  double previous = 0.0;
  for (const Mode& mode : result->modes) {
    const std::string where =
        solver + " " + to_string(result->plane) + " mode " + std::to_string(mode.index);
    if (!std::isfinite(mode.omega_rad_s) || mode.omega_rad_s <= 0.0) {
      violations.push_back(where + ": omega " + std::to_string(mode.omega_rad_s) +
                           " in a usable result");
    } else if (mode.omega_rad_s < previous) {
      violations.push_back(where + ": frequencies out of order in a usable result");
    }
    previous = mode.omega_rad_s;
  }
}

void check_forced(const SolverOutput& output, std::vector<std::string>& violations) {
  if (!output.summary.is_usable()) return;
  for (const ForcedResponse& response : output.forced) {
    if (response.diagnostic.empty() && !std::isfinite(response.max_abs_tension_n)) {
      violations.push_back(output.solver + " forced at " + std::to_string(response.omega_rad_s) +
                           " rad/s: non-finite response without a diagnostic in a usable result");
    }
  }
}

}  // namespace

FuzzOutcome fuzz_scene_text(const std::string& text,
                            std::uint64_t solver_choice,
                            const FuzzLimits& limits) {
  FuzzOutcome outcome;
  std::vector<Scene> scenes;
  try {
    scenes = parse_scene_text(text, "fuzz.toml");
  } catch (const Error&) {
    return outcome;  // bad input, named: what the reader must do
  }
  if (scenes.size() > limits.max_sweep_scenes) scenes.resize(limits.max_sweep_scenes);
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.findings = builtin_findings_table();
  outcome.stage = FuzzStage::StaticsFailed;
  for (const Scene& original : scenes) {
    const Scene scene = cheap_scene(original, limits);
    const std::vector<std::string> names = scene.solver_names();
    if (!names.empty()) options.only_solvers = {names[solver_choice % names.size()]};
    SceneResult result;
    try {
      result = run_scene(scene, options);
    } catch (const Error&) {
      continue;  // bad input found before any work (e.g. an invalid knob)
    }
    if (!result.error.empty()) continue;
    outcome.stage = FuzzStage::Solved;
    for (const SolverOutput& output : result.outputs) {
      check_modes(output.inplane, output.solver, outcome.violations);
      check_modes(output.outofplane, output.solver, outcome.violations);
      check_forced(output, outcome.violations);
    }
  }
  return outcome;
}

}  // namespace catena::fuzz
