#pragma once
/// \file
/// Which solvers take a general line (docs/physics.md, "General lines"): the analytic models
/// (frobenius, asymptotic, airy) are models of one uniform cable, and decline a line of several
/// segments or with point attachments with this reason.

#include <optional>
#include <string>

#include "catena/models/cable.hpp"

namespace catena::internal {

/// The reason a uniform-cable method declines `problem`, or nullopt for a uniform cable.
inline std::optional<std::string> uniform_cable_only(const Problem& problem, const char* model) {
  if (problem.is_uniform()) return std::nullopt;
  return std::string(model) + " is a model of one uniform cable; this line has " +
         std::to_string(problem.line.segments.size()) + " segment(s) and " +
         std::to_string(problem.line.points.size()) + " point attachment(s)";
}

}  // namespace catena::internal
