// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver's damped forced response (docs/explanation/methods/fe.md, "Damping"): one
/// complex symmetric banded solve of (K + i omega C - omega^2 M) x = -(K_ib + i omega C_ib) d per
/// forcing frequency and level (fe_complex_banded_ldlt.hpp), refined once in plane against the
/// chain's element forces (fe_structured_residual.hpp, applied to the real and imaginary parts);
/// the real and imaginary fields extrapolated as the undamped one is (in kappa, Richardson in h:
/// both linear); the dynamic tension tau = (EA + i omega c_a) t . D' / l0 (Kelvin-Voigt). A damped
/// line has no singular resonance: the response is finite at every frequency, and the only
/// diagnostic is a Q(i omega) singular to rounding (a mode the damping does not reach, e.g. the
/// transverse modes of a bar with only axial damping, forced at its frequency). Its error estimate
/// adds to the mesh and kappa terms the amplification of the natural frequencies' and decay
/// rates' errors, 2 |lambda_n|^2 e_n / |omega_n^2 - omega^2 + 2 i delta_n omega| (and the same
/// with 2 delta_n omega d_n), finite at resonance.

#include <vector>

#include "solvers/fe/fe_complex_banded_ldlt.hpp"
#include "solvers/fe/fe_forced.hpp"

namespace catena::internal {

/// The response of one level with its damping matrix; as respond_on_level, with the imaginary
/// (quadrature) parts in `imag`. `pencil`, when given, holds the level's K, C, M
/// (ComplexBandedLdlt::set_pencil) and is refactored at omega: a run of frequencies then skips
/// the sparse matrices' scans.
struct FeDampedLevelResponse {
  bool ok = false;
  std::string diagnostic;
  FeResponseField real;
  FeResponseField imag;
  double tension_rounding = 0.0;
};
FeDampedLevelResponse respond_damped_on_level(Plane plane,
                                              const FeChain& chain,
                                              const FeMatrices& matrices,
                                              const FeDampingMatrix& damping,
                                              double omega,
                                              const Vec2& end_a,
                                              const Vec2& end_b,
                                              ComplexBandedLdlt* pencil = nullptr);

/// The propagated error of the damped natural roots into the response at `omega` (header).
double damped_frequency_error_amplification(double omega,
                                            const std::vector<FeNaturalFrequency>& naturals);

/// The damped forced response at every requested frequency (as fe_forced_response). Assembles the
/// operators and damping of the forced plane where the levels lack them.
ForcedOutcome fe_damped_forced_response(const ForcedRequest& request,
                                        const SolveContext& context,
                                        const FePlan& plan,
                                        FeLevels& levels,
                                        const std::vector<FeNaturalFrequency>& naturals,
                                        FeTimings& timings);

}  // namespace catena::internal
