// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A cooperative budget for one run of the solvers: a wall-clock deadline and a progress report
/// (docs/contributing/architecture.md, "Limits on work").
///
/// The solvers check the budget after each unit of work at their natural granularity (a mode of
/// shooting or frobenius, an eigen solve of an fe level, a forcing frequency, a chunk of an airy
/// scan) and the driver checks it between the parts of a run (each plane, the forced response).
/// The first unit of a part always runs. When the deadline has passed, the part stops and keeps
/// what it has computed: its status is NoConvergence with the message
/// "time limit of X s reached after k of n <units>", and every result it returns is valid. The
/// parts not started are reported the same way with nothing done. A unit already running is not
/// interrupted, so a run may overshoot the deadline by one unit.

#include <chrono>
#include <functional>
#include <optional>
#include <string>

namespace catena {

/// Called as work is done: the solver ("shooting"), the part ("in-plane modes", "forced
/// frequencies", ...), the units done and the units in that part. Called from the thread running
/// the solver, possibly very often (once per forcing frequency): a display should throttle itself.
using ProgressCallback =
    std::function<void(const std::string& solver, const std::string& part, long done, long total)>;

/// The budget of one run; a SolveContext points to it (nullptr: no limit, no progress).
struct RunLimits {
  using Clock = std::chrono::steady_clock;

  /// Stop when this time has passed; none: no time limit.
  std::optional<Clock::time_point> deadline;
  /// The limit as given [s], for the messages.
  double time_limit_s = 0.0;
  /// Progress report; empty: none.
  ProgressCallback progress;

  /// The largest time limit accepted [s] (about 30 years: far from the clock's overflow).
  static constexpr double kMaxTimeLimit = 1e9;
  /// A budget of `seconds` from now (validated as check_time_limit does).
  static RunLimits time_limit(double seconds);
  /// Throws InvalidInput naming `field` unless 0 < seconds <= kMaxTimeLimit.
  static void check_time_limit(double seconds, const std::string& field);
  /// Whether the deadline has passed.
  bool expired() const { return deadline && Clock::now() >= *deadline; }
};

}  // namespace catena
