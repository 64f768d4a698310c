// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `airy` solver's out-of-plane model (docs/explanation/methods/airy.md): the string
///     (P v')' + M omega^2 v = 0,   v(0) = v(L) = 0,
/// with its geometric stiffness P = T / (1 + e) (docs/explanation/physics.md) made linear in s,
/// P(s) = P_A + P' s, P' = (P_B - P_A) / L (fit_tension_string: the closest such line in the
/// relative max norm, which makes the model error bound of linear_tension_error_bound smallest).
/// With x = P(s) the equation becomes P'^2 d/dx(x dv/dx) + M omega^2 v = 0, solved exactly by
/// J0(z), Y0(z), z = 2 omega sqrt(M P) / |P'|; the frequencies are the zeros of J0(z_A) Y0(z_B) -
/// J0(z_B) Y0(z_A) = M_A M_B sin(theta_B - theta_A) (modulus-phase form, airy_bessel_phase.hpp).
/// Because the Bessel phase difference
///     Delta(omega) = theta(z_B) - theta(z_A) (taken positive: z_A, z_B ordered)
/// rises strictly from 0 (its derivative is (2 / (pi omega)) (1/M(z_hi)^2 - 1/M(z_lo)^2) > 0,
/// M decreasing), the n-th root is the n-th mode: Delta = n pi, a count that needs no scan. It is
/// written omega tau + phi(omega c_hi) - phi(omega c_lo) with tau = int_0^L sqrt(M / P) ds
/// = 2 L sqrt(M) / (sqrt(P_A) + sqrt(P_B)) and c = 2 sqrt(M P) / |P'|, so no difference of large
/// phases is formed and P' = 0 (c = inf, phi = 0) is the uniform string omega tau = n pi exactly.

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// The linear-tension string of a cable.
struct TensionString {
  double length = 1.0;       // L [m]
  double normal_mass = 1.0;  // M [kg/m]
  double stiffness_a = 1.0;  // P_A = T/(1+e) at s = 0 [N]
  double stiffness_b = 1.0;  // P_B at s = L [N]
};

/// P(s) = T(s) / (1 + e(s)), the out-of-plane geometric stiffness of the statics [N].
double outofplane_stiffness(const StaticSolution& statics, double s);

/// The secant string through the end values of P.
TensionString secant_tension_string(const StaticSolution& statics);

/// A linear-tension string with its relative deviation from the statics,
/// delta >= max_s |P(s) / P_lin(s) - 1|.
struct FittedTensionString {
  TensionString string;
  double deviation = 0.0;
};

/// The secant scaled by 1 + (d_min + d_max) / 2, where [d_min, d_max] is the range of
/// P / P_secant - 1 over `samples` + 1 equally spaced stations: the relative deviation then
/// swings equally to both sides (the static tension is convex, so the secant lies above it and
/// the scaled line halves the deviation). `deviation` is that half range times 1.01 (sampling a
/// near-parabola at 128 intervals misses less than 1e-4 of its extremum).
FittedTensionString fit_tension_string(const StaticSolution& statics, int samples = 128);

/// int_0^s sqrt(M / P_lin) ds [s], without cancellation for any slope.
double string_travel_time(const TensionString& string, double s);

/// Delta(omega) - n pi (see above): strictly increasing in omega > 0, zero at the n-th mode.
double string_phase_residual(const TensionString& string, double omega, int n);

/// The n-th (n >= 1) frequency [rad/s], bracketed in [(n - 1/4) pi / tau, n pi / tau] and
/// refined by TOMS 748 to 2^(1 - tolerance_bits) relative.
double string_frequency(const TensionString& string, int n, int tolerance_bits);

/// The mode at omega on the stations [m] (not normalised):
/// v = M(z) sin(theta(z) - theta(z_A)) evaluated as P^(-1/4) sqrt(z) M(z) sin(...).
Vector string_mode_shape(const TensionString& string, double omega, const Vector& stations_m);

/// Rigorous bound on the relative frequency error of the linear-tension string against the
/// exact string of P(s) with P_lin (1 - delta) <= P <= P_lin (1 + delta): by the min-max
/// principle every omega_n^2 moves by a factor in [1 - delta, 1 + delta], so
/// |omega_lin / omega - 1| <= 1 / sqrt(1 - delta) - 1 (~ delta / 2). +inf when delta >= 1.
double linear_tension_error_bound(double delta);

}  // namespace catena::internal
