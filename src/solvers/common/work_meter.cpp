// SPDX-License-Identifier: MIT
// Progress and deadline of one part of a run: see work_meter.hpp.
#include "solvers/common/work_meter.hpp"

#include <fmt/format.h>

namespace catena::internal {

std::string time_limit_message(const RunLimits& limits,
                               long done,
                               long total,
                               const std::string& units) {
  return fmt::format("time limit of {:g} s reached after {} of {} {}", limits.time_limit_s, done,
                     total, units);
}

WorkMeter::WorkMeter(const RunLimits* limits, std::string solver, std::string units, long total)
    : limits_(limits), solver_(std::move(solver)), units_(std::move(units)), total_(total) {}

bool WorkMeter::stop_after(long done) {
  done_ = done;
  if (!limits_) return false;
  if (limits_->progress) limits_->progress(solver_, units_, done, total_);
  stopped_ = stopped_ || (done < total_ && limits_->expired());
  return stopped_;
}

bool WorkMeter::expired() {
  stopped_ = stopped_ || (limits_ && done_ < total_ && limits_->expired());
  return stopped_;
}

std::string WorkMeter::message() const {
  return stopped_ ? time_limit_message(*limits_, done_, total_, units_) : std::string();
}

void mark_time_limit(const WorkMeter& meter, SolverSummary& summary) {
  if (!meter.stopped()) return;
  std::string said = summary.message;
  for (const std::string status : {"Converged: ", "No convergence: ", "Not converged: "}) {
    if (said.rfind(status, 0) == 0) said.erase(0, status.size());
  }
  summary.termination = Termination::NoConvergence;
  summary.message = "No convergence: " + meter.message() + (said.empty() ? "" : "; " + said);
}

}  // namespace catena::internal
