// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The omega-independent part of Triantafyllou's Airy model (docs/explanation/methods/airy.md;
/// notation in include/catena/solvers/airy_solver.hpp): the statics at the ends, the transverse
/// travel time and the linear fit Q(s) = Q0 (s - s0) that turns the slow solution into Airy
/// functions.

#include "catena/models/cable.hpp"
#include "catena/solvers/airy_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// Everything of the model that does not depend on omega.
struct AiryModel {
  double length = 1.0;               // L [m]
  double mass = 1.0;                 // m [kg/m]
  double normal_mass = 1.0;          // M [kg/m]
  double h = 1.0;                    // m / M
  double inverse_ea = 0.0;           // 1/EA [1/N], 0 when inextensible
  double alpha_end[2] = {0.0, 0.0};  // static curvature at s = 0, L [1/m]
  double c_end[2] = {1.0, 1.0};      // sqrt(T/M) at s = 0, L [m/s]
  double travel_time = 0.0;          // int_0^L ds / c [s]
  // alpha^2(s) ~ a2_ref + a2_slope (s - s_ref), so Q(s) = m w^2/EA - h alpha^2 = Q0 (s - s0).
  double a2_ref = 0.0;
  double a2_slope = 0.0;
  double s_ref = 0.0;
  double kappa = 0.0;  // Q0^(1/3), Q0 = -h a2_slope (real cube root: negative for a falling chord)
};

/// Static curvature alpha(s) = dphi0/ds = W0 H / T(s)^2 [1/m].
double static_curvature(const StaticSolution& statics, double s);

/// The model of `problem` with Q linearised by `fit`; the travel time by `quadrature_panels`
/// panels of 20-point Gauss-Legendre.
AiryModel build_airy_model(const Problem& problem,
                           const StaticSolution& statics,
                           const DimensionlessGroups& groups,
                           AiryCurvatureFit fit,
                           int quadrature_panels);

/// Argument -z(s) = -Q(s) / kappa^2 of the Airy functions at frequency omega [rad/s], station s
/// [m].
double airy_argument(const AiryModel& model, double omega, double s);

}  // namespace catena::internal
