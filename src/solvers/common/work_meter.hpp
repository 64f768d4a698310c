// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// One part of a run (a plane's modes, the forced frequencies, ...) measured against the run's
/// budget (catena/solvers/run_limits.hpp): it reports progress and says when to stop. A solver
/// calls stop_after(done) after each unit of work at its natural granularity; when it returns
/// true the solver stops and keeps what it has, and message() is the part's reason.

#include <string>

#include "catena/solvers/run_limits.hpp"
#include "catena/solvers/solver_registry.hpp"

namespace catena::internal {

/// "time limit of 5 s reached after 37 of 600 in-plane modes".
std::string time_limit_message(const RunLimits& limits,
                               long done,
                               long total,
                               const std::string& units);

/// Marks the summary of a part stopped by its meter: NoConvergence, and the message
/// "No convergence: time limit of ... reached after k of n ...; <what the part said>" (a leading
/// status word of the part's own message is dropped, not repeated). Does nothing when the meter
/// did not stop.
class WorkMeter;
void mark_time_limit(const WorkMeter& meter, SolverSummary& summary);

class WorkMeter {
 public:
  /// `units`: what is counted, plural ("in-plane modes", "forced frequencies"); `total`: how many
  /// the part has. A null `limits` never stops and reports nothing.
  WorkMeter(const RunLimits* limits, std::string solver, std::string units, long total);
  WorkMeter(const SolveContext& context, std::string solver, std::string units, long total)
      : WorkMeter(context.limits, std::move(solver), std::move(units), total) {}

  /// Records that `done` units are finished and reports it; true when the deadline has passed
  /// and the part must stop (and stays true).
  bool stop_after(long done);
  /// True when the deadline has passed with work left (and stays true), without recording
  /// progress: for checks inside one unit of work (a root's refinement, a long scan), so that a
  /// time limit holds within one evaluation, not one unit.
  bool expired();
  bool stopped() const { return stopped_; }
  long done() const { return done_; }
  /// The reason of a stopped part (empty when it was not stopped).
  std::string message() const;

 private:
  const RunLimits* limits_;
  std::string solver_;
  std::string units_;
  long total_;
  long done_ = 0;
  bool stopped_ = false;
};

}  // namespace catena::internal
