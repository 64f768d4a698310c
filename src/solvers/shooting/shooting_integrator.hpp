// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The integration core of the `shooting` solver (docs/explanation/methods/shooting.md): one "shot"
/// integrates the principal solutions of the linearised cable equations along s, for one frequency,
/// with SUNDIALS ARKODE's ERKStep and Verner's 6(5) pair (the default) or CVODE's Adams or BDF
/// (shooting_steppers.hpp; "Integrators" in docs/explanation/methods/shooting.md).
///
/// Scaled first-order system. With x = s / L, Phi^ = Phi / L and F^ = F / T_ref (T_ref = the
/// larger end tension), the harmonic equations (A Phi')' + w^2 Mmat Phi = 0 become
///
///     dPhi^/dx = B(x) F^,   dF^/dx = -C(x) Phi^,
///     B = T_ref A^{-1} = (T_ref/EA) t t^T + (T_ref (1+e)/T) n n^T,
///     C = Omega^2 Mmat / M,  Omega^2 = w^2 L^2 M / T_ref,
///
/// in plane (Phi, F in R^2, D = 2) and dv^/dx = (T_ref (1+e)/T) G^, dG^/dx = -Omega^2 v^ out of
/// plane (D = 1). B is finite for EA = inf (exact inextensible cable). The principal solutions
/// start at Phi = 0, F = I: a 2D x D basis Y = [Phi; F].
///
/// Counting (Morse index / Sturm). The phase theta = arg det(Phi + i F) evolves along x as
///
///     d theta / dx = -tr[ G^{-1} (Phi^T C Phi + F^T B F) ],   G = Phi^T Phi + F^T F,
///
/// (monotone decreasing where C >= 0; a seabed foundation makes C indefinite, and then only its
/// crossings of det Phi = 0 are one-way, which is all the count needs:
/// docs/explanation/methods/shooting.md, "Seabed contact"), and is integrated as one extra ODE
/// component (so it never needs unwrapping). At the far end it gives the number of conjugate
/// points, i.e. of eigenfrequencies below w, by count_conjugate_points
/// (shooting_conjugate_count.hpp). Out of plane this is Pruefer's angle.
///
/// Loss of independence. The two in-plane columns can grow at different exponential rates (the
/// "chain" solutions of a curved inextensible cable, or large lambda^2). After every step the
/// Gram matrix G is checked; when its condition number exceeds `max_condition` (or the basis scale
/// leaves [1e-6, 1e6]) the basis is replaced by the Q of its QR factorisation with positive
/// diagonal R (so det R > 0: the sign of det Phi and theta are unchanged) and the stepper
/// restarted. The R factors are kept so that a combination of the final basis maps back to every
/// segment.
///
/// Seabed. A shot from a starts with the grounded pieces of a line resting on the seabed
/// (shooting_grounded.hpp): there the directions decouple and each column is integrated as a
/// Pruefer pair, whose cost does not grow with the foundation's stiffness; the growth goes into
/// diagonal R factors, and the general shot takes over at the touchdown point with the phase set
/// from the grounded count.
///
/// Frequency derivative. A shot may also carry S = c w dY/dw (the variational equation): w enters
/// the carried system only through the inertia part Ci of C (proportional to w^2, the balancing
/// kappa held at the shot's value) and the point jumps K (also ~ w^2), so S' = A S - 2 c [0; Ci
/// Phi], S(0) = 0, S_F -> S_F - K S_Phi - 2 c K Phi at a point, S -> S R^{-1} at a
/// re-orthonormalisation. The scale c = atol / (kSlopeAccuracy kappa^2) keeps S near atol /
/// kSlopeAccuracy, so that CVODE controls it to about kSlopeAccuracy relative (enough for Newton's
/// step) and it does not shorten the steps of Y. The slopes of the normalised end determinant and
/// of the end angle follow from S at the end, with the change of kappa itself (kappa ~ sqrt(w)
/// where Omega > 1): they are the total derivatives of the values the shots return. Not carried
/// through the grounded run (its shots come without a slope).
///
/// Balancing. The shot integrates Phi~ = kappa Phi^, F~ = F^ / kappa with kappa^2 = max(Omega, 1)
/// (a constant symplectic scaling: B -> kappa^2 B, C -> C / kappa^2). It balances B and C for the
/// transverse wave so that the phase turns at a nearly uniform rate; unbalanced, the Pruefer-type
/// phase turns in bursts and costs CVODE several times more steps. Results are unscaled.
///
/// Axial frame (in plane). The axial displacement of a nearly straight cable is a small
/// difference of its x and y components (of relative size ~ max(sqrt(T_ref/EA), spread of the
/// tangent angle), 1e-5 on a taut cable at eps = 1e-5), and CVODE, controlling the error of x and
/// y, left it with a few digits: the first in-plane mode of such a cable, which balances the
/// stretch against the geometric shortening, then came out wrong by ~rtol / eps (5e-7 at eps =
/// 1e-5, and moving by more with rtol). The shot therefore integrates Phi~ = P Phi^,
/// F~ = P^{-T} F^ with P = diag(sigma, 1) R^T: R rotates to the mean tangent (the bisector of the
/// end tangents) and sigma = axial_stretch(...) brings the axial component to the size of the
/// normal one (used when sigma >= kMinAxialStretch). P is constant and P, P^{-T} preserve Phi = 0,
/// so the system stays Hamiltonian and monotone (B -> P B P^T, C -> P^{-T} C P^{-1}) and the
/// conjugate points, the count and the sign of the end determinant are those of the physical
/// variables. Results are returned physical.

#include <Eigen/Core>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"

namespace catena::internal {

/// Integrator settings of one ShootingIntegrator.
struct IntegratorSettings {
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-12;
  ShootingMethod method = ShootingMethod::RungeKutta;  ///< the stepper (header, "Integrators")
  bool fixed_point = false;    ///< CVODE: fixed-point iteration instead of Newton + dense LU
  long max_steps = 200000;     ///< per shot
  double max_condition = 1e2;  ///< re-orthonormalise when cond(G) exceeds this
  bool balance = true;         ///< rescale Phi, F by kappa^2 = max(Omega, 1) (off only for studies)
};

/// An integration failure (CVODE's or ARKODE's flag name and the position) inside a
/// shot; the solver turns it into a summary.
class ShootingFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Result of one shot at one frequency.
struct Shot {
  double omega_rad_s = 0.0;
  /// Scaled basis [Phi^; F^] (2D x D) at the far end.
  Eigen::MatrixXd y_end;
  /// det Phi / sqrt(det G) at the far end: invariant under Y -> Y R^{-1} (det R > 0), so a
  /// smooth function of omega in [-1, 1], zero exactly at the natural frequencies.
  double determinant = 0.0;
  /// Conjugate points on (0, L]: eigenfrequencies below omega.
  int count = 0;
  /// Smallest and largest eigen-angle of U at the far end, in [pi, 3 pi) (shifted down by 1e-12
  /// rad) [rad].
  double angle_min = 0.0;
  double angle_max = 0.0;
  /// |theta_integrated - theta_exact| [rad]: integration error of the phase (must be << pi).
  double phase_defect = 0.0;
  /// Stations (when asked): the scaled basis there and the segment it belongs to.
  std::vector<Eigen::MatrixXd> station_y;
  std::vector<int> station_segment;
  /// R factors of the re-orthonormalisations, in order (segment k starts after R_k).
  std::vector<Eigen::MatrixXd> segment_r;
  /// A shot asked for with_slope (and not starting on the seabed): the frequency derivatives of
  /// `determinant` and (D = 1) of the end angle [1/(rad/s), rad/(rad/s)].
  bool has_slope = false;
  double determinant_slope = 0.0;
  double angle_slope = 0.0;
  long steps = 0;
  long rhs_evaluations = 0;
  /// log of the product of det R over the re-orthonormalisations (growth of the basis volume).
  double log_growth = 0.0;
};

/// Integrates principal solutions for one plane; holds the steppers between shots.
class ShootingIntegrator {
 public:
  ShootingIntegrator(Plane plane,
                     const ShootingCoefficients& coefficients,
                     const IntegratorSettings& settings);
  ~ShootingIntegrator();
  ShootingIntegrator(const ShootingIntegrator&) = delete;
  ShootingIntegrator& operator=(const ShootingIntegrator&) = delete;

  /// Shoots at `omega_rad_s` with the tolerances scaled by `tolerance_factor`. `from_b` starts
  /// at s = L and integrates toward s = 0 (then F is returned with its physical sign). Stations
  /// `stations_x` (x = s/L, in the order of integration) are recorded when given. `with_slope`
  /// carries the frequency derivative (header, "Frequency derivative"; Shot::has_slope says
  /// whether it was). Throws ShootingFailure when the integration fails.
  Shot shoot(double omega_rad_s,
             double tolerance_factor = 1.0,
             const std::vector<double>* stations_x = nullptr,
             bool from_b = false,
             bool with_slope = false);

  /// Totals over all shots.
  long total_steps() const;
  long total_rhs_evaluations() const;
  long total_reorthonormalisations() const;
  double max_log_growth() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Relative accuracy to which the carried frequency derivative is integrated (header).
constexpr double kSlopeAccuracy = 1e-6;

/// Largest axial stretch sigma (a straight inextensible cable has no axial scale).
constexpr double kMaxAxialStretch = 1e8;
/// Below this stretch the axial frame is not used (the shot stays in x and y): the axial
/// component is then at most 4x smaller than the normal one and loses no significant digits, and
/// the frequencies of cables with sag stay those of the plain shot.
constexpr double kMinAxialStretch = 4.0;

/// The axial stretch sigma of the axial frame (header comment) for the scaled axial compliance
/// T_ref/EA and the largest angle between a tangent and the mean tangent [rad]:
/// 1/max(sqrt(T_ref/EA), spread), within [1, kMaxAxialStretch] (1 for a cable with sag: nothing to
/// balance).
double axial_stretch(double axial_compliance, double tangent_spread);

/// The solution (scaled [Phi^; F^], a 2D-vector) at station j of a shot for the combination `c`
/// (a D-vector) of the final basis, mapped back through the segment R factors.
Eigen::VectorXd combine_at_station(const Shot& shot, std::size_t j, const Eigen::VectorXd& c);

}  // namespace catena::internal
