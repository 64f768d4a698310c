// SPDX-License-Identifier: MIT
#include "catena/verification/mutation.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <set>

#include "verification/internal/checks.hpp"
#include "verification/internal/dynamic_tension_checks.hpp"
#include "verification/internal/mode_mix.hpp"
#include "verification/internal/parallel_for.hpp"

namespace catena {

std::string to_string(MutatedQuantity quantity) {
  switch (quantity) {
    case MutatedQuantity::Frequency:
      return "frequency";
    case MutatedQuantity::Shape:
      return "shape";
    case MutatedQuantity::ForcedTension:
      return "forced-tension";
    case MutatedQuantity::DecayRate:
      return "decay-rate";
    case MutatedQuantity::DynamicTension:
      return "dynamic-tension";
  }
  return "?";
}

double frequency_accuracy_target(const std::string& solver,
                                 const SolverKnobs& knobs,
                                 const Mode& mode) {
  const SolverEntry* entry = find_solver(solver);
  if (!entry) return 0.0;
  // An exact solver's own promise (the function its summaries' accuracy_target comes from,
  // docs/reference/verdicts.md, "Declared misses"); a model's accuracy is its model error, which
  // its estimate states.
  if (entry->accuracy_target) return entry->accuracy_target(knobs);
  if (entry->kind == SolverKind::Model) return std::max(0.0, mode.relative_error_estimate);
  return 0.0;
}

double decay_rate_accuracy_target(const std::string& solver,
                                  const SolverKnobs& knobs,
                                  const Mode& mode) {
  const SolverEntry* entry = find_solver(solver);
  if (!entry) return 0.0;
  if (entry->accuracy_target) return entry->accuracy_target(knobs);
  if (entry->kind == SolverKind::Model) return std::max(0.0, mode.decay_rate_error_estimate);
  return 0.0;
}

namespace {

const char* plane_name(Plane plane) {
  return plane == Plane::InPlane ? "in-plane" : "out-of-plane";
}

std::optional<ModalResult>& modal_of(SolverOutput& output, Plane plane) {
  return plane == Plane::InPlane ? output.inplane : output.outofplane;
}

std::string check_key(const CheckResult& check) {
  return fmt::format("{}|{}|{}|{}", check.check, check.compare, check.plane, check.mode);
}

// One scene's mutations: a working copy of its results, mutated and restored one result at a
// time, and the checks that failed before any mutation.
class SceneMutator {
 public:
  SceneMutator(const SceneResult& result, const SceneRunOptions& options)
      : work_(result), options_(options) {
    family_ = result.scene.file.parent_path().filename().string();
    for (const auto& check : run_checks()) {
      if (check.verdict == Verdict::Fail) baseline_failures_.insert(check_key(check));
    }
  }

  SceneResult& work() { return work_; }
  const SceneResult& work() const { return work_; }
  const SceneRunOptions& options() const { return options_; }
  std::vector<MutationOutcome>& outcomes() { return outcomes_; }

  // Runs the checks on the present (mutated) state and records whether a check went to FAIL.
  void record(const std::string& solver,
              MutatedQuantity quantity,
              const std::string& plane,
              int mode,
              double size,
              double estimate,
              bool exact_witness) {
    MutationOutcome outcome{work_.scene.name, family_,       solver, quantity, plane, mode, size,
                            estimate,         exact_witness, false,  ""};
    for (const auto& check : run_checks()) {
      if (check.verdict != Verdict::Fail || baseline_failures_.count(check_key(check))) continue;
      outcome.caught = true;
      outcome.caught_by =
          fmt::format("{} {} {} mode {}", check.check, check.compare, check.plane, check.mode);
      break;
    }
    outcomes_.push_back(std::move(outcome));
  }

  // True when an exact solver other than `solver` returned what `has` looks for.
  template <class Has>
  bool exact_witness(const std::string& solver, Has has) const {
    for (const auto& output : work_.outputs) {
      if (output.solver != solver && is_exact_solver(output.solver) && output.summary.is_usable() &&
          has(output)) {
        return true;
      }
    }
    return false;
  }

 private:
  std::vector<CheckResult> run_checks() const {
    return internal::run_checks(work_, options_.tolerances, options_.findings);
  }

  SceneResult work_;
  const SceneRunOptions& options_;
  std::string family_;
  std::set<std::string> baseline_failures_;
  std::vector<MutationOutcome> outcomes_;
};

bool has_mode(const SolverOutput& output, Plane plane, int index, bool with_shape) {
  const auto& modal = plane == Plane::InPlane ? output.inplane : output.outofplane;
  if (!modal) return false;
  for (const auto& mode : modal->modes) {
    if (mode.index == index) return !with_shape || internal::has_stacked_shape(mode, plane);
  }
  return false;
}

void scale_frequency(Mode& mode, double factor) {
  mode.omega_rad_s *= factor;
  mode.frequency_hz *= factor;
  mode.k_l_over_pi *= factor;
  if (mode.gale_ratio) *mode.gale_ratio *= factor;
}

void mutate_frequencies(SceneMutator& mutator, SolverOutput& output, Plane plane) {
  auto& modal = modal_of(output, plane);
  if (!modal) return;
  const Scene& scene = mutator.work().scene;
  const SolverKnobs knobs =
      scene.solvers.count(output.solver) ? scene.solvers.at(output.solver) : SolverKnobs{};
  for (Mode& mode : modal->modes) {
    const double target = frequency_accuracy_target(output.solver, knobs, mode);
    if (!(target > 0.0) || !std::isfinite(mode.omega_rad_s)) continue;
    const double change = kFrequencyMutationFactor * target;
    const Mode saved = mode;
    scale_frequency(mode, 1.0 + change);
    const bool witness = mutator.exact_witness(output.solver, [&](const SolverOutput& other) {
      return has_mode(other, plane, mode.index, false);
    });
    mutator.record(output.solver, MutatedQuantity::Frequency, plane_name(plane), mode.index, change,
                   saved.relative_error_estimate, witness);
    mode = saved;
  }
}

bool has_decay(const SolverOutput& output, Plane plane, int index, bool overdamped) {
  const auto& modal = plane == Plane::InPlane ? output.inplane : output.outofplane;
  if (!modal) return false;
  for (const auto& mode : overdamped ? modal->overdamped : modal->modes) {
    if (mode.index == index) return mode.decay_rate_1_s > 0.0;
  }
  return false;
}

// A damped mode's delta (or an overdamped root's), made wrong by 10 x its solver's target where
// delta is a claim on its own: its damping ratio above that target (below it the decay-rate check
// of src/verification/internal/damping_checks.cpp compares delta relative to |lambda|, and no
// mutation of delta is made).
void mutate_decay_list(SceneMutator& mutator,
                       const std::string& solver,
                       std::vector<Mode>& modes,
                       Plane plane,
                       bool overdamped) {
  const Scene& scene = mutator.work().scene;
  const SolverKnobs knobs = scene.solvers.count(solver) ? scene.solvers.at(solver) : SolverKnobs{};
  for (Mode& mode : modes) {
    const double target = decay_rate_accuracy_target(solver, knobs, mode);
    if (!(target > 0.0) || !(mode.decay_rate_1_s > 0.0) || !(mode.damping_ratio > target) ||
        !std::isfinite(mode.decay_rate_1_s))
      continue;
    const double change = kFrequencyMutationFactor * target;
    const Mode saved = mode;
    mode.decay_rate_1_s *= 1.0 + change;
    mode.damping_ratio =
        overdamped ? 1.0 : mode.decay_rate_1_s / std::hypot(mode.decay_rate_1_s, mode.omega_rad_s);
    const bool witness = mutator.exact_witness(solver, [&](const SolverOutput& other) {
      return has_decay(other, plane, mode.index, overdamped);
    });
    mutator.record(solver, MutatedQuantity::DecayRate,
                   std::string(plane_name(plane)) + (overdamped ? " overdamped" : ""), mode.index,
                   change, saved.decay_rate_error_estimate, witness);
    mode = saved;
  }
}

void mutate_decay_rates(SceneMutator& mutator, SolverOutput& output, Plane plane) {
  auto& modal = modal_of(output, plane);
  if (!modal || !mutator.work().scene.problem.is_damped()) return;
  mutate_decay_list(mutator, output.solver, modal->modes, plane, false);
  mutate_decay_list(mutator, output.solver, modal->overdamped, plane, true);
}

// The widest 1 - MAC tolerance `solver` is held to in this scene (the scene's override, else the
// table's rule against each other solver with shapes in `plane`); 0 when none applies.
double widest_mac_tolerance(const SceneMutator& mutator, const std::string& solver, Plane plane) {
  const SceneResult& result = mutator.work();
  if (result.scene.checks.mac_min) return 1.0 - *result.scene.checks.mac_min;
  double widest = 0.0;
  for (const auto& other : result.outputs) {
    if (other.solver == solver || !other.summary.is_usable() || !has_mode(other, plane, 1, true))
      continue;
    const ToleranceRule* rule = mutator.options().tolerances.find(
        "mac", solver, other.solver, result.scene.name, result.scene.tags);
    if (rule) widest = std::max(widest, rule->max);
  }
  return widest;
}

void mutate_shapes(SceneMutator& mutator, SolverOutput& output, Plane plane) {
  auto& modal = modal_of(output, plane);
  if (!modal || modal->modes.size() < 2) return;
  const double drop = kShapeMutationFactor * widest_mac_tolerance(mutator, output.solver, plane);
  if (!(drop > 0.0)) return;
  auto& modes = modal->modes;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const Mode& neighbour = modes[i + 1 < modes.size() ? i + 1 : i - 1];
    if (!internal::has_stacked_shape(modes[i], plane) ||
        !internal::has_stacked_shape(neighbour, plane))
      continue;
    const Vector p = internal::stacked_shape(modes[i], plane);
    const auto delta =
        internal::mix_for_mac_drop(p, internal::stacked_shape(neighbour, plane), drop);
    if (!delta) continue;
    const Mode saved = modes[i];
    internal::mix_modes(modes[i], neighbour, *delta);
    const double size = internal::one_minus_mac(p, internal::stacked_shape(modes[i], plane));
    const int index = modes[i].index;
    const bool witness = mutator.exact_witness(output.solver, [&](const SolverOutput& other) {
      return has_mode(other, plane, index, true);
    });
    mutator.record(output.solver, MutatedQuantity::Shape, plane_name(plane), index, size, -1.0,
                   witness);
    modes[i] = saved;
  }
}

void mutate_forced(SceneMutator& mutator, SolverOutput& output) {
  for (std::size_t i = 0; i < output.forced.size(); ++i) {
    ForcedResponse& response = output.forced[i];
    // A tension of zero (out-of-plane forcing of a cable whose statics lie in a plane: the dynamic
    // tension is of second order) is not changed by a relative mutation: none is made.
    if (!response.diagnostic.empty() || !std::isfinite(response.max_abs_tension_n) ||
        response.max_abs_tension_n == 0.0)
      continue;
    const double saved_max = response.max_abs_tension_n;
    const Vector saved_curve = response.tension_n;
    response.max_abs_tension_n *= 1.0 + kForcedTensionMutation;
    response.tension_n *= 1.0 + kForcedTensionMutation;
    const bool witness = mutator.exact_witness(output.solver, [&](const SolverOutput& other) {
      return i < other.forced.size() && other.forced[i].diagnostic.empty();
    });
    mutator.record(output.solver, MutatedQuantity::ForcedTension, "forced", static_cast<int>(i + 1),
                   kForcedTensionMutation, response.relative_error_estimate, witness);
    response.max_abs_tension_n = saved_max;
    response.tension_n = saved_curve;
  }
}

bool has_dynamic_tension(const SolverOutput& output, std::size_t k) {
  return k < output.dynamic_tension.size() &&
         internal::dynamic_station_values(output.dynamic_tension[k]).size() > 0;
}

// Scales one excitation's dynamic tension: along the line and at both ends.
void scale_dynamic_tension(DynamicTension& t, double factor) {
  (t.irregular ? t.std_n : t.amplitude_n) *= factor;
  for (DynamicTensionEnd* end : {&t.fairlead, &t.anchor})
    (t.irregular ? end->std_n : end->amplitude_n) *= factor;
}

// Each excitation's dynamic tension made wrong by kDynamicTensionMutation: what a solver with a
// wrong linear solve or a wrong fixed point would return.
void mutate_dynamic_tension(SceneMutator& mutator, SolverOutput& output) {
  for (std::size_t k = 0; k < output.dynamic_tension.size(); ++k) {
    DynamicTension& t = output.dynamic_tension[k];
    const double fairlead = internal::dynamic_end_value(t, t.fairlead);
    if (!has_dynamic_tension(output, k) || !std::isfinite(fairlead) || !(fairlead > 0.0)) continue;
    const DynamicTension saved = t;
    scale_dynamic_tension(t, 1.0 + kDynamicTensionMutation);
    const bool witness = mutator.exact_witness(
        output.solver, [&](const SolverOutput& other) { return has_dynamic_tension(other, k); });
    mutator.record(output.solver, MutatedQuantity::DynamicTension, "dynamic",
                   static_cast<int>(k + 1), kDynamicTensionMutation, saved.relative_error_estimate,
                   witness);
    t = saved;
  }
}

}  // namespace

std::vector<MutationOutcome> mutate_scene(const SceneResult& result,
                                          const SceneRunOptions& options) {
  if (!result.statics || !result.groups || !result.error.empty()) return {};
  SceneMutator mutator(result, options);
  for (auto& output : mutator.work().outputs) {
    if (!output.summary.is_usable()) continue;
    for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
      mutate_frequencies(mutator, output, plane);
      mutate_shapes(mutator, output, plane);
      mutate_decay_rates(mutator, output, plane);
    }
    mutate_forced(mutator, output);
    mutate_dynamic_tension(mutator, output);
  }
  return std::move(mutator.outcomes());
}

MutationRun run_mutations(const std::vector<SceneResult>& results,
                          int jobs,
                          const SceneRunOptions& options,
                          const SuiteProgress& progress) {
  options.validate();  // before the workers: an exception must not escape a thread
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<MutationOutcome>> per_scene(results.size());
  std::size_t done = 0;
  std::mutex progress_mutex;
  internal::parallel_for(results.size(), jobs, [&](std::size_t i) {
    per_scene[i] = mutate_scene(results[i], options);
    std::lock_guard<std::mutex> lock(progress_mutex);
    ++done;
    if (progress) progress(done, results.size(), results[i].scene.name);
  });
  MutationRun run;
  for (auto& outcomes : per_scene) {
    for (auto& outcome : outcomes) run.outcomes.push_back(std::move(outcome));
  }
  run.threads = internal::thread_count(jobs);
  run.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::map<std::tuple<std::string, std::string, std::string>, MutationTally> MutationRun::tallies()
    const {
  std::map<std::tuple<std::string, std::string, std::string>, MutationTally> out;
  for (const auto& outcome : outcomes) {
    MutationTally& tally = out[{outcome.solver, outcome.family, to_string(outcome.quantity)}];
    ++tally.made;
    tally.caught += outcome.caught;
  }
  return out;
}

MutationTally MutationRun::exact_with_witness() const {
  MutationTally tally;
  for (const auto& outcome : outcomes) {
    if (!is_exact_solver(outcome.solver) || !outcome.exact_witness) continue;
    ++tally.made;
    tally.caught += outcome.caught;
  }
  return tally;
}

MutationTally MutationRun::exact_beyond_estimate() const {
  MutationTally tally;
  for (const auto& outcome : outcomes) {
    if (!is_exact_solver(outcome.solver) || !outcome.exact_witness ||
        !(outcome.size > outcome.estimate))
      continue;
    ++tally.made;
    tally.caught += outcome.caught;
  }
  return tally;
}

}  // namespace catena
