#pragma once
/// \file
/// Which solvers take a general line (docs/physics.md, "General lines"): the analytic models
/// (frobenius, asymptotic, airy) are models of one uniform cable, and decline a line of several
/// segments or with point attachments with this reason; and which take a line resting on the
/// seabed (docs/physics.md, "Seabed contact"): fe (docs/methods/fe.md, "Seabed contact"); shooting
/// declines until its dynamics lands. A seabed the line does not touch changes nothing.

#include <optional>
#include <string>

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// The reason a uniform-cable method declines `problem`, or nullopt for a uniform cable.
inline std::optional<std::string> uniform_cable_only(const Problem& problem, const char* model) {
  if (problem.is_uniform()) return std::nullopt;
  return std::string(model) + " is a model of one uniform cable; this line has " +
         std::to_string(problem.line.segments.size()) + " segment(s) and " +
         std::to_string(problem.line.points.size()) + " point attachment(s)";
}

/// The reason a method declines a static state with seabed contact (L_g > 0), or nullopt.
inline std::optional<std::string> no_seabed_contact(const StaticSolution& statics, const char* model) {
  if (!statics.has_contact()) return std::nullopt;
  return std::string(model) + " has no model of seabed contact; this line rests " +
         std::to_string(statics.grounded_length_m()) + " m of its length on the seabed";
}

/// shooting on a line with seabed contact, until its linear dynamics is built.
inline std::optional<std::string> seabed_dynamics_not_implemented(const StaticSolution& statics) {
  if (!statics.has_contact()) return std::nullopt;
  return std::string("seabed contact dynamics: not implemented in this build");
}

}  // namespace catena::internal
