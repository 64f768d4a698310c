#pragma once
/// \file
/// The forced response of the frobenius solver (docs/methods/frobenius.md; Gale 1976, eqs.
/// 2.76-2.79, docs/references.md): the fixed end at rest, the driven end given its displacement
/// amplitude (tangential, normal, a given in-plane vector resolved on the end's tangent and
/// normal, or out of plane), and the fields U, V, T of the solution along the cable. The
/// combination of the basis solves the boundary system with that right-hand side; at a natural
/// frequency (scaled boundary determinant below 1e-13) there is no finite response and the
/// response carries a diagnostic instead.

#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "solvers/internal/frobenius_fields.hpp"
#include "solvers/internal/work_meter.hpp"

namespace catena::internal {

/// The driven end's displacement in Gale's units (of a): tangential U and normal V in plane, or
/// U normal to the plane out of plane.
struct EndDisplacement {
  double u = 0.0;
  double v = 0.0;
};

/// The displacement `forced` prescribes at its end, where sigma = sigma_end, in units of a
/// (`length_m`).
EndDisplacement forced_end_displacement(const ForcedRequest& forced, double sigma_end, double length_m);

/// The response at each of `forced`'s frequencies, on `stations`. `base` is the in-plane boundary
/// problem (the plane follows the forcing direction).
/// A `meter` is told each frequency done and may stop early (the responses computed so far).
std::vector<ForcedResponse> frobenius_forced_responses(const PlaneSetup& base, const ForcedRequest& forced,
                                                       const FieldStations& stations, const CableUnits& units,
                                                       WorkMeter* meter = nullptr);

}  // namespace catena::internal
