// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// How a result was obtained (after Ceres' Solver::Summary). Defaults mean "never ran".

#include <string>
#include <vector>

namespace catena {

/// Why a solver stopped.
enum class Termination {
  Converged,         ///< every requested quantity to the requested tolerance
  NoConvergence,     ///< partial results (e.g. fewer modes than asked); see message
  NumericalFailure,  ///< nothing usable; see message
  NotApplicable      ///< the solver's model does not cover this problem; see message
};

/// "converged", "no-convergence", "numerical-failure", "not-applicable".
std::string to_string(Termination termination);

struct SolverSummary {
  Termination termination = Termination::NumericalFailure;
  /// Why it stopped, with numbers: "Converged: 6 of 6 modes, max residual 3.1e-12 <= 1e-10".
  std::string message = "solve() was not called.";
  /// "fe", "shooting", "frobenius", "asymptotic", "airy".
  std::string solver;
  /// The resolution actually used, in words: "N = 800 and 1600 elements, Richardson".
  std::string resolution;
  /// Restarts / Newton steps / series terms / root iterations, solver-specific (-1: not counted).
  long iterations = -1;
  /// Mat-vec products, RHS evaluations, ... (-1: not counted).
  long operations = -1;
  /// Largest relative error estimate over the returned frequencies (-1: none).
  double max_error_estimate = -1.0;
  /// e.g. max_i ||K phi - w^2 M phi|| / ||K phi|| (-1: not applicable).
  double max_residual = -1.0;
  /// The relative accuracy of each frequency the solver was asked for (its tolerance, in the
  /// solver's own terms: docs/explanation/methods/<solver>.md), -1 when it was asked for none. A
  /// mode whose error estimate exceeds it is not returned as converged: the part becomes
  /// NoConvergence and the mode is listed in missed_modes (the skeleton applies this rule for every
  /// solver).
  double accuracy_target = -1.0;
  /// The modes beyond accuracy_target, one line each: "in-plane mode 1: estimate 2.4e-07 >
  /// target 1.1e-09" (the part's warnings say why, when the solver knows).
  std::vector<std::string> missed_modes;
  double wall_time_s = -1.0;
  /// Notes a user should read: penalties used, shifts moved, validity limits exceeded.
  std::vector<std::string> warnings;
  /// Facts of the method worth reporting (e.g. "mode count proved by Sylvester inertia: 12").
  std::vector<std::string> notes;

  /// Converged, or NoConvergence with partial results.
  bool is_usable() const;
  /// One line: "<solver>: <termination>: <message> (<resolution>, <time>)".
  std::string brief_report() const;
  /// Several lines, with warnings and notes.
  std::string full_report() const;
};

}  // namespace catena
