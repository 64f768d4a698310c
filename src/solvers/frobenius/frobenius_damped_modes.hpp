// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The damped modes of one plane of the frobenius solver (docs/explanation/methods/frobenius.md,
/// "Damping"): the roots of frobenius_damped_roots.hpp turned into modes (omega_d, delta, zeta and
/// their separate error estimates, complex shapes and tension), the overdamped roots listed apart,
/// and the argument-principle count as the proof of the number of modes.

#include "catena/solvers/modal_result.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "solvers/frobenius/frobenius_damped_roots.hpp"

namespace catena::internal {

/// Gale's drag eta = c / (m sqrt(g/a)) of a coefficient c [N s/m per m].
double gale_drag(double c_n_s_per_m2, const CableUnits& units);

/// The `count` lowest damped modes of `setup` as a ModalResult (summary filled; accuracy_target
/// applies to the relative errors of omega_d and of delta, each on its own).
ModalResult damped_modal_result(const DampedSetup& setup,
                                int count,
                                const RootSettings& settings,
                                const ModeFieldRequest& fields,
                                const CableUnits& units,
                                const DimensionlessGroups& groups,
                                double accuracy_target);

}  // namespace catena::internal
