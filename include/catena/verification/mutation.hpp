// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Mutation testing of the verification harness (`catena verify --mutation`,
/// docs/explanation/mutation.md): after a scene is solved, one result at a time is made wrong by a
/// stated amount and the scene's checks are run again on the mutated results (nothing is
/// re-solved). A mutation is caught when some check of that scene goes from a non-FAIL verdict to
/// FAIL. The share caught measures how much a "0 failed" is worth.

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "catena/verification/scene_runner.hpp"
#include "catena/verification/suite.hpp"

namespace catena {

/// A natural frequency is multiplied by (1 + kFrequencyMutationFactor x the solver's accuracy
/// target for that mode, frequency_accuracy_target()).
inline constexpr double kFrequencyMutationFactor = 10.0;
/// A mode shape phi_n is mixed with a neighbour, phi_n + delta phi_{n+1} renormalised, with delta
/// chosen so that 1 - MAC(phi_n, mixed) is kShapeMutationFactor x the widest MAC tolerance the
/// solver is held to in that scene.
inline constexpr double kShapeMutationFactor = 10.0;
/// A forced response's max |tension| (and its tension curve) is multiplied by (1 + this).
inline constexpr double kForcedTensionMutation = 1e-4;

/// A dynamic tension under a motion request (its values along the line and at both ends: the
/// amplitude, or the standard deviation when irregular) is multiplied by (1 + this): 10 x the
/// dynamic-tension rule of fe against an exact solver (verification/tolerances.toml).
inline constexpr double kDynamicTensionMutation = 1e-3;

/// What a mutation changed. DecayRate: on a damped line, a mode's decay rate delta (or an
/// overdamped root's) multiplied by (1 + kFrequencyMutationFactor x its solver's accuracy target,
/// decay_rate_accuracy_target()), its damping ratio with it. DynamicTension: one excitation's
/// dynamic tension multiplied by (1 + kDynamicTensionMutation).
enum class MutatedQuantity { Frequency, Shape, ForcedTension, DecayRate, DynamicTension };
/// "frequency", "shape", "forced-tension", "decay-rate", "dynamic-tension".
std::string to_string(MutatedQuantity quantity);

/// One mutation and whether the checks caught it.
struct MutationOutcome {
  std::string scene;
  /// The folder of the scene file (gale, grinfogel, studies, ...): the scene family.
  std::string family;
  std::string solver;
  MutatedQuantity quantity = MutatedQuantity::Frequency;
  /// "in-plane", "out-of-plane", "forced" or "dynamic".
  std::string plane;
  /// 1-based mode, or 1-based forcing (or excitation) index.
  int mode = 0;
  /// The size of the mutation: relative change of omega, 1 - MAC against the unmutated shape, or
  /// relative change of the tension.
  double size = 0.0;
  /// The mutated value's own relative error estimate, before the mutation (-1: none, e.g. a
  /// shape). A mutation no larger than it is within what the solver itself says of its error.
  double estimate = -1.0;
  /// Another exact solver (SolverKind::Exact) returned the same quantity in this scene.
  bool exact_witness = false;
  bool caught = false;
  /// The first check that went to FAIL ("frequency fe vs shooting in-plane mode 2"); empty when
  /// not caught.
  std::string caught_by;
};

/// Mutations made and caught.
struct MutationTally {
  int made = 0;
  int caught = 0;
};

/// All mutations of a run.
struct MutationRun {
  std::vector<MutationOutcome> outcomes;
  double wall_time_s = 0.0;
  int threads = 0;

  /// Tallies by (solver, family, quantity).
  std::map<std::tuple<std::string, std::string, std::string>, MutationTally> tallies() const;
  /// Tally of the exact solvers' mutations where another exact solver ran (the target:
  /// all caught).
  MutationTally exact_with_witness() const;
  /// The same, for the mutations larger than the mutated value's own error estimate: changes
  /// beyond what the solver claims, which a check must see wherever a witness ran.
  MutationTally exact_beyond_estimate() const;
};

/// The relative accuracy `solver` promises on `mode` with the scene's `knobs`: an exact solver's
/// SolverEntry::accuracy_target (the function its summaries' accuracy_target comes from: shooting
/// 10 rtol + root_tolerance, frobenius 10 tolerance, fe its `tolerance` or else 1e-6), a model's
/// (SolverKind::Model) the mode's own model-error estimate. 0 when there is none (no mutation is
/// made), e.g. for a solver not in the registry. Which solvers are exact: is_exact_solver()
/// (catena/solvers/solver_registry.hpp).
double frequency_accuracy_target(const std::string& solver,
                                 const SolverKnobs& knobs,
                                 const Mode& mode);
/// The relative accuracy of the decay rate delta on its own that `solver` promises on `mode`: an
/// exact solver's accuracy target (as for the frequency: the decay-rate check holds the pair to the
/// sum of their targets), a model's its mode's decay_rate_error_estimate. 0 when there is none.
double decay_rate_accuracy_target(const std::string& solver,
                                  const SolverKnobs& knobs,
                                  const Mode& mode);

/// Every mutation of one solved scene, each checked with `options`' tables. A scene without
/// statics (an error) gives none.
std::vector<MutationOutcome> mutate_scene(const SceneResult& result,
                                          const SceneRunOptions& options);

/// mutate_scene on every result, on `jobs` threads (0: all cores), timed.
MutationRun run_mutations(const std::vector<SceneResult>& results,
                          int jobs,
                          const SceneRunOptions& options,
                          const SuiteProgress& progress = {});

}  // namespace catena
