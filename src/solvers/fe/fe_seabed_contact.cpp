// SPDX-License-Identifier: MIT
// Singular planes of the dynamics on the seabed: see fe_seabed_contact.hpp.
#include "solvers/fe/fe_seabed_contact.hpp"

#include <fmt/format.h>

namespace catena::internal {

double slack_grounded_length_m(const StaticSolution& statics) {
  if (!statics.has_contact()) return 0.0;
  // The statics cuts the grounded part where the friction tension reaches 0, so a piece is slack
  // as a whole when its tension at its end (toward B) is not positive.
  double slack = 0.0;
  for (const StaticPiece& piece : statics.pieces()) {
    if (!piece.grounded) break;
    const double end = piece.s_begin_m + piece.section.length_m;
    if (!(statics.tension_n(0.5 * (piece.s_begin_m + end)) > 0.0)) slack += piece.section.length_m;
  }
  return slack;
}

std::optional<std::string> seabed_plane_singular(Plane plane, const StaticSolution& statics) {
  const double slack = slack_grounded_length_m(statics);
  if (!(slack > 0.0)) return std::nullopt;
  const Seabed& seabed = statics.seabed();
  const bool inplane = plane == Plane::InPlane;
  const double stiffness =
      inplane ? seabed.stiffness_n_per_m2 : seabed.tangential_stiffness_n_per_m2;
  if (stiffness > 0.0) return std::nullopt;
  // The anchor's unclipped friction tension is H - C_B W_g (W_g: the grounded weight), so the
  // grounded part keeps some tension for C_B < H / W_g.
  const double H = statics.horizontal_force_n();
  const double drop = H - statics.pieces().front().grounded_tension_begin_n;
  const double largest_friction = seabed.friction * H / drop;
  return fmt::format(
      "{}: the grounded stretch s in [0, {:.6g}] m has no static tension (seabed friction C_B = "
      "{:g} takes it all) "
      "and [seabed].{} = 0, so its {} motion has no stiffness (a continuum of zero frequencies): "
      "give "
      "[seabed].{} > 0, or a friction below C_B = {:.6g}",
      to_string(plane), slack, seabed.friction, inplane ? "stiffness" : "tangential_stiffness",
      inplane ? "vertical" : "out-of-plane", inplane ? "stiffness" : "tangential_stiffness",
      largest_friction);
}

}  // namespace catena::internal
