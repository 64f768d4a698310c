// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The one solver skeleton (docs/contributing/architecture.md, "Solver skeleton"). A solver
/// implements SolverNumerics (its numerics only); drive_solver() owns everything around it, the
/// same way for every solver:
///
///   1. validate the request and the problem (InvalidInput propagates: bad input, exit 2);
///   2. ask not_applicable(): a reason ends the run as NotApplicable; so does a damped problem
///      for numerics that do not handle damping (handles_damping());
///   3. prepare(): work shared by the planes; a returned Outcome ends the run with that status;
///   4. modes(plane, count) for each requested plane (in-plane first), timed per plane; each
///      plane's result validated (result_validation.hpp: a wrong answer is never "converged");
///   5. forced(request) when a forced response is asked, for the amplitude's mantissa in
///      [0.5, 1) (the model is linear in it), then scaled exactly to the requested amplitude and
///      validated;
///   5b. the dynamic tension of a motion request (dynamic_tension.hpp): the drag linearisation's
///      fixed point, each iterate one forced_with_drag() call;
///   6. describe(): the overall resolution, notes and warnings (also after a prepare() Outcome);
///   7. combine the parts' summaries by combine_summaries() and time the whole.
///
/// Any std::exception other than InvalidInput that escapes steps 2-5 becomes NumericalFailure with
/// its message: numerical outcomes are statuses, never exceptions.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "solvers/common/drag_profile.hpp"

namespace catena::internal {

/// A status and its reason, for a solver that stops before producing results.
struct Outcome {
  Termination termination = Termination::NumericalFailure;
  std::string message;
};

/// The forced response of a solver, with the summary of that part of the run.
struct ForcedOutcome {
  std::vector<ForcedResponse> responses;
  /// termination, message ("5 of 5 forced frequencies"), iterations, operations, warnings.
  SolverSummary summary;
};

/// What one solver computes, for one problem (built from a SolveContext and the solver's options).
class SolverNumerics {
 public:
  virtual ~SolverNumerics() = default;

  /// Why the solver's model does not cover the problem; nullopt when it does. Must be cheap.
  virtual std::optional<std::string> not_applicable() const { return std::nullopt; }

  /// True when modes() solves the damped problem (complex roots, docs/explanation/physics.md,
  /// "Damping"). The driver declines a damped problem for numerics that do not: an undamped
  /// answer to a damped line is never returned.
  virtual bool handles_damping() const { return false; }

  /// Same for forced(): false makes the forced part of a damped problem NotApplicable.
  virtual bool handles_damped_forced() const { return false; }

  /// True when forced_with_drag() is implemented (the dynamic tension in waves,
  /// docs/explanation/dynamic-tension.md). False: that part is NotApplicable.
  virtual bool handles_drag() const { return false; }

  /// True when the numerics model a tangential added mass (ma_t: m + ma_t resists tangential
  /// motion). The driver declines a problem with one for numerics that do not.
  virtual bool handles_tangential_added_mass() const { return false; }

  /// Work shared by every plane and the forced response (e.g. fe's discrete statics). A returned
  /// Outcome ends the run with that status and message.
  virtual std::optional<Outcome> prepare() { return std::nullopt; }

  /// The `count` lowest modes of one plane, with that plane's summary (termination, message,
  /// error estimate, ...). The driver sets the plane, the solver name and the wall time.
  virtual ModalResult modes(Plane plane, int count) = 0;

  /// The forced response at every requested frequency. The default: not computed (a NotApplicable
  /// part with a warning).
  virtual ForcedOutcome forced(const ForcedRequest& request);

  /// The damped forced response at request.omegas_rad_s of the line with the linearised drag
  /// `drag` added to its sections' own linear damping (DragProfile::normal_at, tangential_at):
  /// the same contract as forced() on a damped line (a response per frequency, with its
  /// quadrature parts, its tension and its relative error estimate, at the request's stations
  /// `drag.stations()`; amplitude as given, no scaling by the driver). Called once per iterate of
  /// the fixed point with the same request and a new profile. The default: not computed.
  virtual ForcedOutcome forced_with_drag(const ForcedRequest& request, const DragProfile& drag);

  /// Facts for the overall summary: resolution, notes, warnings that concern the whole run. Called
  /// after the parts (or after prepare() ended the run), so it may report what they learned.
  virtual void describe(SolverSummary& summary) const { (void)summary; }
};

/// Runs `numerics` through the steps above. `solver` names the outputs and summaries.
SolverOutput drive_solver(const std::string& solver,
                          const SolveContext& context,
                          SolverNumerics& numerics);

/// The typed entry points (solve_fe(...) and the others): validate the options, build the
/// solver's numerics and drive them, exactly as run_solver() does for a registry entry.
template <class Numerics, class Options>
SolverOutput solve_with(const std::string& solver,
                        const SolveContext& context,
                        const Options& options) {
  options.validate();
  Numerics numerics(context, options);
  return drive_solver(solver, context, numerics);
}

/// The accuracy rule (catena/solvers/solver_summary.hpp, accuracy_target): when the plane's
/// summary carries a target, every mode whose error estimate exceeds it (or has none) gets
/// meets_target = false and a line in missed_modes, and a Converged plane becomes NoConvergence
/// with the count in front of its message. Applied by drive_solver() after validation.
void apply_accuracy_target(ModalResult& result);

/// The one rule that combines the parts of a run (each plane and the forced response) into the
/// overall summary:
/// - termination: Converged when every part converged; NumericalFailure when no part is usable;
///   otherwise NoConvergence (partial results). A NotApplicable part (a quantity the method does
///   not compute, e.g. the forced response of an analytic model) adds its message and warnings but
///   does not change the termination; only NotApplicable parts make the run NotApplicable;
/// - message: the parts' messages joined by "; ";
/// - iterations, operations: sums of the counted ones (-1 when none counted);
/// - max_error_estimate, max_residual: the largest over the parts (-1 when none);
/// - warnings: every part's warnings, prefixed with the part ("in-plane: ...");
/// - accuracy_target: the largest over the parts; missed_modes: every part's, prefixed likewise;
/// - notes: a plane's notes stay in the plane's summary; the forced part's are copied, prefixed
///   "forced: " (it has no summary of its own in SolverOutput).
/// `overall` keeps its resolution, notes and warnings (from describe()) and gains the rest.
void combine_summaries(const std::vector<std::pair<std::string, const SolverSummary*>>& parts,
                       SolverSummary& overall);

}  // namespace catena::internal
