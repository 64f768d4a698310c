// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The asymptotic solver's out-of-plane modes (docs/explanation/methods/asymptotic.md): the WKB
/// string, frequencies omega_n int_0^L sqrt(M (1 + e) / T) ds = n pi (wkb_outofplane_omegas in
/// catena/solvers/asymptotic_solver.hpp) and shapes (P M)^(-1/4) sin(omega int_0^s sqrt(M/P) ds),
/// P = T/(1+e). Only the asymptotic solver uses them; airy has its own out-of-plane model
/// (src/solvers/airy/airy_tension_string.hpp).

#include <string>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// WKB out-of-plane shape (P M)^(-1/4) sin(omega int_0^s sqrt(M/P) ds) with P = T/(1+e), at the
/// stations [m] (not normalised).
Vector wkb_outofplane_shape(const StaticSolution& statics,
                            const Vector& stations_m,
                            double omega_rad_s);

/// The out-of-plane WKB string modes (frequencies by wkb_outofplane_omegas, shapes by
/// wkb_outofplane_shape, normalised; zero first-order tension) as a ModalResult. Each mode
/// carries `error_estimate`; the summary is Converged, for `solver`, without a message (the
/// caller's).
ModalResult wkb_outofplane_modes(const StaticSolution& statics,
                                 const DimensionlessGroups& groups,
                                 const SolveRequest& request,
                                 double normal_mass_kg_per_m,
                                 double error_estimate,
                                 int quadrature_panels,
                                 const std::string& solver);

}  // namespace catena::internal
