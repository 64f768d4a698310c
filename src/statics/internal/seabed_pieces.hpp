// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The pieces of a line resting partly on a flat seabed (docs/explanation/physics.md, "Seabed
/// contact"): the grounded pieces (straight, horizontal, tension set by Coulomb friction) from A to
/// the touchdown point, then the suspended pieces of a general line leaving the seabed with V = 0.

#include <vector>

#include "catena/models/line.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// The part of `line` beyond unstretched arc length `s_m` (0 <= s_m < L), re-based to start at 0;
/// points within 1e-12 L of s_m stay with the part before it. `first_segment` receives the index
/// in line.segments of the part's first segment.
Line line_beyond(const Line& line, double s_m, std::size_t& first_segment);

/// The pieces of `line` (validated) on a seabed at height `seabed_offset_z_m` relative to A, with
/// grounded length `grounded_length_m` (in [0, L)), friction coefficient `friction` and suspended
/// horizontal force `H` (> 0). Offsets are relative to A.
std::vector<StaticPiece> build_seabed_pieces(const Line& line,
                                             double friction,
                                             double seabed_offset_z_m,
                                             double H,
                                             double grounded_length_m);

/// Appends to `pieces` the grounded stretch [0, grounded_length_m) from an anchor A lying on the
/// seabed (offsets relative to A): Coulomb friction C_B = `friction` drops the tension from `H` at
/// its end towards A, down to 0; cut at joints, points and where the tension reaches 0. Returns the
/// stretched length of the stretch (the x of its end) [m].
double append_anchor_stretch(std::vector<StaticPiece>& pieces,
                             const Line& line,
                             double friction,
                             double seabed_offset_z_m,
                             double H,
                             double grounded_length_m);

/// Tension of a grounded piece at `ds` from its start [N]: max(T_begin + slope ds, 0).
double grounded_tension(const StaticPiece& piece, double ds);

/// Stretched length of [0, ds] of a grounded piece, ds + int_0^ds T/EA [m].
double grounded_stretched_increment(const StaticPiece& piece, double ds);

}  // namespace catena::internal
