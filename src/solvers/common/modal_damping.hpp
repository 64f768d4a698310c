// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Light damping of an analytic model's modes by first-order perturbation from its own undamped
/// modes (docs/explanation/methods/asymptotic.md, "Damping"; the physics in
/// docs/explanation/physics.md, "Damping"). For the quadratic eigenproblem
/// (lambda^2 Mass + lambda C + K) phi = 0 with C small, the undamped mode phi of omega0 gives
///     delta = phi^T C phi / (2 phi^T Mass phi),   lambda = -delta + i sqrt(omega0^2 - delta^2),
/// which is exact for proportional damping (C = alpha Mass) and otherwise first order in the
/// non-proportional part of C. In plane, with eps_dyn = tau / EA the mode's dynamic strain and
/// w_z its vertical displacement on the grounded part,
///     delta = [int (c_t u^2 + c_n w^2) ds + int c_a eps_dyn^2 ds + int_grounded c_s w_z^2 ds]
///             / (2 int (m u^2 + M w^2) ds),
/// and out of plane delta = int c_n v^2 ds / (2 int M v^2 ds). The asymptotic and airy solvers
/// evaluate their own shapes on the quadrature nodes given here and share everything else
/// through this file, so the formula and the error model exist once.

#include <limits>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/statics/dimensionless_groups.hpp"

namespace catena::internal {

/// Composite Gauss-Legendre nodes (ascending) and weights on [0, L].
struct DampingQuadrature {
  Vector s_m;
  Vector weights;
};

/// Nodes fine enough for the products of a mode whose phase runs through `phase_rad` along the
/// cable (kL, or omega times the transverse travel time): 10-point panels of at most two radians
/// of phase, at least 8 panels. A squared mode then turns through at most omega h = 4 rad per
/// panel, where the 10-point rule's error, (n!)^4 / ((2n+1) ((2n)!)^3) (omega h)^20 = 6e-19 of
/// the panel's share, is below rounding.
DampingQuadrature damping_quadrature(double length_m, double phase_rad);

/// A uniform section's inertia, axial stiffness and damping (per unit unstretched length).
struct DampedSection {
  double mass_kg_per_m = 1.0;
  double normal_mass_kg_per_m = 1.0;
  double axial_stiffness_n = kInfinity;  // EA; inf: inextensible (then c_a = 0)
  SectionDamping damping;
  double seabed_damping_n_s_per_m2 = 0.0;  // c_s, under the grounded part only

  /// The uniform cable of `problem` and its seabed's dashpot (0 without a seabed).
  static DampedSection of(const Problem& problem);
};

/// An undamped in-plane mode sampled on the quadrature nodes, in one common scaling.
struct InplaneModeSamples {
  Vector u;  // tangential displacement
  Vector w;  // normal displacement
  /// Dynamic tension tau (empty: no tension, e.g. an inextensible model).
  Vector tension_n;
  /// Vertical displacement w_z where the line rests on the seabed, 0 elsewhere (empty: no
  /// grounded part).
  Vector grounded_vertical;
};

/// delta [1/s] of an in-plane mode (formula above).
double inplane_decay_rate(const DampingQuadrature& quadrature,
                          const InplaneModeSamples& mode,
                          const DampedSection& section);

/// delta [1/s] of an out-of-plane mode v sampled on the nodes.
double outofplane_decay_rate(const DampingQuadrature& quadrature,
                             const Vector& v,
                             const DampedSection& section);

/// Bound D [1/s] on the non-proportional part of the damping operator in the mass norm, for a
/// mode of frequency omega0: C = r Mass + D with r the mean of c_t/m and c_n/M, so |D| <=
/// |c_t/m - c_n/M| / 2 (0 when the two rates agree to rounding: then C is alpha Mass to rounding,
/// and so is the root), plus c_s/M (the seabed dashpot acts on part of the line only) and, for
/// Kelvin-Voigt, (c_a/EA) omega0^2 (c_a/EA times the axial part of the stiffness, which is at
/// most the stiffness). Out of plane, c_n/M alone: D = 0 (proportional) for a uniform section.
double nonproportional_rate_1_s(Plane plane, const DampedSection& section, double omega0);

/// The relative error of delta from rounding alone: the quotient of two quadratures on the same
/// nodes, a few ulp per term (what proportional damping reports).
inline constexpr double kDecayRoundingEstimate = 64.0 * std::numeric_limits<double>::epsilon();

/// The perturbation's validity limit: above it (the non-proportional damping ratio D/(2 omega0),
/// or the coupling D / (2 |omega_j - omega0|) to the nearest mode) the first-order theory is not
/// meaningful and the plane is declined.
inline constexpr double kMaxPerturbationParameter = 0.3;

/// Turns a plane of undamped modes (frequencies, the model's relative_error_estimate, shapes when
/// asked) and their decay rates (one per mode) into the damped result: lambda = -delta +
/// i sqrt(omega0^2 - delta^2), modes ordered by omega_d and re-indexed, overdamped roots (delta >=
/// omega0: -delta +- sqrt(delta^2 - omega0^2)) listed apart, estimates per
/// docs/explanation/methods/asymptotic.md, "Damping"; shapes stay the undamped (real) ones with
/// zero imaginary parts. When the perturbation is not meaningful for some mode (above
/// kMaxPerturbationParameter), the plane becomes NotApplicable with no modes and the reason.
/// `proved_count_below_top` becomes -1 (the count was of the undamped model's roots). `plane` is
/// the plane of the modes (the driver sets result.plane only after the solver returns).
void apply_perturbed_damping(Plane plane,
                             ModalResult& result,
                             const std::vector<double>& decay_rates_1_s,
                             const DampedSection& section,
                             const DimensionlessGroups& groups);

}  // namespace catena::internal
