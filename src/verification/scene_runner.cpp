#include "catena/verification/scene_runner.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>

#include "catena/core/error.hpp"
#include "verification/internal/checks.hpp"

namespace catena {

std::string to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::Pass: return "PASS";
    case Verdict::Fail: return "FAIL";
    case Verdict::SourceDiscrepancy: return "SOURCE";
    case Verdict::Warn: return "WARN";
    case Verdict::Skipped: return "SKIP";
  }
  return "?";
}

int SceneResult::failed_checks() const {
  int failed = 0;
  for (const auto& check : checks) failed += check.verdict == Verdict::Fail;
  return failed;
}

SceneResult run_scene(const Scene& scene, const SceneRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SceneResult result;
  result.scene = scene;
  try {
    result.statics = solve_statics(scene.problem);
    result.groups = compute_dimensionless_groups(scene.problem, *result.statics);
    result.request = resolve_request(scene, *result.groups);
  } catch (const Error& error) {
    result.error = fmt::format("{}: {}", scene.file.string(), error.what());
    result.statics.reset();
    result.groups.reset();
    result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

  const SolveContext context{scene.problem, *result.statics, *result.groups, result.request};
  for (const std::string& name : scene.solver_names()) {
    if (!options.only_solvers.empty() &&
        std::find(options.only_solvers.begin(), options.only_solvers.end(), name) ==
            options.only_solvers.end()) {
      continue;
    }
    const SolverEntry* entry = find_solver(name);
    const auto knobs = scene.solvers.count(name) ? scene.solvers.at(name) : SolverKnobs{};
    try {
      result.outputs.push_back(run_solver(*entry, context, knobs));
    } catch (const InvalidInput& error) {
      result.error = fmt::format("{}: solver {}: {}", scene.file.string(), name, error.what());
      break;
    }
  }
  if (options.perturbation) {
    for (auto& output : result.outputs) {
      if (output.solver != options.perturbation->solver) continue;
      auto& modal = options.perturbation->plane == Plane::InPlane ? output.inplane : output.outofplane;
      if (!modal) continue;
      for (auto& mode : modal->modes) {
        if (mode.index == options.perturbation->mode) mode.omega_rad_s *= 1.0 + options.perturbation->relative;
      }
    }
  }
  if (options.checks && result.error.empty()) result.checks = internal::run_checks(result);
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace catena
