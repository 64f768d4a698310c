// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Which solvers take a general line (docs/explanation/physics.md, "General lines"): the analytic
/// models (frobenius, asymptotic, airy) are models of one uniform cable, and decline a line of
/// several segments or with point attachments with this reason; and which take a line resting on
/// the seabed (docs/explanation/physics.md, "Seabed contact"): fe and shooting
/// (docs/explanation/methods/fe.md and docs/explanation/methods/shooting.md, "Seabed contact"),
/// which say in their summary which model they used. A seabed the line does not touch changes
/// nothing.

#include <cstdio>
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
inline std::optional<std::string> no_seabed_contact(const StaticSolution& statics,
                                                    const char* model) {
  if (!statics.has_contact()) return std::nullopt;
  return std::string(model) + " has no model of seabed contact; this line rests " +
         std::to_string(statics.grounded_length_m()) + " m of its length on the seabed";
}

/// The note fe and shooting put in their summary on a line with seabed contact: the dynamic model
/// they solved (`discretisation` says how), or nullopt without contact.
inline std::optional<std::string> seabed_model_note(const StaticSolution& statics,
                                                    const std::string& discretisation) {
  if (!statics.has_contact()) return std::nullopt;
  char text[256];
  std::snprintf(
      text, sizeof text,
      "seabed contact: the grounded %.6g m from A move on a Winkler foundation (k_s = %.6g, k_t = "
      "%.6g "
      "N/m per unstretched m) with the friction tension of the statics, the contact set fixed; ",
      statics.grounded_length_m(), statics.seabed().stiffness_n_per_m2,
      statics.seabed().tangential_stiffness_n_per_m2);
  return text + discretisation;
}

}  // namespace catena::internal
