// SPDX-License-Identifier: MIT
// Singular planes of the dynamics on the seabed: see fe_seabed_contact.hpp.
#include "solvers/fe/fe_seabed_contact.hpp"

#include <fmt/format.h>

namespace catena::internal {

double slack_grounded_length_m(const StaticSolution& statics) {
  if (!statics.has_contact()) return 0.0;
  // The statics cuts a grounded stretch where its tension reaches 0, so a piece is slack as a
  // whole when its tension at its midpoint is not positive (any stretch: the friction stretch from
  // an anchor on the seabed, or the grounded part of a slack line, H = 0).
  double slack = 0.0;
  for (const StaticPiece& piece : statics.pieces()) {
    if (!piece.grounded) continue;
    const double middle = piece.s_begin_m + 0.5 * piece.section.length_m;
    if (!(statics.tension_n(middle) > 0.0)) slack += piece.section.length_m;
  }
  return slack;
}

namespace {

// What removes the zero tension: a lower friction for the stretch from an anchor on the seabed
// (its unclipped tension is H - C_B W_g, W_g the grounded weight, so it keeps some tension for
// C_B < H / W_g); nothing for a slack line (H = 0), whose grounded part carries no tension at all.
std::string tension_remedy(const StaticSolution& statics) {
  const double H = statics.horizontal_force_n();
  const Seabed& seabed = statics.seabed();
  const double drop =
      statics.anchor_grounded() ? H - statics.pieces().front().grounded_tension_begin_n : 0.0;
  if (!(H > 0.0) || !(drop > 0.0) || !(seabed.friction > 0.0)) return "";
  return fmt::format(", or a friction below C_B = {:.6g}", seabed.friction * H / drop);
}

}  // namespace

std::optional<std::string> seabed_plane_singular(Plane plane, const StaticSolution& statics) {
  const double slack = slack_grounded_length_m(statics);
  if (!(slack > 0.0)) return std::nullopt;
  const Seabed& seabed = statics.seabed();
  const bool inplane = plane == Plane::InPlane;
  const double stiffness =
      inplane ? seabed.stiffness_n_per_m2 : seabed.tangential_stiffness_n_per_m2;
  if (stiffness > 0.0) return std::nullopt;
  const bool slack_line = !(statics.horizontal_force_n() > 0.0);
  return fmt::format(
      "{}: {:.6g} m of the line rest on the seabed without static tension ({}) and [seabed].{} = "
      "0, so their {} motion has no stiffness (a continuum of zero frequencies): give "
      "[seabed].{} > 0{}",
      to_string(plane), slack,
      slack_line ? "a slack line, H = 0"
                 : fmt::format("seabed friction C_B = {:g} takes it all", seabed.friction),
      inplane ? "stiffness" : "tangential_stiffness", inplane ? "vertical" : "out-of-plane",
      inplane ? "stiffness" : "tangential_stiffness", tension_remedy(statics));
}

std::optional<std::string> slack_line_declined(const StaticSolution& statics) {
  if (!statics.has_contact() || statics.horizontal_force_n() > 0.0) return std::nullopt;
  return fmt::format(
      "a slack line (H = 0): {:.6g} m rest on the seabed without tension and the hanging part "
      "leaves it with zero tension, where fe's chain converges only logarithmically in the mesh "
      "size (the grounded stretch holds the node that the hanging chain's free foot should move): "
      "fe declines it (the hanging part's transverse frequencies are those of the hanging chain, "
      "J0(2 omega sqrt(l M / w)) = 0)",
      slack_grounded_length_m(statics));
}

}  // namespace catena::internal
