// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The forced response of the frobenius solver (docs/explanation/methods/frobenius.md; Gale 1976,
/// eqs. 2.76-2.79, docs/reference/references.md): the fixed end at rest, the driven end given its
/// displacement amplitude (tangential, normal, a given in-plane vector resolved on the end's
/// tangent and normal, or out of plane), and the fields U, V, T of the solution along the cable.
/// The combination of the basis solves the boundary system with that right-hand side.
///
/// High forcing frequencies: a solution is a wave of wave number Omega sqrt(mu/C), and a series
/// reaching a phase P sums terms of size e^P to an O(1) result. The basis is therefore built with
/// at most kForcedPhasePerExpansion of phase per expansion (more centres as Omega grows), so that
/// cancellation costs at most ~3.5 of long double's 19 digits at any Omega. A frequency that
/// would need more than kForcedMaxCentres centres is declined with that reason.
///
/// Resonance, relative to the solver's own accuracy at that frequency: the boundary matrix is
/// evaluated twice (the second time with half the phase per expansion and series cut 1e-3 finer);
/// the larger of their entrywise difference and the entries' own error estimates, relative to
/// each row (rows equilibrated: at high Omega the U rows are ~Omega^-3 of the column norms), is
/// the matrix's uncertainty e. With kappa the 1-norm condition number of the row-equilibrated
/// matrix, the forcing is at a natural frequency when kappa e >= 1 (the matrix is singular within
/// its own accuracy: the boundary determinant scaled by its condition is at the level of the
/// entries' error); otherwise the response is returned with relative error estimate
/// kappa e + |max|T| of the two evaluations' difference| / max|T|.

#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/frobenius/frobenius_fields.hpp"

namespace catena::internal {

/// Largest phase per series expansion of the forced response's basis [rad]: e^8 ~ 3e3 of
/// cancellation, 3.5 digits.
inline constexpr double kForcedPhasePerExpansion = 8.0;
/// Cap on the expansion centres of one forced frequency's basis (about 0.2 s of work per basis).
inline constexpr int kForcedMaxCentres = 20000;
/// Entries known to worse than this (relative to their row) are not a basis to solve with: the
/// frequency is declined rather than called a resonance.
inline constexpr double kForcedMaxEntryError = 1e-6;

/// The driven end's displacement in Gale's units (of a): tangential U and normal V in plane, or
/// U normal to the plane out of plane.
struct EndDisplacement {
  double u = 0.0;
  double v = 0.0;
};

/// The displacement `forced` prescribes at its end, where sigma = sigma_end, in units of a
/// (`length_m`).
EndDisplacement forced_end_displacement(const ForcedRequest& forced,
                                        double sigma_end,
                                        double length_m);

/// What the forced responses cost, for the summary.
struct ForcedWork {
  long terms = 0;
  int centres = 0;
  long evaluations = 0;
};

/// The response at each of `forced`'s frequencies, on `stations`. `base` is the in-plane boundary
/// problem (the plane follows the forcing direction). `work` gains the largest series and centre
/// counts of the bases used. A `meter` is told each frequency done and may stop early (the
/// responses computed so far).
std::vector<ForcedResponse> frobenius_forced_responses(const PlaneSetup& base,
                                                       const ForcedRequest& forced,
                                                       const FieldStations& stations,
                                                       const CableUnits& units,
                                                       ForcedWork& work,
                                                       WorkMeter* meter = nullptr);

/// Estimated number of expansion centres the forced basis needs at Omega = omega (phase along the
/// longer half of the cable over the phase one expansion covers).
double forced_centres_needed(const PlaneSetup& setup, double omega);

}  // namespace catena::internal
