// SPDX-License-Identifier: MIT
#pragma once
// The lines under `catena solve`'s tables: a solver that declined or failed in one short line
// (why), the failed checks, a count of the others that are not PASS; under --verbose every long
// message once (each solver's resolution, plane summaries, warnings, notes; every check that is
// not PASS).

#include <string>

#include "catena/verification/scene_runner.hpp"

namespace catena::cli {

/// One clause of `message` (clauses end at ": " or "; " outside parentheses), at most `width`
/// characters: a decline's first (its reason); otherwise the first that says what went wrong
/// ("not", "miss", "fail", "limit", ...), else the first.
std::string short_message(const std::string& message, bool decline, std::size_t width = 96);

/// Declines (of a solver, or of one plane), failures, partial results, forced diagnostics and
/// unconverged fixed points, one short line each, and the overdamped roots (each line ends in a
/// newline, indented by two spaces). Under `verbose` only the overdamped roots: solver_details()
/// says the rest in full.
std::string solver_notes(const SceneResult& result, bool verbose);

/// The checks worth a line: FAIL always (one line each), and a count of SOURCE and WARN (each
/// listed under `verbose`).
std::string check_notes(const SceneResult& result, bool verbose);

/// Every solver's long messages, each said once (--verbose).
std::string solver_details(const SceneResult& result);

}  // namespace catena::cli
