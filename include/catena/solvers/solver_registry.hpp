// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The solvers behind `catena solve` and `catena verify`, by name, with their knobs.
///
/// Each solver also has its own typed entry point and options struct (e.g. solve_fe with
/// FeSolverOptions). Both paths run through one driver (src/solvers/common/solver_driver.hpp):
/// validation, applicability, the per-plane loop, timing, exception-to-status mapping and the rule
/// that combines the plane summaries are written once; a solver supplies only its numerics
/// (docs/contributing/architecture.md, "Solver skeleton").

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/run_limits.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

namespace internal {
class SolverNumerics;
}

/// A knob value as written in a scene: `elements = 400`, `richardson = true`, `rtol = 1e-10`.
using KnobValue = std::variant<bool, long, double, std::string>;
/// Knobs of one solver, by name.
using SolverKnobs = std::map<std::string, KnobValue>;

/// Everything a solver may read: the problem, its shared statics and groups, and the request.
struct SolveContext {
  const Problem& problem;
  const StaticSolution& statics;
  const DimensionlessGroups& groups;
  const SolveRequest& request;
  /// The run's time limit and progress report (catena/solvers/run_limits.hpp); nullptr: none.
  const RunLimits* limits = nullptr;
};

/// Description of one knob, generated from the solver's knob table: for `catena solvers`, the docs
/// and error messages.
struct KnobSpec {
  std::string name;
  /// Meaning and unit.
  std::string description;
  /// "integer", "real", "flag" or "choice".
  std::string type;
  /// The default as a scene would write it ("400", "1e-10", "true", "\"adams\"").
  std::string default_value;
  /// The valid values in words ("[2, 1e7]", "(0, 0.01]", "\"adams\" or \"bdf\""); empty for flags.
  std::string valid;
};

/// One solver as the harness sees it.
struct SolverEntry {
  std::string name;
  std::string description;
  std::vector<KnobSpec> knobs;
  /// Throws InvalidInput for unknown knobs, wrong types or values out of range, naming
  /// `[solvers.<name>].<knob>` (used when a scene is read, and before every run).
  std::function<void(const SolverKnobs&)> validate_knobs;
  /// The solver's numerics for one problem, with its knobs read (they are validated first).
  std::function<std::unique_ptr<internal::SolverNumerics>(const SolveContext&, const SolverKnobs&)>
      make_numerics;
  /// The code path that computes each quantity the harness compares, by quantity
  /// ("frequency-in-plane", "frequency-out-of-plane", "shape-in-plane", "shape-out-of-plane",
  /// "tension", "forced"): two solvers that declare the same id for a quantity are one witness,
  /// and the harness does not compare them on it (docs/reference/verdicts.md, "Independence"). A
  /// quantity the solver does not produce is absent.
  std::map<std::string, std::string> computations;
};

/// The quantities named in SolverEntry::computations.
const std::vector<std::string>& compared_quantities();

/// All solvers, in a fixed order: fe, shooting, frobenius, asymptotic, airy.
const std::vector<SolverEntry>& solver_registry();
/// The entry named `name`, or nullptr.
const SolverEntry* find_solver(const std::string& name);

/// Runs `entry` on the context through the driver: validates the knobs and the request, checks
/// applicability (a NotApplicable output with the reason when the solver declines), runs each
/// requested plane and the forced response, times them, and never lets a numerical exception
/// escape (it becomes NumericalFailure with its message). InvalidInput propagates.
SolverOutput run_solver(const SolverEntry& entry,
                        const SolveContext& context,
                        const SolverKnobs& knobs);

}  // namespace catena
