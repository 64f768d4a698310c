// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The independent check of the in-plane root count of the frobenius solver
/// (docs/explanation/methods/frobenius.md): conjugate points of the clamped end. For this
/// self-adjoint (Hamiltonian) system the number of zeros along the cable of det[U, V] of the two
/// solutions clamped at the first end equals the number of natural frequencies below omega (Morse
/// index), whatever the root scan found.

#include "solvers/frobenius/frobenius_boundary.hpp"
#include "solvers/frobenius/frobenius_root_scan.hpp"

namespace catena::internal {

/// Number of zeros in (sigma1, sigma2] of det [[U_a, U_b], [DU_a, DU_b]] for the two in-plane
/// solutions with U = DU = 0 at sigma1, sampled on `points` equal steps in sigma, in precision `p`.
int conjugate_point_count(Precision p, const PlaneSetup& setup, double omega, int points);

/// Checks the in-plane roots `found` against the conjugate-point count just above the highest of
/// them. On a disagreement the scan is repeated 4x finer (twice at most) and `found` replaced;
/// the notes and warnings of `found` say what happened. Returns the proved count, or -1.
int confirm_inplane_count(const PlaneSetup& setup,
                          int count,
                          const RootSettings& settings,
                          PlaneRoots& found);

}  // namespace catena::internal
