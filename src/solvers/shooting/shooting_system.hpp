// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The carried linear system of a `shooting` shot (shooting_integrator.hpp, header): the
/// coefficients B and C at x in the balanced, axial-frame variables, and the right-hand side of
/// the state [Y, phase] or [Y, phase, S] that every integrator of the shot steps
/// (shooting_steppers.hpp). Private to the shooting solver.

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

#include "solvers/common/drag_profile.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"

namespace catena::internal {

template <int D>
using Basis = Eigen::Matrix<double, 2 * D, D>;
template <int D>
using Square = Eigen::Matrix<double, D, D>;
template <int D>
using ComplexBasis = Eigen::Matrix<std::complex<double>, 2 * D, D>;
template <int D>
using ComplexSquare = Eigen::Matrix<std::complex<double>, D, D>;

/// Everything the right-hand sides need (CVODE's and ARKODE's user data).
struct RhsData {
  ShootingCoefficients coefficients;
  int dimension = 2;
  double omega2 = 0.0;  // scaled Omega^2
  // Symplectic rescaling Phi~ = kappa Phi^, F~ = F^ / kappa with kappa^2 = max(Omega, 1) below a
  // static strain of 1 (set_balance, shooting_shot_setup.hpp): it balances B and C for the
  // transverse wave, so that the phase turns at a nearly uniform rate
  // (a Pruefer angle of unbalanced variables turns in bursts and costs CVODE many steps).
  double kappa2 = 1.0;
  // True where kappa^2 moves with w (kappa ~ sqrt(w)): the slopes then include its change
  // (set_balance in shooting_shot_setup.hpp).
  bool balance_moves = false;
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
  // A damped shot (shooting_damped_integrator.hpp): the characteristic root lambda [1/s] at which
  // the complex system is integrated; unused by the undamped shots.
  std::complex<double> lambda = 0.0;
  // A damped shot with linearised drag (forced_with_drag): the profile added to the pieces' own
  // damping, and the segment of each piece (the profile's factors jump there); null without.
  const DragProfile* drag = nullptr;
  std::vector<std::size_t> drag_segment;
};

// The tangential and normal damping [N s/m per m] of piece p at s [m] (unstretched, from a): the
// section's own, plus the linearised drag of a damped shot that carries one.
struct PieceDamping {
  double tangential = 0.0;
  double normal = 0.0;
};
inline PieceDamping damping_at(const RhsData& data, const ShootingPiece& p, double s) {
  PieceDamping c{p.damping_tangential, p.damping_normal};
  if (data.drag) {
    const std::size_t segment = data.drag_segment[data.piece];
    c.tangential += data.drag->tangential_at(s, segment);
    c.normal += data.drag->normal_at(s, segment);
  }
  return c;
}

// The static state at x on the current piece: s [m], the tension along the chord direction
// (H, V), the tension T (the friction profile on the seabed) and the strain e = T / EA.
struct StaticState {
  double s = 0.0;
  double V = 0.0;
  double T_direction = 0.0;
  double T = 0.0;
  double e = 0.0;
};

inline StaticState static_state_at(const RhsData& data, const ShootingPiece& p, double x) {
  const ShootingCoefficients& k = data.coefficients;
  StaticState state;
  state.s = k.length_m * (data.from_b ? 1.0 - x : x);
  state.V = p.V_begin + p.W0 * (state.s - p.s_begin);
  // sqrt, not hypot (a tenth of a shot's time): forces are far from overflow.
  state.T_direction = std::sqrt(k.H * k.H + state.V * state.V);
  // On the seabed the tension is the friction profile and the tangent +x (V = 0).
  state.T = p.grounded ? p.tension(k.H, state.s) : state.T_direction;
  state.e = state.T * p.compliance;
  return state;
}

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
  const StaticState st = static_state_at(data, p, x);
  const double b_normal = k.t_ref * (1.0 + st.e) / st.T;
  if constexpr (D == 1) {
    B(0, 0) = data.kappa2 * b_normal;
    C(0, 0) = (data.omega2 / data.kappa2) * (p.M / k.M);
  } else {
    const double b_tangent = k.t_ref * p.compliance;
    const Vec2 t(k.H / st.T_direction, st.V / st.T_direction);
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

// The damped coefficients at x for the root lambda = data.lambda (docs/explanation/physics.md,
// "Damping"): the undamped B and C with -w^2 m -> lambda^2 m + lambda c_t, -w^2 M -> lambda^2 M +
// lambda c_n, EA -> EA + c_a lambda and, on the seabed, k_s -> k_s + c_s lambda, in the same
// scaled, balanced, axial-frame variables:
//   B = kappa^2 [T_ref/(EA + c_a lambda) tp tp^T + T_ref (1+e)/T np np^T],
//   C = -(L^2 / (T_ref kappa^2)) [(lambda^2 m + lambda c_t + k_t) tq tq^T
//                                 + (lambda^2 M + lambda c_n + k_s + c_s lambda) nq nq^T],
// (k_t, k_s, c_s on grounded pieces only; out of plane C = -(L^2/(T_ref kappa^2)) (lambda^2 M +
// lambda c_n + k_t)). With lambda = i w and no damping they are coefficients_at's. c_t and c_n are
// damping_at's: the section's and the shot's linearised drag at s (the unstretched arc length of
// x, which runs from b on a shot from b).
template <int D>
void damped_coefficients_at(const RhsData& data,
                            double x,
                            ComplexSquare<D>& B,
                            ComplexSquare<D>& C) {
  using Complex = std::complex<double>;
  const ShootingCoefficients& k = data.coefficients;
  const ShootingPiece& p = k.pieces[data.piece];
  const StaticState st = static_state_at(data, p, x);
  const Complex lambda = data.lambda;
  const double b_normal = k.t_ref * (1.0 + st.e) / st.T;
  const double c_scale = -k.length_m * k.length_m / (k.t_ref * data.kappa2);
  const double k_t = p.grounded ? p.foundation_tangential : 0.0;
  const PieceDamping damping = damping_at(data, p, st.s);
  const Complex normal_load = lambda * lambda * p.M + lambda * damping.normal;
  if constexpr (D == 1) {
    B(0, 0) = data.kappa2 * b_normal;
    C(0, 0) = c_scale * (normal_load + k_t);
  } else {
    const Complex b_tangent =
        k.t_ref * p.compliance / (1.0 + p.compliance * p.damping_axial * lambda);
    const Vec2 t(k.H / st.T_direction, st.V / st.T_direction);
    const Vec2 n(-t.y(), t.x());
    const Vec2 tp = data.to_axial * t, np = data.to_axial * n;
    const Vec2 tq = data.to_axial_force * t, nq = data.to_axial_force * n;
    const Complex tangential = lambda * lambda * p.m + lambda * damping.tangential + k_t;
    const Complex normal =
        normal_load + (p.grounded ? p.foundation_normal + p.foundation_damping * lambda : 0.0);
    B = data.kappa2 * (b_tangent * (tp * tp.transpose()).template cast<Complex>() +
                       b_normal * (np * np.transpose()).template cast<Complex>());
    C = c_scale * (tangential * (tq * tq.transpose()).template cast<Complex>() +
                   normal * (nq * nq.transpose()).template cast<Complex>());
  }
}

// Y' = A(lambda) Y for the complex basis Y = [Phi; F] stored as interleaved real and imaginary
// parts (std::complex's layout): the damped shot carries no phase (the count is the argument
// principle's, shooting_damped_roots.hpp).
template <int D>
void damped_rhs_values(const RhsData& data, double x, const double* state, double* derivative) {
  using Complex = std::complex<double>;
  Eigen::Map<const ComplexBasis<D>> Y(reinterpret_cast<const Complex*>(state));
  Eigen::Map<ComplexBasis<D>> dY(reinterpret_cast<Complex*>(derivative));
  ComplexSquare<D> B, C;
  damped_coefficients_at<D>(data, x, B, C);
  dY.template topRows<D>() = B * Y.template bottomRows<D>();
  dY.template bottomRows<D>() = -C * Y.template topRows<D>();
}

}  // namespace catena::internal
