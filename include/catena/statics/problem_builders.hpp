// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Builders of a physical Problem from the dimensionless forms of the published papers
/// (docs/explanation/physics.md, "Dimensionless groups"). Each builder's output, passed through
/// solve_statics and compute_dimensionless_groups, reproduces its inputs (tested to 1e-12).

#include "catena/models/cable.hpp"
#include "catena/statics/gale_coordinates.hpp"

namespace catena {

/// Taut inclined cable from Grinfogel's groups (Grinfogel 1984; docs/reference/references.md): L =
/// 1 m, T0 = 1 N, M = 1 kg/m, m = mass_ratio, W0 = eps, EA = lambda2 / (eps^2 cos^2 phi), H = cos
/// phi; the point where the static angle equals phi sits at s_a, found by a 1-D root so that the
/// chord has angle phi. \param eps W0 L / T0, in (0, 10]. \param phi_deg chord inclination [deg],
/// in [0, 90) (lambda2 is 0 for a vertical cable). \param lambda2 EA eps^2 cos^2(phi) / T0, > 0 and
/// finite. \param mass_ratio h = m / M, in (0, 1].
Problem make_taut_inclined_problem(double eps, double phi_deg, double lambda2, double mass_ratio);

/// Inextensible catenary from Gale's end coordinates xi1 < xi2 (Gale 1976;
/// docs/reference/references.md): a = H/W0 = 1 m, W0 = 1 N/m, m = 1 kg/m (so sqrt(g/a) = 1 rad/s
/// and omega is Gale's ratio), no added mass.
Problem make_gale_xi_problem(double xi1, double xi2);

/// Inextensible catenary from Gale's geometry: h/b (support height difference over span, >= 0)
/// and the sag parameter b / sqrt(l^2 - h^2) in (0, 1). Same units as make_gale_xi_problem.
Problem make_gale_sag_problem(double height_over_span, double sag_parameter);

/// Damping of a make_taut_inclined_problem() problem from nondimensional coefficients (held in the
/// fields of `eta`): c_t = eta_t sqrt(T0 M) / L, c_n = eta_n sqrt(T0 M) / L, c_a = eta_a L sqrt(T0
/// M) with the builder's T0 = 1 N, M and L (docs/reference/scene-format.md, "Damping"). The scene
/// keys are eta_tangential, eta_normal, eta_axial. Validates the problem afterwards.
void set_taut_inclined_damping(Problem& problem, const SectionDamping& eta);
/// Damping of a Gale-form problem (make_gale_xi_problem, make_gale_sag_problem) from Gale's
/// nondimensional drag coefficients (eqs. 2.28e,f): eta = f / rho sqrt(a / g) with rho the mass per
/// length, so f = eta rho sqrt(g / a) (= eta in the form's units). Validates the problem
/// afterwards.
void set_gale_damping(Problem& problem, double eta1, double eta2);
/// Gale's eq. 3.5: a/b from the sag parameter, i.e. the root u of u / sinh(u) = sag_parameter,
/// a/b = 1 / (2u). sag_parameter in (0, 1); returns 0 for sag_parameter = 0.
double gale_a_over_b(double sag_parameter);

}  // namespace catena
