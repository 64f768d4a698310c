// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver's damped forced response with a linearised drag profile (the dynamic tension
/// in waves, docs/explanation/methods/fe.md, "Dynamic tension (linearised drag)"): the damped
/// forced response of fe_damped_forced.hpp, on the same levels, with each element's normal and
/// tangential damping increased by the profile's exact mean over the element's unstretched span
/// (DragProfile::normal_mean, tangential_mean, the segment of its midpoint). The levels' chains,
/// operators and natural frequencies do not depend on the profile and are reused between the
/// fixed point's iterates; an iterate assembles the damping matrices of the forced meshes and
/// solves. The natural frequencies' decay rates (for the resonance amplification of the error
/// estimate) gain the profile's first-order share phi^T C_drag phi / (2 phi^T M phi), from the
/// finest level's vectors.

#include <vector>

#include "solvers/common/drag_profile.hpp"
#include "solvers/fe/fe_damped_forced.hpp"

namespace catena::internal {

/// The chain's damping arrays with the profile added: element j's c_n, c_t plus the profile's
/// means over [s_j, s_{j+1}] (`drag_only`: the profile's means alone, every other damping zero).
FeChain chain_with_drag(const FeChain& chain, const DragProfile& drag, bool drag_only);

/// `naturals` with each decay rate increased by the profile's first-order share, from the
/// vectors of `level` (its undamped eigenvectors, or its damped ones on a damped line; column i
/// for mode i). A mode beyond the vectors keeps its decay rate.
std::vector<FeNaturalFrequency> naturals_with_drag(Plane plane,
                                                   const FeLevel& level,
                                                   const DragProfile& drag,
                                                   const std::vector<FeNaturalFrequency>& naturals);

/// The damped forced response at every requested frequency with `drag` added (the contract of
/// SolverNumerics::forced_with_drag). Assembles the forced plane's operators where the levels
/// lack them; leaves the levels' own damping matrices as they were.
ForcedOutcome fe_drag_forced_response(const ForcedRequest& request,
                                      const DragProfile& drag,
                                      const SolveContext& context,
                                      const FePlan& plan,
                                      FeLevels& levels,
                                      const std::vector<FeNaturalFrequency>& naturals,
                                      FeTimings& timings);

}  // namespace catena::internal
