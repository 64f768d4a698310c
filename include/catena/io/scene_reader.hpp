// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Strict reading of scene files (TOML). Every key is checked: an unknown key, a wrong type, a
/// missing table or an invalid value is a ParseError/InvalidInput whose message names the file,
/// the table and the key, e.g.
///     "scenes/x.toml: [cable].mass = -1: must be > 0 [kg/m]"
///
/// Format (docs/reference/scene-format.md; documented with examples in verification/README.md):
///
///     name = "mooring-line"            # optional (default: file stem)
///     description = "..."              # optional
///     tags = ["mooring"]               # optional
///     [cable]  length, weight, EA (number or "inf"), mass, added_mass = 0, a = [x, z], b = [x, z]
///              (also in each [[line.segments]]: diameter, drag_normal = 0, drag_tangential = 0,
///              added_mass_tangential = 0; and the damping keys)
///     [environment]  water_density = 1025, gravity = 9.80665
///     [taut_inclined]  eps, phi_deg, lambda2, mass_ratio = 1
///     [gale]   xi1, xi2   |   h_over_b, sag_param            (exactly one of the three forms)
///     [request]  inplane_modes = 6, outofplane_modes = 0, shapes = false, points = 101,
///                tension = false
///     [request.forced]  end = "b", direction = "tangential" | "normal" | "out_of_plane" | [x, z],
///                amplitude, amplitude_unit = "m" | "a", frequencies = [...],
///                frequency_unit = "rad/s" | "Hz" | "kL/pi" | "gale"
///     [request.motion]  direction = [x, z] | "out_of_plane", amplitude, periods (regular), or
///                spectrum = {omega, density} | jonswap = {hs, tp, gamma} with rao = {omega,
///                amplitude, phase_deg, per} (irregular); frequencies, duration, tolerance,
///                max_iterations
///     [solvers]  fe = { elements = 400 }, shooting = {}   (only these run; default: all)
///     [checks]   frequency_rel, mac_min, shape_max_diff, tension_rel, orthogonality
///     [[published]]  source, quantity, unit, modes, values, decimals
///     [sweep]    parameter = "taut_inclined.lambda2", values = [...]

#include <filesystem>
#include <vector>

#include "catena/verification/scene.hpp"

namespace catena {

/// Reads one scene file. Returns one Scene, or one per value for a sweep. The file must be a
/// regular file of at most kMaxInputFileBytes, nested at most 64 levels
/// (docs/reference/scene-format.md, "Limits"); otherwise a ParseError naming the path.
std::vector<Scene> read_scene_file(const std::filesystem::path& path);

/// Parses scene text (for tests); `origin` names it in messages.
std::vector<Scene> parse_scene_text(const std::string& text, const std::string& origin);

/// Every entry named *.toml under `directory` (recursively, not following directory symlinks),
/// sorted by path, including entries that are not readable regular files (dangling symlinks,
/// FIFOs, symlink loops): read_scene_file then reports them instead of their being skipped.
/// InvalidInput naming the path when `directory` is not a directory or cannot be listed.
std::vector<std::filesystem::path> list_scene_files(const std::filesystem::path& directory);

}  // namespace catena
