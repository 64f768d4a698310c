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

/// What a solver solves, as the verification harness needs to know it
/// (docs/reference/verdicts.md, "Solver roles").
enum class SolverKind {
  /// The exact linear equations of the cable (fe, shooting, frobenius): its error is numerical,
  /// bounded by the accuracy it was asked for (SolverEntry::accuracy_target). Two exact solvers
  /// witness each other: the mutation score counts a mutation of one where another ran.
  Exact,
  /// An approximate model (asymptotic, airy): its error is the model's, which each mode's
  /// relative_error_estimate states; it is measured against the exact solvers (the report's
  /// "Model error" section), never used as a reference.
  Model
};

/// One solver as the harness sees it. Its roles (kind, certifies_references,
/// all_modes_at_once, accuracy_target) are data: the harness and the report read them here and
/// never name a solver (tests/verification/solver_names_test.cpp checks it), so a solver added
/// to the registry (or by register_solver()) joins every check, table and score without an edit
/// there.
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

  /// Exact method or approximate model.
  SolverKind kind = SolverKind::Exact;
  /// May serve as the certified reference of `catena check`
  /// (catena/verification/certified_reference.hpp): an exact solver of every cable that command
  /// accepts, extensible or not, at any sag (frobenius is not: it solves Gale's inextensible
  /// catenary only). The candidates are tried most accurate first (exact_solvers_by_accuracy()).
  bool certifies_references = false;
  /// Its modes come from one eigenvalue problem, all at once, not from one root search each: many
  /// modes cost little more than a few (fe gives 64 modes of a Gale C-2 catenary in 0.04 s,
  /// shooting 2.2 s, frobenius 3.9 s). The harness asks such a solver first when it needs many
  /// modes only to ~1e-4 (the forced check's condition number).
  bool all_modes_at_once = false;
  /// The relative accuracy of each frequency the solver promises with these knobs (validated
  /// first; {} gives the defaults): the accuracy_target its plane summaries report, computed by the
  /// same function, or, where the solver was asked for none, what its default resolution is
  /// declared to reach (fe without `tolerance`: 1e-6, verification/tolerances.toml). Empty for a
  /// model: its accuracy is each mode's model-error estimate. Throws InvalidInput for bad knobs.
  std::function<double(const SolverKnobs&)> accuracy_target;
};

/// The quantities named in SolverEntry::computations.
const std::vector<std::string>& compared_quantities();

/// All solvers, in a fixed order: fe, shooting, frobenius, asymptotic, airy, then those added by
/// register_solver() in the order they were added.
const std::vector<SolverEntry>& solver_registry();
/// The entry named `name`, or nullptr.
const SolverEntry* find_solver(const std::string& name);

/// Adds a solver to the registry, after the five, for tests and plugins: from then on scenes may
/// name it, a scene that names no solver runs it, and the harness compares it with the others and
/// counts it in the mutation score by its roles. An entry without `computations` gets its own code
/// path for every compared quantity (independent of every other solver). Call it before any scene
/// is read or solved, from one thread: it invalidates the pointers find_solver() returned. Throws
/// InvalidInput for an empty or taken name, or an entry without validate_knobs or make_numerics.
void register_solver(SolverEntry entry);

/// The names of the solvers of `kind`, in registry order.
std::vector<std::string> solver_names(SolverKind kind);
/// True when `name` is a registered exact solver.
bool is_exact_solver(const std::string& name);
/// The exact solvers, the most accurate at their default knobs first (accuracy_target({}):
/// frobenius 1e-11, shooting 1.1e-9, fe 1e-6); ties keep registry order. The "most accurate
/// exact solver that ran" of the harness and the report is the first of these that ran.
std::vector<std::string> exact_solvers_by_accuracy();
/// The solvers with certifies_references, in the order of exact_solvers_by_accuracy().
std::vector<std::string> reference_solvers();

/// Runs `entry` on the context through the driver: validates the knobs and the request, checks
/// applicability (a NotApplicable output with the reason when the solver declines), runs each
/// requested plane and the forced response, times them, and never lets a numerical exception
/// escape (it becomes NumericalFailure with its message). InvalidInput propagates.
SolverOutput run_solver(const SolverEntry& entry,
                        const SolveContext& context,
                        const SolverKnobs& knobs);

}  // namespace catena
