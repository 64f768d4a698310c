// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// `catena check` as one library call (docs/how-to/check.md): another program's results against
/// Catena's certified reference for a scene. The scene's request is adapted to what the check needs
/// (enough modes in each plane the results use, shapes and tensions when the results carry them,
/// shooting and fe only, their knobs from the scene kept), the scene is run, the reference of each
/// plane is chosen (include/catena/verification/certified_reference.hpp) and the results are
/// compared (include/catena/verification/external_check.hpp). The CLI and the Python module both
/// call it.

#include <optional>
#include <string>
#include <vector>

#include "catena/verification/external_check.hpp"
#include "catena/verification/scene.hpp"

namespace catena {

/// The comparison, or why none could be made.
struct SceneCheck {
  /// Absent when no reference could be computed (see `error`).
  std::optional<ExternalCheck> check;
  /// Why there is no comparison: the statics failed numerically, or neither exact solver converged
  /// in a plane the results use ("no certified reference: ..."). Empty when `check` is present.
  std::string error;
};

/// The scene that computes the reference for `results`: `scene` with its request and solvers
/// adapted as the file comment says.
Scene reference_scene(Scene scene, const std::vector<ExternalMode>& results);

/// Validates `options` and `results`, runs the reference scene and compares. Throws InvalidInput
/// for bad input (options, results, or bad input found while solving, e.g. an unreachable chord);
/// numerical failure is SceneCheck::error, never an exception.
SceneCheck check_scene(const std::vector<ExternalMode>& results,
                       const Scene& scene,
                       const ExternalCheckOptions& options = {});

}  // namespace catena
