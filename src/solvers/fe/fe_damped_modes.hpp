// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The damped modes of one plane from the `fe` levels (docs/explanation/methods/fe.md,
/// "Damping"): on every level the damping matrix (fe_operators.hpp) and the lowest underdamped
/// roots with their argument-principle count (fe_quadratic_eigen.hpp); the roots paired across
/// levels by their complex shapes (largest |a^H b|^2 / (|a|^2 |b|^2) on the common nodes);
/// omega_d = Im lambda and delta = -Re lambda each extrapolated as the undamped frequency is
/// (Richardson in the mesh, linear in kappa: fe_extrapolation.hpp), each with its own error
/// estimate; complex shapes and Kelvin-Voigt tension from the finest main mesh; the overdamped
/// roots found on every level listed apart.

#include "catena/solvers/modal_result.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/fe/fe_levels.hpp"

namespace catena::internal {

/// Spectra's tolerance for the damped roots (relative, on nu = 1 / lambda): the roots are polished
/// by inverse iteration afterwards (to a backward error ~1e-15), so the Arnoldi iteration need not
/// reach the undamped 1e-13; 1e-8 rather than 1e-10 saved ~6 % of the damped solve.
inline constexpr double kDampedArnoldiTolerance = 1e-8;

/// Assembles C of `plane` and solves its damped roots on every level (as solve_level_modes).
FePlaneEigenReport solve_level_damped_modes(FeLevels& levels,
                                            Plane plane,
                                            int modes,
                                            const FeSolverOptions& options,
                                            FeTimings& timings,
                                            WorkMeter* meter = nullptr);

/// The number of underdamped modes every level delivered in `plane` (at most `modes`).
int damped_modes_on_every_level(const FeLevels& levels, Plane plane, int modes);

/// The plane's modes (ascending omega_d) and overdamped roots from the solved levels, with the
/// error estimates, the proved count and the summary's notes and message (the termination of
/// `result.summary` must be set from the level solves).
void damped_modal_result(const SolveContext& context,
                         const FePlan& plan,
                         const FeLevels& levels,
                         Plane plane,
                         int count,
                         ModalResult& result);

}  // namespace catena::internal
