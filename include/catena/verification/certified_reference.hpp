// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Catena's certified reference for `catena check` (docs/how-to/check.md, "The reference"): of the
/// two exact, reference-grade solvers, shooting and fe (Richardson-extrapolated), the one that
/// converged with the smaller error estimate; when both converged, their largest disagreement is
/// reported as an independent confirmation.

#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/verification/external_check.hpp"

namespace catena {

/// The reference for `plane` from the outputs of one run (which should include every solver of
/// reference_solvers(): shooting and fe, the solvers with SolverEntry::certifies_references). A
/// solver qualifies when its plane converged with at least one mode; among those, the smaller
/// largest error estimate wins (on a tie, the first of reference_solvers(): shooting). nullopt,
/// with `why` saying what each solver reported, when none qualifies.
std::optional<CertifiedReference> certified_reference(const std::vector<SolverOutput>& outputs,
                                                      Plane plane,
                                                      std::string& why);

}  // namespace catena
