#pragma once
/// \file
/// The solvers behind `catena solve` and `catena verify`, by name, with their knobs.
///
/// Each solver also has its own typed entry point and options struct (e.g. solve_fe with
/// FeSolverOptions); the registry adapts scene knobs (TOML values) to those options so that the
/// harness never needs to know a solver's internals.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

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
};

/// Description of one knob, for validation and `--help`.
struct KnobSpec {
  std::string name;
  std::string description;  ///< meaning, unit, valid range, default
};

/// One solver as the harness sees it.
struct SolverEntry {
  std::string name;
  std::string description;
  std::vector<KnobSpec> knobs;
  /// nullopt when the solver applies; otherwise the reason it does not.
  std::function<std::optional<std::string>(const SolveContext&)> not_applicable_reason;
  /// Runs the solver. Throws InvalidInput for bad knobs (naming the knob); numerical trouble goes
  /// in the summaries.
  std::function<SolverOutput(const SolveContext&, const SolverKnobs&)> run;
  /// Throws InvalidInput for unknown knobs or bad values (used when a scene is read).
  std::function<void(const SolverKnobs&)> validate_knobs;
};

/// All solvers, in a fixed order: fe, shooting, frobenius, asymptotic, airy.
const std::vector<SolverEntry>& solver_registry();
/// The entry named `name`, or nullptr.
const SolverEntry* find_solver(const std::string& name);

/// Runs `entry` on the context: checks applicability (a NotApplicable output with the reason when
/// it declines), times the run, and never lets a numerical exception escape (an unexpected
/// std::exception becomes NumericalFailure with its message). InvalidInput propagates.
SolverOutput run_solver(const SolverEntry& entry, const SolveContext& context, const SolverKnobs& knobs);

}  // namespace catena
