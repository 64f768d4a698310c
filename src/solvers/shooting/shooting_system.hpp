// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The carried linear system of a `shooting` shot (shooting_integrator.hpp, header): the
/// coefficients B and C at x in the balanced, axial-frame variables, and the right-hand side of
/// the state [Y, phase] or [Y, phase, S] that every integrator of the shot steps
/// (shooting_steppers.hpp). Private to the shooting solver.

#include <Eigen/Dense>
#include <cmath>
#include <cstddef>

#include "solvers/shooting/shooting_coefficients.hpp"

namespace catena::internal {

template <int D>
using Basis = Eigen::Matrix<double, 2 * D, D>;
template <int D>
using Square = Eigen::Matrix<double, D, D>;

/// Everything the right-hand sides need (CVODE's and ARKODE's user data).
struct RhsData {
  ShootingCoefficients coefficients;
  int dimension = 2;
  double omega2 = 0.0;  // scaled Omega^2
  // Symplectic rescaling Phi~ = kappa Phi^, F~ = F^ / kappa with kappa^2 = max(Omega, 1): it
  // balances B and C for the transverse wave, so that the phase turns at a nearly uniform rate
  // (a Pruefer angle of unbalanced variables turns in bursts and costs CVODE many steps).
  double kappa2 = 1.0;
  bool from_b = false;
  // In plane, the constant symplectic change of variables Phi~ = P Phi^, F~ = P^{-T} F^ into the
  // axial frame (axial_frame in the header): P = diag(sigma, 1) R^T, Q = P^{-T}.
  Eigen::Matrix2d to_axial = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d to_axial_force = Eigen::Matrix2d::Identity();
  // The piece being integrated (a general line restarts the stepper at every break).
  std::size_t piece = 0;
  // A shot with the frequency derivative carries S = slope_scale w dY/dw after Y and the phase
  // (header, "Frequency derivative").
  double slope_scale = 0.0;
  // The tolerances of the current shot (slope_error_weights).
  double rtol = 1e-10;
  double atol = 1e-12;
  double atol_phase = 1e-6;
};

// The Winkler foundation under a grounded piece (docs/explanation/methods/shooting.md, "Seabed
// contact"): springs k per unstretched metre (like m, M and W0: docs/explanation/physics.md,
// "Seabed contact: linear dynamics") enter the force balance as F' = -(w^2 Mmat - Kf) D, Kf = k_t t
// t^T + k_s n n^T (out of plane k_t), t = +x: in the scaled, carried variables C -> C - L^2 Q Kf
// Q^T / (T_ref kappa^2).
template <int D>
void subtract_foundation(const RhsData& data, const ShootingPiece& p, Square<D>& C) {
  const ShootingCoefficients& k = data.coefficients;
  const double scale = k.length_m * k.length_m / (k.t_ref * data.kappa2);
  if constexpr (D == 1) {
    C(0, 0) -= scale * p.foundation_tangential;
  } else {
    const Vec2 tq = data.to_axial_force * Vec2(1.0, 0.0), nq = data.to_axial_force * Vec2(0.0, 1.0);
    C -= scale * (p.foundation_tangential * tq * tq.transpose() +
                  p.foundation_normal * nq * nq.transpose());
  }
}

// B and C of the scaled system at x (see the header). From b the variable is x' = 1 - s/L and the
// force is carried as -F^, which leaves the equations unchanged.
template <int D>
void coefficients_at(
    const RhsData& data, double x, Square<D>& B, Square<D>& C, Square<D>* inertia = nullptr) {
  const ShootingCoefficients& k = data.coefficients;
  const ShootingPiece& p = k.pieces[data.piece];
  const double s = k.length_m * (data.from_b ? 1.0 - x : x);
  const double V = p.V_begin + p.W0 * (s - p.s_begin);
  // sqrt, not hypot (a tenth of a shot's time): forces are far from overflow.
  const double T_direction = std::sqrt(k.H * k.H + V * V);
  // On the seabed the tension is the friction profile and the tangent +x (V = 0).
  const double T = p.grounded ? p.tension(k.H, s) : T_direction;
  const double e = T * p.compliance;
  const double b_normal = k.t_ref * (1.0 + e) / T;
  if constexpr (D == 1) {
    B(0, 0) = data.kappa2 * b_normal;
    C(0, 0) = (data.omega2 / data.kappa2) * (p.M / k.M);
  } else {
    const double b_tangent = k.t_ref * p.compliance;
    const Vec2 t(k.H / T_direction, V / T_direction);
    const Vec2 n(-t.y(), t.x());
    const double mass_ratio = p.m / k.M;
    const Vec2 tp = data.to_axial * t, np = data.to_axial * n;
    const Vec2 tq = data.to_axial_force * t, nq = data.to_axial_force * n;
    B = data.kappa2 * (b_tangent * tp * tp.transpose() + b_normal * np * np.transpose());
    C = (data.omega2 / data.kappa2) *
        (mass_ratio * tq * tq.transpose() + (p.M / k.M) * nq * nq.transpose());
  }
  if (inertia) *inertia = C;
  if (p.grounded) subtract_foundation<D>(data, p, C);
}

// Y' = A Y with A = [0 B; -C 0], the phase, and for a shot with the slope S' = A S - 2 c [0; Ci
// Phi] (Ci the inertia part of C, c the slope scale): the derivative of Y' = A Y with respect to
// log w, as C's inertia part is proportional to w^2 and nothing else depends on w (the balancing
// kappa is held at its value for the shot).
template <int D, bool Slope>
void rhs_values(const RhsData& data, double x, const double* state, double* derivative) {
  Eigen::Map<const Basis<D>> Y(state);
  Eigen::Map<Basis<D>> dY(derivative);
  Square<D> B, C, inertia;
  coefficients_at<D>(data, x, B, C, Slope ? &inertia : nullptr);
  const auto Phi = Y.template topRows<D>();
  const auto F = Y.template bottomRows<D>();
  dY.template topRows<D>() = B * F;
  dY.template bottomRows<D>() = -C * Phi;
  // Phase theta = arg det(Phi + i F); its derivative is -tr(G^{-1} N) (header).
  const Square<D> G = Phi.transpose() * Phi + F.transpose() * F;
  const Square<D> N = Phi.transpose() * C * Phi + F.transpose() * B * F;
  derivative[2 * D * D] = -(G.inverse() * N).trace();
  if constexpr (Slope) {
    Eigen::Map<const Basis<D>> S(state + 2 * D * D + 1);
    Eigen::Map<Basis<D>> dS(derivative + 2 * D * D + 1);
    dS.template topRows<D>() = B * S.template bottomRows<D>();
    dS.template bottomRows<D>() =
        -C * S.template topRows<D>() - (2.0 * data.slope_scale) * inertia * Phi;
  }
}

}  // namespace catena::internal
