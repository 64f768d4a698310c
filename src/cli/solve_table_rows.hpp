// SPDX-License-Identifier: MIT
#pragma once
// `catena solve`'s tables filled from one scene's results: the modes of a plane, the forced
// responses and the dynamic tensions, each beside the verdict of the checks about that row (the
// same CheckResult list `--json` writes, so the verdict shown is the JSON's).

#include <optional>
#include <string>
#include <vector>

#include "catena/verification/scene_runner.hpp"
#include "cli/solve_table.hpp"
#include "cli/solve_units.hpp"

namespace catena::cli {

/// The worst verdict of the checks about `place` ("in-plane", "forced", "fairlead", ...) and
/// `index` (1-based mode, forcing or excitation): FAIL, SOURCE, WARN, PASS, SKIP in that order;
/// empty when there is none.
std::string row_verdict(const std::vector<CheckResult>& checks,
                        const std::string& place,
                        int index);

/// The unit the modes can be shown in: `wanted`, or rad/s when a mode lacks it (Gale's ratio of a
/// line that is not one uniform cable).
FrequencyUnit usable_unit(const SceneResult& result, FrequencyUnit wanted);

/// The modes of `plane`, a column per solver that returned some (nullopt: none did). Damped
/// modes show the damped frequency omega_d, then the reference solver's delta and zeta
/// (`reference`: the solver named in their headers; empty: the first solver of the table).
std::optional<SolverTable> modal_table(const SceneResult& result,
                                       Plane plane,
                                       FrequencyUnit unit,
                                       const std::string& reference);

/// max |tau| of each forcing frequency, a column per solver (nullopt: no forced responses).
std::optional<SolverTable> forced_table(const SceneResult& result);

/// The dynamic tension at the fairlead and the anchor, a row per excitation, end and quantity
/// (regular: mean, amplitude, max; irregular: mean, std, Tz, most probable max), a column per
/// solver; a fixed point that did not converge is "-" (nullopt: no dynamic tension).
std::optional<SolverTable> dynamic_tension_table(const SceneResult& result);

}  // namespace catena::cli
