// SPDX-License-Identifier: MIT
#include "catena/solvers/run_limits.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"

namespace catena {

void RunLimits::check_time_limit(double seconds, const std::string& field) {
  // The upper bound keeps now() + seconds far from the steady clock's overflow (about 292 years).
  if (!std::isfinite(seconds) || seconds <= 0.0 || seconds > kMaxTimeLimit) {
    throw InvalidInput(
        fmt::format("Invalid {} = {}: must be > 0 and <= {:g} [s]", field, seconds, kMaxTimeLimit));
  }
}

RunLimits RunLimits::time_limit(double seconds) {
  check_time_limit(seconds, "RunLimits time limit");
  RunLimits limits;
  limits.time_limit_s = seconds;
  limits.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(seconds));
  return limits;
}

}  // namespace catena
