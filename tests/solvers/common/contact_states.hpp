// SPDX-License-Identifier: MIT
#pragma once
// Static states with general seabed contact built by hand from their pieces (the StaticSolution
// pieces constructor), independently of any seabed statics solver: a symmetric U (both ends above
// the seabed, a grounded middle) and a slack line (H = 0: a vertical hanging part, the rest on the
// seabed without tension). The problems carry no seabed (the solvers read it from the statics),
// so that they validate whatever the seabed statics accepts.

#include <vector>

#include "catena/models/cable.hpp"
#include "catena/models/line.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "statics/internal/line_pieces.hpp"

namespace catena::testing {

/// A problem (without seabed) and its hand-built static state on `seabed`.
struct ContactState {
  Problem problem;
  StaticSolution statics;
};

/// The pieces of `cable` cut to `length_m`, shifted to start at arc length `s_begin_m`, offset
/// `offset_m` from A and stretched length `stretched_m` (build_line_pieces starts them at 0).
inline std::vector<StaticPiece> shifted_arc(const CableProperties& cable,
                                            double length_m,
                                            double H,
                                            double V_begin,
                                            double s_begin_m,
                                            const Vec2& offset_m,
                                            double stretched_m) {
  CableProperties arc = cable;
  arc.length_m = length_m;
  std::vector<StaticPiece> pieces = internal::build_line_pieces(line_of_cable(arc), H, V_begin);
  for (StaticPiece& piece : pieces) {
    piece.s_begin_m += s_begin_m;
    piece.offset_begin_m += offset_m;
    piece.stretched_begin_m += stretched_m;
  }
  return pieces;
}

/// Stretched length of an arc (its single piece) of `length_m` with forces (H, V_begin).
inline double arc_stretched_m(const CableProperties& cable, double length_m, double H, double V) {
  CableProperties arc = cable;
  arc.length_m = length_m;
  const StaticSolution alone(arc, Vec2::Zero(), H, V);
  return alone.stretched_length_m(length_m);
}

/// A U of a uniform `cable` (its length_m is ignored): two catenary arcs from their lowest
/// points, `arc_m` from A and `arc_b_m` to B (symmetric when equal, the default), with horizontal
/// force `H`, and `grounded_m` between them on the seabed with tension H (friction not
/// mobilised). A is at x = 0, each end at its arc's height above the seabed.
inline ContactState u_shape(CableProperties cable,
                            double H,
                            double arc_m,
                            double grounded_m,
                            const Seabed& seabed,
                            double arc_b_m = -1.0) {
  if (arc_b_m < 0.0) arc_b_m = arc_m;
  cable.length_m = arc_m + grounded_m + arc_b_m;
  const double w = cable.weight_n_per_m;
  CableProperties arc = cable;
  arc.length_m = arc_m;
  // The first arc descends from A to its lowest point: V from -w l_a to 0.
  const Vec2 drop = catenary_end_offset(arc, H, -w * arc_m);
  const Vec2 a(0.0, seabed.z_m - drop.y());
  std::vector<StaticPiece> pieces =
      shifted_arc(cable, arc_m, H, -w * arc_m, 0.0, Vec2::Zero(), 0.0);
  const double arc_stretch = arc_stretched_m(cable, arc_m, H, -w * arc_m);
  StaticPiece ground;
  ground.section = arc;
  ground.section.length_m = grounded_m;
  ground.s_begin_m = arc_m;
  ground.offset_begin_m = drop;
  ground.stretched_begin_m = arc_stretch;
  ground.grounded = true;
  ground.grounded_tension_begin_n = H;
  ground.grounded_tension_slope_n_per_m = 0.0;
  pieces.push_back(ground);
  const double ground_stretch =
      grounded_m * (1.0 + (cable.is_inextensible() ? 0.0 : H / cable.axial_stiffness_n));
  const Vec2 lift_off = drop + Vec2(ground_stretch, 0.0);
  for (const StaticPiece& piece : shifted_arc(cable, arc_b_m, H, 0.0, arc_m + grounded_m, lift_off,
                                              arc_stretch + ground_stretch))
    pieces.push_back(piece);
  CableProperties arc_b = cable;
  arc_b.length_m = arc_b_m;
  ContactState state;
  state.problem.cable = cable;
  state.problem.supports.a_m = a;
  state.problem.supports.b_m = a + lift_off + catenary_end_offset(arc_b, H, 0.0);
  state.problem.seabed = seabed;  // given statics must be the problem's (statics_match.hpp)
  state.statics = StaticSolution(line_of_cable(cable), a, seabed, H, pieces);
  return state;
}

/// A grounded stretch of `length_m` of `section` from arc length `s_begin_m` at `offset_m`
/// (its height is the seabed's), with tension `H` along it (friction not mobilised).
inline StaticPiece grounded_piece(const CableProperties& section,
                                  double length_m,
                                  double H,
                                  double s_begin_m,
                                  const Vec2& offset_m,
                                  double stretched_m) {
  StaticPiece piece;
  piece.section = section;
  piece.section.length_m = length_m;
  piece.s_begin_m = s_begin_m;
  piece.offset_begin_m = offset_m;
  piece.stretched_begin_m = stretched_m;
  piece.grounded = true;
  piece.grounded_tension_begin_n = H;
  return piece;
}

/// A line in two grounded stretches (a W without its outer arms): `grounded_a_m` from A (on the
/// seabed at z = 0), then a hump of two arcs of `hump_arc_m` held up by a buoy of mass
/// `buoy_mass_kg` at its top (upward force 2 w hump_arc_m: the arcs leave and meet the seabed
/// tangentially), `grounded_b_m` on the seabed, and an arc of `arc_b_m` up to B; tension H on
/// both grounded stretches (C_B = 0).
inline ContactState two_stretch_line(CableProperties cable,
                                     double H,
                                     double grounded_a_m,
                                     double hump_arc_m,
                                     double buoy_mass_kg,
                                     double grounded_b_m,
                                     double arc_b_m,
                                     const Seabed& seabed) {
  const double w = cable.weight_n_per_m;
  const double strain = cable.is_inextensible() ? 0.0 : H / cable.axial_stiffness_n;
  cable.length_m = grounded_a_m + 2.0 * hump_arc_m + grounded_b_m + arc_b_m;
  Line line = line_of_cable(cable);
  PointAttachment buoy;
  buoy.s_m = grounded_a_m + hump_arc_m;
  buoy.mass_kg = buoy_mass_kg;
  buoy.weight_n = -2.0 * w * hump_arc_m;
  buoy.added_mass_kg = 0.5 * buoy_mass_kg;
  line.points.push_back(buoy);
  std::vector<StaticPiece> pieces{grounded_piece(cable, grounded_a_m, H, 0.0, Vec2::Zero(), 0.0)};
  double x = grounded_a_m * (1.0 + strain), stretched = x;
  Line hump = line;
  hump.segments.front().length_m = 2.0 * hump_arc_m;
  hump.points.front().s_m = hump_arc_m;
  const std::vector<StaticPiece> hump_pieces = internal::build_line_pieces(hump, H, 0.0);
  for (StaticPiece piece : hump_pieces) {
    piece.s_begin_m += grounded_a_m;
    piece.offset_begin_m += Vec2(x, 0.0);
    piece.stretched_begin_m += stretched;
    pieces.push_back(piece);
  }
  // The hump is symmetric: it comes back down to the seabed (z = 0 up to rounding).
  const Vec2 hump_offset = internal::line_end_offset(hump_pieces, H);
  stretched += 2.0 * arc_stretched_m(cable, hump_arc_m, H, 0.0);
  x += hump_offset.x();
  const double s_b = grounded_a_m + 2.0 * hump_arc_m;
  pieces.push_back(grounded_piece(cable, grounded_b_m, H, s_b, Vec2(x, 0.0), stretched));
  x += grounded_b_m * (1.0 + strain);
  stretched += grounded_b_m * (1.0 + strain);
  for (const StaticPiece& piece :
       shifted_arc(cable, arc_b_m, H, 0.0, s_b + grounded_b_m, Vec2(x, 0.0), stretched))
    pieces.push_back(piece);
  CableProperties arc_b = cable;
  arc_b.length_m = arc_b_m;
  ContactState state;
  state.problem.line = line;
  state.problem.cable = cable;
  state.problem.supports.a_m = Vec2(0.0, seabed.z_m);
  state.problem.supports.b_m =
      state.problem.supports.a_m + Vec2(x, 0.0) + catenary_end_offset(arc_b, H, 0.0);
  state.problem.seabed = seabed;  // given statics must be the problem's (statics_match.hpp)
  state.statics = StaticSolution(line, state.problem.supports.a_m, seabed, H, pieces);
  return state;
}

/// One arc of the U alone: `arc_m` of `cable` from a fixed end at its lowest point (the U's
/// touchdown point) to the U's end B, in the same equilibrium (H, V = 0 at the fixed end).
inline ContactState u_arc(CableProperties cable, double H, double arc_m) {
  cable.length_m = arc_m;
  ContactState state;
  state.problem.cable = cable;
  state.problem.supports.b_m = catenary_end_offset(cable, H, 0.0);
  state.statics = StaticSolution(cable, Vec2::Zero(), H, 0.0);
  return state;
}

/// A slack line (H = 0) of `cable`: `grounded_m` from A lying on the seabed at z = 0 without
/// tension, then `hanging_m` hanging vertically up to B (V from 0 at the lift-off point).
inline ContactState slack_line(CableProperties cable,
                               double grounded_m,
                               double hanging_m,
                               const Seabed& seabed) {
  cable.length_m = grounded_m + hanging_m;
  StaticPiece ground;
  ground.section = cable;
  ground.section.length_m = grounded_m;
  ground.offset_begin_m = Vec2::Zero();
  ground.grounded = true;
  std::vector<StaticPiece> pieces{ground};
  const Vec2 lift_off(grounded_m, 0.0);
  for (const StaticPiece& piece :
       shifted_arc(cable, hanging_m, 0.0, 0.0, grounded_m, lift_off, grounded_m))
    pieces.push_back(piece);
  CableProperties hanging = cable;
  hanging.length_m = hanging_m;
  ContactState state;
  state.problem.cable = cable;
  state.problem.supports.a_m = Vec2(0.0, seabed.z_m);
  state.problem.supports.b_m =
      state.problem.supports.a_m + lift_off + catenary_end_offset(hanging, 0.0, 0.0);
  state.problem.seabed = seabed;  // given statics must be the problem's (statics_match.hpp)
  state.statics =
      StaticSolution(line_of_cable(cable), state.problem.supports.a_m, seabed, 0.0, pieces);
  return state;
}

}  // namespace catena::testing
