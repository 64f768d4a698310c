// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The pieces of a general line's statics (docs/explanation/physics.md, "General lines"): the line
/// cut at every joint and point attachment, each piece a closed-form catenary, chained by
/// continuity of position and H and by the jump of V at each point's weight.

#include <Eigen/Dense>
#include <vector>

#include "catena/models/line.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// The section of `segment` as a cable of length `length_m` [m].
CableProperties section_of(const LineSegment& segment, double length_m);

/// The pieces of `line` (validated) with forces (H, V_A) at end A, from A to B.
std::vector<StaticPiece> build_line_pieces(const Line& line, double H, double V_A);

/// r(L) - r(0) of the line: the end of the last piece [m].
Vec2 line_end_offset(const std::vector<StaticPiece>& pieces, double H);

/// d r(L) / d(H, V_A): the sum of the pieces' Jacobians (each piece's start force moves with V_A
/// one to one, since the weights in between are fixed).
Eigen::Matrix2d line_end_jacobian(const std::vector<StaticPiece>& pieces, double H);

}  // namespace catena::internal
