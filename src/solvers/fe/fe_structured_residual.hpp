// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The residual of fe's in-plane forced problem from the chain's own element data, for one step of
/// iterative refinement (docs/explanation/methods/fe.md, "Forced response and its estimate"). The
/// assembled element stiffness a t t^T + b (I - t t^T), a = EA/l0 and b = T/l, is rounded entry by
/// entry to eps a, which on a penalised chain (a / b ~ 1/kappa) moves the soft transverse stiffness
/// b and, amplified near a resonance, makes the response jump by 1e-5 relative between penalties 1
/// % apart. Summed element by element as a (t . d) t + b (n . d) n in long double, with d the
/// element's end-displacement difference, the residual carries no such rounding: one solve with
/// the assembled factorisation then moves x to the response of the unrounded chain.

#include "catena/core/types.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena::internal {

/// f - (K - omega^2 M) x on the free unknowns of the in-plane chain, with the free displacements
/// `x` and the end displacements `end_a`, `end_b` (the load f is the ends' coupling). The element
/// forces are summed in long double from the chain's a, b, t, n; the mass and the seabed
/// foundation (no cancellation there) from `matrices.mass` and inplane_foundation.
Vector inplane_structured_residual(const FeChain& chain,
                                   const FeMatrices& matrices,
                                   double omega,
                                   const Vector& x,
                                   const Vec2& end_a,
                                   const Vec2& end_b);

}  // namespace catena::internal
