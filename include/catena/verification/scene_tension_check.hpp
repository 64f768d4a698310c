// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// `catena check` on another program's dynamic tension as one library call
/// (docs/how-to/check-dynamic-tension.md): the scene's [request.motion] reduced to the one
/// excitation the other program computed, solved by the reference-grade solvers (shooting and fe,
/// their knobs from the scene kept), Catena's reference chosen, and the comparison
/// (include/catena/verification/tension_check.hpp). The CLI calls it; other front ends may.

#include <optional>
#include <string>
#include <vector>

#include "catena/verification/scene.hpp"
#include "catena/verification/tension_check.hpp"

namespace catena {

/// The comparison, or why none could be made.
struct SceneTensionCheck {
  /// Absent when Catena could not compute the reference (see `error`).
  std::optional<TensionCheck> check;
  /// Why there is no comparison: the statics failed, or no Catena solver computed the dynamic
  /// tension (each solver's report follows). Empty when `check` is present.
  std::string error;
};

/// The scene that computes the reference for `tension`: `scene` with its motion reduced to the
/// excitation compared (the period of `tension.period_s`, or the scene's only one), no modes, no
/// forced response, 2001 stations, and the reference solvers only. Throws InvalidInput when the
/// scene has no [request.motion], when the quantity does not fit its motion (tension_std_n needs
/// an irregular motion, tension_amplitude_n a regular one), when a regular motion asks several
/// periods and the file gives none, or when the file's period is not one of the scene's.
Scene tension_reference_scene(Scene scene, const ExternalTension& tension);

/// Catena's reference from the outputs of one run: of the reference solvers that computed the
/// excitation and reached its fixed point, the one with the smaller relative error estimate
/// (shooting on a tie). nullopt, with `why` giving each solver's report, when none did.
std::optional<TensionReference> tension_reference(const std::vector<SolverOutput>& outputs,
                                                  TensionQuantity quantity,
                                                  std::string& why);

/// Validates `options` and `tension` (against the scene's line length), runs the reference scene
/// and compares. Throws InvalidInput for bad input; a reference that could not be computed is
/// SceneTensionCheck::error, never an exception.
SceneTensionCheck check_scene_tension(const ExternalTension& tension,
                                      const Scene& scene,
                                      const ExternalCheckOptions& options = {});

}  // namespace catena
