// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// What every solver's results must satisfy before they leave the solver skeleton
/// (docs/contributing/architecture.md, "Result validation"). drive_solver() applies these checks
/// after each part, for every solver alike, so that no wrong answer is ever reported as converged.
///
/// Modes of one plane, in the order returned:
///   - index = position + 1 (1-based, lowest first);
///   - omega finite and > 0, frequency_hz and k_l_over_pi finite;
///   - strictly ascending, except equal within a multiple root whose multiplicity the solver
///     proved (Mode::multiplicity > 1 on both); any other tie is read as one root returned twice
///     (and another one missing);
///   - relative_error_estimate finite and >= 0, or exactly -1 ("none");
///   - every shape, tension and modal-mass value finite;
///   - no more modes than asked;
///   - when proved_count_below_top >= 0, it equals the number of returned modes: the counting
///     argument must cover exactly the returned set, otherwise a root was skipped (or found twice)
///     and the indices are not proved.
/// The first violating mode ends the valid prefix. A violation makes the plane NoConvergence with
/// that prefix when it is not empty, else NumericalFailure with no modes; a count that does not
/// cover the returned set is NumericalFailure (no prefix is then known to be right). The message
/// names the mode and the property; a status that is already worse is kept.
///
/// Forced responses: max_abs_tension_n, its error estimate and every array finite, or a
/// diagnostic saying why there is no finite answer. A non-finite value without a diagnostic
/// becomes one (arrays cleared) and the forced part NoConvergence.

#include <string>

#include "catena/solvers/modal_result.hpp"
#include "solvers/common/solver_driver.hpp"

namespace catena::internal {

/// Applies the mode rules above to `result`, asked for `requested` modes.
void validate_modal_result(ModalResult& result, int requested);

/// The response of the linear model to amplitude A is A times its response to a unit amplitude.
/// The driver asks the solvers for the mantissa m in [0.5, 1) of A = m 2^e (so nothing overflows in
/// a solve) and scale_forced_outcome() multiplies by 2^e, which is exact in binary floating point:
/// the results are bit for bit those of a solve at A whenever that solve does not overflow.
double amplitude_mantissa(double amplitude_m);

/// Scales `outcome`, solved for amplitude_mantissa(amplitude_m), to amplitude_m (displacements and
/// tension; not the stations or the relative error). A response whose scaled values overflow
/// double precision gets a diagnostic naming the amplitude (its arrays cleared) and the forced
/// part becomes NoConvergence.
void scale_forced_outcome(ForcedOutcome& outcome, double amplitude_m);

/// Applies the forced-response rules above to `outcome`.
void validate_forced_outcome(ForcedOutcome& outcome);

/// Lowers `summary` to `termination` (NoConvergence or NumericalFailure) unless it is already
/// worse, with `reason` in front of its message and among its warnings.
void reject_part(SolverSummary& summary, Termination termination, const std::string& reason);

}  // namespace catena::internal
