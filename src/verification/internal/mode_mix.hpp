// SPDX-License-Identifier: MIT
#pragma once
// The shape mutation of docs/explanation/mutation.md: a mode shape mixed with a neighbouring mode,
// phi_n + delta phi_m, renormalised by the convention of catena/solvers/modal_result.hpp.

#include <optional>

#include "catena/solvers/modal_result.hpp"

namespace catena::internal {

/// The shape the checks and the mutations compare: (u, w) stacked in plane, v out of plane.
Vector stacked_shape(const Mode& mode, Plane plane);
/// True when `mode` carries its shape in `plane`.
bool has_stacked_shape(const Mode& mode, Plane plane);

/// 1 - MAC(p, q) (Euclidean MAC, as the `mac` check computes it).
double one_minus_mac(const Vector& p, const Vector& q);

/// The delta > 0 for which 1 - MAC(p, p + delta r) = drop (bisection; the function grows from 0
/// to 1 - (p.r)^2 / (|p|^2 |r|^2) as delta grows). nullopt when r is (nearly) parallel to p and
/// the drop cannot be reached.
std::optional<double> mix_for_mac_drop(const Vector& p, const Vector& r, double drop);

/// mode <- mode + delta neighbour (displacements and tension curve), scaled back so that the
/// component it was normalised by has max |.| = 1, positive at its first station of largest
/// magnitude; max_abs_tension_n follows the tension curve when there is one.
void mix_modes(Mode& mode, const Mode& neighbour, double delta);

}  // namespace catena::internal
