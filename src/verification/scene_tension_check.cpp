// SPDX-License-Identifier: MIT
// `catena check` on another program's dynamic tension: reference scene, run, Catena's reference,
// comparison (docs/how-to/check-dynamic-tension.md).
#include "catena/verification/scene_tension_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena {
namespace {

// Catena's stations for the reference: linear interpolation to the other program's arc lengths
// then errs by ~ (L/2000)^2 |T''| / 8, and the check adds that estimate to Catena's uncertainty.
constexpr int kReferenceStations = 2001;
// A period in the file is the scene's period when they agree to this relative difference (a
// period printed with 12 significant digits is still recognised).
constexpr double kSamePeriod = 1e-9;

double select_period(const MotionRequest& motion, const ExternalTension& tension) {
  if (!tension.period_s) {
    if (motion.periods_s.size() != 1) {
      throw InvalidInput(fmt::format(
          "{}: the scene's [request.motion] asks {} periods; give the one compared in a period_s "
          "column",
          tension.origin, motion.periods_s.size()));
    }
    return motion.periods_s.front();
  }
  for (double period : motion.periods_s) {
    if (std::abs(period - *tension.period_s) <= kSamePeriod * period) return period;
  }
  std::string asked;
  for (double period : motion.periods_s)
    asked += (asked.empty() ? "" : ", ") + fmt::format("{:g}", period);
  throw InvalidInput(fmt::format(
      "{}, column 'period_s': {:g} s is not a period of the scene's [request.motion] ({} s)",
      tension.origin, *tension.period_s, asked));
}

// The largest difference between two solvers' profiles, relative to the larger profile.
double largest_disagreement(const DynamicTension& a, const DynamicTension& b, TensionQuantity q) {
  const Vector& x = q == TensionQuantity::Amplitude ? a.amplitude_n : a.std_n;
  const Vector& y = q == TensionQuantity::Amplitude ? b.amplitude_n : b.std_n;
  if (x.size() != y.size() || x.size() == 0) return -1.0;
  const double scale = std::max(x.cwiseAbs().maxCoeff(), y.cwiseAbs().maxCoeff());
  return scale > 0.0 ? (x - y).cwiseAbs().maxCoeff() / scale : 0.0;
}

// Why a solver's output is not a reference, or "" when it is.
std::string disqualification(const SolverOutput& output, TensionQuantity quantity) {
  if (output.dynamic_tension.size() != 1) {
    std::string report =
        fmt::format("{} ({})", to_string(output.summary.termination), output.summary.message);
    for (const auto& warning : output.summary.warnings) {
      if (warning.find("dynamic tension") != std::string::npos) report += "; " + warning;
    }
    return "did not compute the dynamic tension: " + report;
  }
  const DynamicTension& t = output.dynamic_tension.front();
  if (!t.converged) {
    return fmt::format("no fixed point (residual {:.2g} after {} iterations): {}", t.residual,
                       t.iterations, t.diagnostic);
  }
  const Vector& values = quantity == TensionQuantity::Amplitude ? t.amplitude_n : t.std_n;
  if (values.size() != t.s_m.size() || t.s_m.size() < 2)
    return fmt::format("no {} along the line", to_string(quantity));
  return "";
}

}  // namespace

Scene tension_reference_scene(Scene scene, const ExternalTension& tension) {
  SolveRequest& request = scene.request;
  if (!request.motion) {
    throw InvalidInput(fmt::format(
        "{}: the scene has no [request.motion]: Catena needs the excitation the other program "
        "computed",
        tension.origin));
  }
  MotionRequest& motion = *request.motion;
  const bool irregular = motion.is_irregular();
  if (irregular != (tension.quantity == TensionQuantity::StandardDeviation)) {
    throw InvalidInput(fmt::format("{}, column '{}': the scene's [request.motion] is {}; give {}",
                                   tension.origin, to_string(tension.quantity),
                                   irregular ? "irregular" : "regular",
                                   irregular ? "tension_std_n" : "tension_amplitude_n"));
  }
  if (irregular && tension.period_s) {
    throw InvalidInput(
        fmt::format("{}, column 'period_s': the scene's motion is irregular and has no period",
                    tension.origin));
  }
  if (!irregular) motion.periods_s = {select_period(motion, tension)};
  request.inplane_modes = 0;
  request.outofplane_modes = 0;
  request.shapes = false;
  request.tension = false;
  request.forced.reset();
  request.points = kReferenceStations;
  std::map<std::string, SolverKnobs> solvers;
  for (const std::string& name : reference_solvers())
    solvers[name] = scene.solvers.count(name) ? scene.solvers.at(name) : SolverKnobs{};
  scene.solvers = solvers;
  return scene;
}

std::optional<TensionReference> tension_reference(const std::vector<SolverOutput>& outputs,
                                                  TensionQuantity quantity,
                                                  std::string& why) {
  const SolverOutput* best = nullptr;
  const SolverOutput* other = nullptr;
  std::vector<std::string> reports;
  // reference_solvers() lists the most accurate at their defaults first: the order breaks ties.
  for (const std::string& name : reference_solvers()) {
    const auto output = std::find_if(outputs.begin(), outputs.end(),
                                     [&](const SolverOutput& o) { return o.solver == name; });
    if (output == outputs.end()) {
      reports.push_back(name + ": did not run");
      continue;
    }
    const std::string disqualified = disqualification(*output, quantity);
    if (!disqualified.empty()) {
      reports.push_back(name + ": " + disqualified);
      continue;
    }
    const double estimate = output->dynamic_tension.front().relative_error_estimate;
    reports.push_back(fmt::format("{}: fixed point reached, estimate {:.2g}", name, estimate));
    const auto rank = [](double e) { return e < 0.0 ? INFINITY : e; };
    if (!best || rank(estimate) < rank(best->dynamic_tension.front().relative_error_estimate)) {
      other = best;
      best = &*output;
    } else {
      other = &*output;
    }
  }
  std::string all;
  for (const auto& report : reports) all += (all.empty() ? "" : "; ") + report;
  if (!best) {
    why = "no Catena solver computed the dynamic tension: " + all;
    return std::nullopt;
  }
  TensionReference reference;
  reference.solver = best->solver;
  reference.reason = other ? fmt::format("{} reached its fixed point with the smaller estimate: {}",
                                         best->solver, all)
                           : fmt::format("{} is the only reference solver at its fixed point: {}",
                                         best->solver, all);
  reference.tension = best->dynamic_tension.front();
  if (other) {
    reference.cross_check_relative = largest_disagreement(best->dynamic_tension.front(),
                                                          other->dynamic_tension.front(), quantity);
  }
  why.clear();
  return reference;
}

SceneTensionCheck check_scene_tension(const ExternalTension& tension,
                                      const Scene& scene,
                                      const ExternalCheckOptions& options) {
  options.validate();
  validate_external_tension(tension, scene.problem.length_m());
  SceneRunOptions run;
  run.checks = false;
  const SceneResult solved = run_scene(tension_reference_scene(scene, tension), run);
  if (solved.error_kind == SceneError::BadInput) throw InvalidInput(solved.error);
  if (!solved.error.empty()) return {std::nullopt, solved.error};
  std::string why;
  const auto reference = tension_reference(solved.outputs, tension.quantity, why);
  if (!reference) return {std::nullopt, why};
  return {check_external_tension(tension, *reference, options), ""};
}

}  // namespace catena
