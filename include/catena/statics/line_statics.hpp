// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Statics of a general line (docs/explanation/physics.md, "General lines"): segments of different
/// sections, point weights and buoys. H is constant; V jumps by each segment's and each point's
/// weight; each piece between joints and points is an elastic catenary (sagging, straight or
/// hogging).

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Solves (H, V_A) so that the line's end reaches support b: Newton's method on the 2x2 closure
/// with the analytic Jacobian (the sum of the pieces'), a backtracking line search keeping H > 0,
/// started from the parabolic guess of an equivalent uniform cable and, when that start stalls,
/// from H scaled by 10^(+-1, +-2, +-3) (a multi-start globalisation).
///
/// Bad input throws InvalidInput: an invalid problem, an inextensible line not longer than its
/// chord ("line too short for its ends"), a vertical chord (a general line needs a horizontal
/// offset between its ends). A Newton iteration that does not close is returned with
/// `converged == false` and the reason, as solve_statics does.
StaticSolution solve_line_statics(const Problem& problem, const StaticsOptions& options = {});

}  // namespace catena
