// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The JSON documents of `catena solve --json` and `catena verify` (report.json): a public,
/// scriptable interface documented in docs/reference/json-layout.md. Layout:
///
///     { "catena": {version, git, compiler, build_type, generated_utc},
///       "scenes": [ { name, file, description, tags, sweep, problem, request, statics, groups,
///                     solvers: { <name>: {summary, inplane, outofplane, forced} },
///                     checks: [...], error, wall_time_s } ] }
///
/// Units are SI and carried in key names (`_m`, `_n`, `_rad_s`, `_hz`, `_kg`); dimensionless
/// frequencies are `k_l_over_pi` and `gale_ratio`. Non-finite values (e.g. lambda2 of an
/// inextensible cable) are written as null, never as NaN.

#include <filesystem>
#include <string>
#include <vector>

#include "catena/verification/mutation.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena {

/// The whole document for `results` (with the mutation score when `mutation` is given), with
/// `indent` spaces per level and one line per record (a check, a mode, a forced response); -1:
/// compact, on one line.
std::string results_to_json(const std::vector<SceneResult>& results,
                            int indent = 2,
                            const MutationRun* mutation = nullptr);

/// Writes results_to_json to `path` atomically (write_file_atomically: parent directories created,
/// never a 0-byte or half file). Throws InvalidInput naming the path when it cannot be written.
void write_results_json(const std::filesystem::path& path,
                        const std::vector<SceneResult>& results,
                        const MutationRun* mutation = nullptr);

}  // namespace catena
