#pragma once
/// \file
/// What the two analytic solvers (asymptotic and airy) share about a taut, slightly stretched
/// cable (docs/methods/asymptotic.md, docs/methods/airy.md): the small-strain limit both
/// linearise about, the WKB out-of-plane string modes both return, and the exact root count of
/// Grinfogel's eq. (21) with the first axial mode, by which airy cross-checks its scan.
///
/// This header is the one door other solvers use to reach these formulas. The eq. (21) roots and
/// the WKB frequencies are still defined next to the asymptotic solver (asymptotic_solver.cpp);
/// only taut_cable_theory.cpp sees that solver's public header.

#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/internal/knob_table.hpp"

namespace catena::internal {

/// Static strain e0 = T0/EA at the point of chord angle (0 when inextensible). Both analytic
/// models linearise about a slightly stretched string: they neglect e0 in k = omega/sqrt(T0/M)
/// (model error e0/2) and do not apply above kMaxStaticStrain.
double static_strain(const Problem& problem, const DimensionlessGroups& groups);
inline constexpr double kMaxStaticStrain = 0.1;

/// The knobs both analytic solvers declare alike: the eps of a validity warning, the eps above
/// which they decline, and the Gauss-Legendre panels of a travel-time integral (`what`).
template <class Options>
std::vector<KnobBinding<Options>> taut_theory_knobs(const std::string& what) {
  return {real_knob("eps_warning_threshold", &Options::eps_warning_threshold, Range::open_closed(0.0, 10.0),
                    "eps above which a validity warning is given (at most max_eps)"),
          real_knob("max_eps", &Options::max_eps, Range::open_closed(0.0, 10.0),
                    "eps above which the solver declines"),
          integer_knob("quadrature_panels", &Options::quadrature_panels, Range::closed(1, 1000),
                       "panels of 20-point Gauss-Legendre for " + what)};
}

/// Throws InvalidInput naming `[solvers.<solver>].eps_warning_threshold` unless it is <= max_eps.
void require_warning_below_max_eps(const std::string& solver, double eps_warning_threshold, double max_eps);

/// WKB out-of-plane shape (P M)^(-1/4) sin(omega int_0^s sqrt(M/P) ds) with P = T/(1+e), at the
/// stations [m] (not normalised).
Vector wkb_outofplane_shape(const StaticSolution& statics,
                            const Vector& stations_m,
                            double omega_rad_s);

/// The out-of-plane WKB string modes (frequencies omega_n int_0^L sqrt(M(1+e)/T) ds = n pi,
/// shapes by wkb_outofplane_shape, normalised; zero first-order tension) as a ModalResult, shared
/// by the asymptotic and airy solvers, which both treat out-of-plane motion this way. Each mode
/// carries `error_estimate`; the summary is Converged, for `solver`, without a message (the
/// caller's).
ModalResult wkb_outofplane_modes(const StaticSolution& statics,
                                 const DimensionlessGroups& groups,
                                 const SolveRequest& request,
                                 double normal_mass_kg_per_m,
                                 double error_estimate,
                                 int quadrature_panels,
                                 const std::string& solver);

/// The lowest `count` physical roots kL of Grinfogel's eq. (21), ascending, with an exact count
/// (the bracketing of docs/methods/asymptotic.md). count >= 0, eps >= 0, lambda2 > 0 (+inf:
/// inextensible).
std::vector<double> eq21_root_k_ls(int count, double eps, double phi_rad, double lambda2);

/// kL of the first axial (longitudinal bar) mode, pi sqrt(EA M / (T0 m)); +inf when inextensible.
double first_axial_mode_k_l(double eps, double phi_rad, double lambda2, double mass_ratio);

}  // namespace catena::internal
