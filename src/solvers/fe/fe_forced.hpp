// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver's forced response (docs/explanation/methods/fe.md): a harmonic end displacement
/// d imposed by one banded solve of (K - omega^2 M) x = -K_ib d per forcing frequency and level
/// (each penalty, extrapolated to kappa = 0 when the cable is inextensible),
/// Richardson-extrapolated in h over the main mesh pair (fe_forced_richardson.hpp), with a relative
/// error estimate of the peak tension that includes the amplification of the natural frequencies'
/// errors near a resonance. A forcing frequency at a natural frequency (within the frequency's own
/// error estimate) or at a singular K - omega^2 M gets a diagnostic instead of a response.

#include <utility>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/fe/fe_forced_richardson.hpp"
#include "solvers/fe/fe_levels.hpp"
#include "solvers/fe/fe_shapes.hpp"

namespace catena::internal {

/// A computed natural frequency of the forced plane, for the resonance check and the propagated
/// frequency error of the forced estimate.
struct FeNaturalFrequency {
  int index = 0;
  double omega_rad_s = 0.0;
  /// What the forced response inherits from this mode, relative (negative: unknown). The rounding
  /// of a solve with K - w^2 M, which a stiff chain's normwise floor would bound, is not part of
  /// it: each in-plane solve is refined against the unrounded chain (fe_structured_residual.hpp).
  double relative_error_estimate = -1.0;
  /// Damped lines: the mode's decay rate delta [1/s] and its relative error estimate (-1: none).
  double decay_rate_1_s = 0.0;
  double decay_rate_error_estimate = -1.0;
};

/// The imposed end displacements (end A, end B): the amplitude along the forcing direction at the
/// forced end, zero at the other; out of plane carried in x.
std::pair<Vec2, Vec2> end_displacements(const ForcedRequest& request,
                                        const StaticSolution& statics,
                                        double length_m);

/// The chain's pieces of equal elements, where the response is smooth (fe_forced_richardson.hpp).
std::vector<FeFieldPiece> field_pieces(const FeChain& chain);

/// The plane a forcing moves: out of plane only for a displacement normal to the supports' plane.
Plane forced_plane(const ForcedRequest& request);

/// The resonance diagnostic when `omega` lies within max(1e-9, 3 x relative error estimate) of a
/// natural frequency (relative); empty otherwise.
std::string resonance_diagnostic(double omega,
                                 Plane plane,
                                 const std::vector<FeNaturalFrequency>& naturals);

/// The response of one level (a chain and its operators) at `omega` to end displacements
/// `end_a`, `end_b`: nodal displacements and element tensions; `diagnostic` set (and no response)
/// when K - omega^2 M is singular to rounding.
struct FeLevelResponse {
  bool ok = false;
  std::string diagnostic;
  FeResponseField field;
  /// Bound on the rounding of the element tensions EA/l0 t . (D_{j+1} - D_j) [N]: the nodal
  /// displacements D are rounded to eps |D|, and on a stiff (penalised) chain the axial part of
  /// their difference is far smaller than |D|, so eps max_j EA_j/l0_j (|D_j| + |D_{j+1}|).
  double tension_rounding = 0.0;
};
FeLevelResponse respond_on_level(Plane plane,
                                 const FeChain& chain,
                                 const FeMatrices& matrices,
                                 double omega,
                                 const Vec2& end_a,
                                 const Vec2& end_b);

/// The highest forcing frequency fe answers on the meshes `meshes` of `levels` in `plane`: half
/// the smallest of their top frequencies, bounded by Gershgorin's row sums of K against the lumped
/// M. Above it the discrete model no longer resolves the response (the string's waves span fewer
/// than about 6 elements; far above, K - omega^2 M is omega^2 M to rounding and, at 1e300 rad/s,
/// overflows), so its answer is declined, not a resonance (issue 32, item 10).
double fe_forcing_limit(const FeLevels& levels,
                        const std::vector<std::size_t>& meshes,
                        Plane plane);

/// The diagnostic of a forcing frequency above `limit` (fe_forcing_limit), or empty.
std::string fe_forcing_beyond_mesh(double omega, double limit);

/// Declines a computed response whose relative error estimate is above 1 (or not a number): no
/// digit of it can be trusted, so it is not an answer (issue 32, item 10). True when it declined
/// (the diagnostic then says why); false, and `response` unchanged, otherwise.
bool fe_decline_untrusted_response(ForcedResponse& response);

/// How a relative error delta_n of the natural frequencies propagates into the forced response
/// at `omega`: max over the modes with an estimate of 2 delta_n omega_n^2 / |omega_n^2 - omega^2|
/// (the derivative of 1 / (omega_n^2 - omega^2) times the change 2 delta_n omega_n^2 of omega_n^2,
/// relative). 0 without naturals; infinite on a natural frequency.
double frequency_error_amplification(double omega, const std::vector<FeNaturalFrequency>& naturals);

/// The forced response at every requested frequency, with its summary (Converged: every
/// frequency has a response or a resonance diagnostic, which is the discrete model's answer).
/// Assembles the operators of the forced plane where the levels lack them. `naturals`: the natural
/// frequencies computed for the forced plane (empty when that plane was not asked).
ForcedOutcome fe_forced_response(const ForcedRequest& request,
                                 const SolveContext& context,
                                 const FePlan& plan,
                                 FeLevels& levels,
                                 const std::vector<FeNaturalFrequency>& naturals,
                                 FeTimings& timings);

}  // namespace catena::internal
