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
#include <vector>

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

/// The stretches of `statics` resting on the seabed, e.g. "s in [0, 412.3] m and [880, 1010] m"
/// (empty without contact).
inline std::string contact_intervals_text(const StaticSolution& statics) {
  std::string text;
  const std::vector<ContactInterval> intervals = statics.contact_intervals();
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    char interval[96];
    std::snprintf(interval, sizeof interval, "%s[%.6g, %.6g]",
                  i == 0 ? "" : (i + 1 == intervals.size() ? " and " : ", "),
                  intervals[i].s_begin_m, intervals[i].s_end_m);
    text += interval;
  }
  return "s in " + text + " m";
}

/// The reason a method declines a static state with seabed contact (L_g > 0), or nullopt.
inline std::optional<std::string> no_seabed_contact(const StaticSolution& statics,
                                                    const char* model) {
  if (!statics.has_contact()) return std::nullopt;
  char length[64];
  std::snprintf(length, sizeof length, "%.6g", statics.grounded_length_m());
  return std::string(model) + " has no model of seabed contact; this line rests " + length +
         " m of its length on the seabed (" + contact_intervals_text(statics) + ")";
}

/// The note fe and shooting put in their summary on a line with seabed contact: the dynamic model
/// they solved (`discretisation` says how), or nullopt without contact.
inline std::optional<std::string> seabed_model_note(const StaticSolution& statics,
                                                    const std::string& discretisation) {
  if (!statics.has_contact()) return std::nullopt;
  char text[256];
  std::snprintf(text, sizeof text,
                " move on a Winkler foundation (k_s = %.6g, k_t = %.6g N/m per unstretched m) "
                "with the static tension of the statics, the contact set fixed; ",
                statics.seabed().stiffness_n_per_m2,
                statics.seabed().tangential_stiffness_n_per_m2);
  return "seabed contact: the grounded stretches " + contact_intervals_text(statics) + text +
         discretisation;
}

}  // namespace catena::internal
