// SPDX-License-Identifier: MIT
#pragma once
// The scene keys of issue 30 (docs/reference/scene-format.md, "Drag and dynamic tension in
// waves"): a section's Morison drag and tangential added mass, the `[environment]` table and the
// `[request.motion]` table. Values are read with their types and signs checked here (so that a bad
// value names "[table].key"); the constraints between values (table lengths, sorted frequencies,
// regular versus irregular) are MotionRequest::validate()'s and validate_drag()'s, which the scene
// reader calls after reading.

#include "catena/models/cable.hpp"
#include "catena/solvers/solve_request.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena::internal {

/// The drag keys of `[cable]` or a `[[line.segments]]` entry: `diameter` [m] (> 0 when given;
/// absent: 0, no drag), `drag_normal`, `drag_tangential` [-] (>= 0, default 0).
MorisonDrag read_drag(TableReader& section);

/// `added_mass_tangential` [kg/m] of a section (>= 0, default 0).
double read_added_mass_tangential(TableReader& section);

/// `[environment]`: `water_density` [kg/m^3] (> 0, default 1025), `gravity` [m/s^2] (> 0,
/// default 9.80665).
Environment read_environment(TableReader& table);

/// `[request.motion]`: direction ([x, z] or "out_of_plane"), amplitude and periods (regular), or
/// spectrum = {omega, density} or jonswap = {hs, tp, gamma} with rao = {omega, amplitude,
/// phase_deg, per} (irregular); frequencies, duration, tolerance, max_iterations.
MotionRequest read_motion(TableReader& table);

}  // namespace catena::internal
