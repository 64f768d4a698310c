// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The damped forced response of the frobenius solver (docs/explanation/methods/frobenius.md,
/// "Damping"): the boundary system of frobenius_forced.hpp (fixed end at rest, driven end given
/// its displacement amplitude) with the complex series of frobenius_damped_boundary.hpp at
/// lambda = i Omega. With drag the roots are off the imaginary axis, so the system is regular at
/// every real Omega and the response is finite at resonance; the response is
/// Re[(x + i x_imag) e^(i omega t)] for the end moved by A cos(omega t). The same two evaluations
/// (the second with half the phase per expansion and the series cut 1e-3 finer) give the
/// uncertainty of the matrix; a frequency where the condition number times it reaches 1 is beyond
/// the series' accuracy and declined (never called a resonance: there is none on the real axis).

#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/frobenius/frobenius_damped_boundary.hpp"
#include "solvers/frobenius/frobenius_forced.hpp"

namespace catena::internal {

/// The damped response at each of `forced`'s frequencies, on `stations` (`base.plane` is the
/// in-plane problem; the plane follows the forcing direction).
std::vector<ForcedResponse> frobenius_damped_forced_responses(const DampedSetup& base,
                                                              const ForcedRequest& forced,
                                                              const FieldStations& stations,
                                                              const CableUnits& units,
                                                              ForcedWork& work,
                                                              WorkMeter* meter = nullptr);

}  // namespace catena::internal
