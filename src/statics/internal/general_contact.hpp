// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The statics of a line in general seabed contact (docs/explanation/physics.md, "Seabed
/// contact"): any number of grounded stretches, either end above the seabed, arcs lifted by
/// buoyancy, and slack lines (H = 0). Called by solve_seabed_statics once the line without the
/// seabed has been found to pass below it.

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// Solves `problem` (validated, with a seabed, end B above it) in general contact: H by bisection
/// on the horizontal reach of the pieces built by contact_arcs and build_contact_pieces; H = 0 (a
/// slack line) when even H -> 0 reaches past B. Throws InvalidInput for the cases outside the
/// model, naming them; a bisection that does not close is returned with converged == false.
StaticSolution solve_general_contact(const Problem& problem, const StaticsOptions& options);

}  // namespace catena::internal
