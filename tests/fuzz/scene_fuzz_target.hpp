// SPDX-License-Identifier: MIT
#pragma once
// The fuzz target: one scene text through the reader, the statics and a cheap solver request
// (docs/contributing/testing.md, "Fuzzing"). Bad input must end as catena::Error; anything else
// that escapes (another exception, a signal, a sanitizer report) is a defect, and so is a result
// that claims to have converged while holding a non-finite or non-positive frequency or a
// non-finite forced response.

#include <cstdint>
#include <string>
#include <vector>

namespace catena::fuzz {

/// How far one input got.
enum class FuzzStage { Rejected, StaticsFailed, Solved };

struct FuzzOutcome {
  FuzzStage stage = FuzzStage::Rejected;
  /// "converged but ..." findings; empty when the results are consistent.
  std::vector<std::string> violations;
};

/// Caps that keep one iteration cheap (a mutant may ask for a million modes): the request and the
/// resolution knobs are clamped before solving; parsing always sees the text unchanged.
struct FuzzLimits {
  int max_modes_per_plane = 4;
  int max_points = 41;
  std::size_t max_forcing_frequencies = 3;
  std::size_t max_sweep_scenes = 2;
  long max_fe_elements = 200;
  long max_shooting_steps = 20000;
  long max_frobenius_terms = 800;
};

/// Runs one input. `solver_choice` picks which of the scene's solvers runs (round-robin over the
/// iterations gives every solver its turn). Throws only what is not a catena::Error.
FuzzOutcome fuzz_scene_text(const std::string& text,
                            std::uint64_t solver_choice,
                            const FuzzLimits& limits);

}  // namespace catena::fuzz
