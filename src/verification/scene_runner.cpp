// SPDX-License-Identifier: MIT
#include "catena/verification/scene_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "catena/core/error.hpp"
#include "verification/internal/checks.hpp"
#include "verification/internal/forced_conditioning_solve.hpp"

namespace catena {

std::string to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::Pass:
      return "PASS";
    case Verdict::Fail:
      return "FAIL";
    case Verdict::SourceDiscrepancy:
      return "SOURCE";
    case Verdict::Warn:
      return "WARN";
    case Verdict::Skipped:
      return "SKIP";
  }
  return "?";
}

int SceneResult::failed_checks() const {
  int failed = 0;
  for (const auto& check : checks) failed += check.verdict == Verdict::Fail;
  return failed;
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void record_error(SceneResult& result, SceneError kind, const std::string& message) {
  result.error = fmt::format("{}: {}", result.scene.file.string(), message);
  result.error_kind = kind;
}

// Statics, groups and the SI request, shared by every solver. False (with the error recorded)
// when the scene cannot go further.
bool prepare(SceneResult& result) {
  const Scene& scene = result.scene;
  try {
    StaticSolution statics = solve_statics(scene.problem);
    if (!statics.converged) {
      record_error(result, SceneError::NumericalFailure, statics.message);
      return false;
    }
    result.groups = compute_dimensionless_groups(scene.problem, statics);
    result.statics = std::move(statics);
    result.request = resolve_request(scene, *result.groups);
  } catch (const Error& error) {
    record_error(result, SceneError::BadInput, error.what());
    result.statics.reset();
    result.groups.reset();
    return false;
  }
  return true;
}

bool selected(const SceneRunOptions& options, const std::string& name) {
  return options.only_solvers.empty() ||
         std::find(options.only_solvers.begin(), options.only_solvers.end(), name) !=
             options.only_solvers.end();
}

void run_solvers(SceneResult& result, const SceneRunOptions& options, const RunLimits& limits) {
  const Scene& scene = result.scene;
  const SolveContext context{scene.problem, *result.statics, *result.groups, result.request,
                             &limits};
  for (const std::string& name : scene.solver_names()) {
    if (!selected(options, name)) continue;
    const SolverEntry* entry = find_solver(name);
    const auto knobs = scene.solvers.count(name) ? scene.solvers.at(name) : SolverKnobs{};
    try {
      result.outputs.push_back(run_solver(*entry, context, knobs));
    } catch (const InvalidInput& error) {
      record_error(result, SceneError::BadInput, fmt::format("solver {}: {}", name, error.what()));
      break;
    }
  }
}

void apply_perturbation(const Perturbation& perturbation, std::vector<SolverOutput>& outputs) {
  for (auto& output : outputs) {
    if (output.solver != perturbation.solver) continue;
    auto& modal = perturbation.plane == Plane::InPlane ? output.inplane : output.outofplane;
    if (!modal) continue;
    for (auto& mode : modal->modes) {
      if (mode.index == perturbation.mode) mode.omega_rad_s *= 1.0 + perturbation.relative;
    }
  }
}

}  // namespace

void SceneRunOptions::validate() const {
  if (checks && tolerances.rules().empty()) {
    throw InvalidInput(
        "SceneRunOptions::tolerances is empty while checks are asked: pass "
        "builtin_tolerance_table() "
        "or a table read by read_tolerance_file()");
  }
  if (time_limit_s) RunLimits::check_time_limit(*time_limit_s, "SceneRunOptions::time_limit_s");
}

namespace {

// The budget of one scene, from now.
RunLimits scene_limits(const SceneRunOptions& options) {
  RunLimits limits =
      options.time_limit_s ? RunLimits::time_limit(*options.time_limit_s) : RunLimits{};
  limits.progress = options.progress;
  return limits;
}

}  // namespace

SceneResult run_scene(const Scene& scene, const SceneRunOptions& options) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  const RunLimits limits = scene_limits(options);
  SceneResult result;
  result.scene = scene;
  if (!prepare(result)) {
    result.wall_time_s = seconds_since(start);
    return result;
  }
  // A request for no modes, no forcing and no motion is a statics-only scene: no solver runs.
  const SolveRequest& request = result.request;
  if (request.inplane_modes == 0 && request.outofplane_modes == 0 && !request.forced &&
      !request.motion) {
    result.wall_time_s = seconds_since(start);
    return result;
  }
  run_solvers(result, options, limits);
  if (options.perturbation) apply_perturbation(*options.perturbation, result.outputs);
  if (options.checks && result.error.empty()) {
    result.forced_conditioning =
        internal::find_forced_conditioning(result, options.tolerances, limits);
    result.checks = internal::run_checks(result, options.tolerances, options.findings);
  }
  result.wall_time_s = seconds_since(start);
  return result;
}

}  // namespace catena
