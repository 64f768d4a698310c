#pragma once
/// \file
/// Closed-form mode shapes of Grinfogel (1984) used by the asymptotic solver (notation in
/// include/catena/solvers/asymptotic_solver.hpp), and the WKB out-of-plane shape.

#include <string>

#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/solvers/modal_result.hpp"

namespace catena::internal {

/// One in-plane mode evaluated on stations, in the units of the paper's brackets (the common
/// factor C4 Sf / det A is set to 1).
struct AsymptoticModeShape {
  /// Transverse (normal) displacement w(s_j): eq. (34) or (28).
  Vector w;
  /// Tangential displacement u(s_j): eq. (37) times eps cos(phi_a) / kL (= Sf'/Sf).
  Vector u;
  /// Leading-order slow transverse amplitude -w_slow = S2 + 7/4 e1 (eqs. 24, 29, 38), in the same
  /// units; the dynamic tension is M omega^2 slow_amplitude L / (eps cos phi_a).
  double slow_amplitude = 0.0;
};

/// Evaluates eqs. (34)/(28) and (37) at the stations s_j [m] of a cable of length L [m] for the
/// root kL. For a falling chord (sin phi_a < 0) the formulas, written with s from the lower end,
/// are evaluated on the mirrored cable (s -> L - s, u -> -u, w -> -w).
AsymptoticModeShape asymptotic_mode_shape(const Vector& stations_m,
                                          double length_m,
                                          double kl,
                                          double eps,
                                          double phi_rad,
                                          double lambda2,
                                          AsymptoticShapeFormula formula);

/// WKB out-of-plane shape (P M)^(-1/4) sin(omega int_0^s sqrt(M/P) ds) with P = T/(1+e), at the
/// stations [m] (not normalised).
Vector wkb_outofplane_shape(const StaticSolution& statics,
                            const Vector& stations_m,
                            double omega_rad_s);

/// Static strain e0 = T0/EA at the point of chord angle (0 when inextensible). Both analytic
/// models linearise about a slightly stretched string: they neglect e0 in k = omega/sqrt(T0/M)
/// (model error e0/2) and do not apply above kMaxStaticStrain.
double static_strain(const Problem& problem, const DimensionlessGroups& groups);
inline constexpr double kMaxStaticStrain = 0.1;

/// The out-of-plane WKB string modes (frequencies by wkb_outofplane_omegas, shapes by
/// wkb_outofplane_shape, normalised; zero first-order tension) as a ModalResult, shared by the
/// asymptotic and airy solvers, which both treat out-of-plane motion this way. Each mode carries
/// `error_estimate`; the summary is Converged, for `solver`, without a message (the caller's).
ModalResult wkb_outofplane_modes(const StaticSolution& statics,
                                 const DimensionlessGroups& groups,
                                 const SolveRequest& request,
                                 double normal_mass_kg_per_m,
                                 double error_estimate,
                                 int quadrature_panels,
                                 const std::string& solver);

}  // namespace catena::internal
