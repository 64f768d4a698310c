// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The modal mass of a mode of a general line (catena/models/line.hpp) on its stations, shared by
/// the solvers that solve lines (fe, shooting): each segment's densities and each point
/// attachment's mass at its own arc length.

#include "catena/models/line.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// Modal mass of a mode sampled on stations on a general line [kg]: the trapezoidal integral of
/// m u^2 + M w^2 (in plane) or M v^2 (out of plane) with each segment's densities (station
/// intervals are cut at the joints, the shape interpolated linearly there), plus each point
/// attachment's (P + ma_t) u^2 + (P + ma_n) w^2 or (P + ma_out) v^2 at its arc length.
double line_modal_mass(Plane plane,
                       const Mode& mode,
                       const Line& line,
                       const StaticSolution& statics);

}  // namespace catena::internal
