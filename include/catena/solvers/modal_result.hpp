// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Results every solver returns, in the same structures (docs/reference/json-layout.md).
///
/// Shape normalisation (the common convention every solver follows, so that shapes compare
/// directly): in-plane shapes are scaled so that max_j |w(s_j)| = 1 and w is positive where |w| is
/// largest (the first such station); a mode whose normal motion is negligible (max|w| <= 1e-6
/// max|u|, e.g. the axial modes of a straight bar) is scaled by u instead and `normalised_by` says
/// "u". Out-of-plane shapes are scaled the same way by v. Dynamic tension is given for that
/// scaling, i.e. per unit maximum normal amplitude [N/m of displacement].

#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/solver_summary.hpp"

namespace catena {

/// One natural mode.
///
/// Damped lines (docs/explanation/physics.md, "Damping"): the motion is Re[phi(s) e^(lambda t)]
/// with the characteristic root lambda = -delta + i omega_d. `omega_rad_s` is then the damped
/// frequency omega_d = Im lambda (and Hz, kL/pi and Gale's ratio convert it), `decay_rate_1_s`
/// is delta = -Re lambda and `damping_ratio` is zeta = delta / |lambda|. The shape is complex:
/// u, w, v and tension_n hold its real parts and the `_imag` vectors its imaginary parts, after
/// the normalisation of this file applied to the magnitude (the largest |w| is 1 and real
/// positive). Undamped: delta = zeta = 0 and the `_imag` vectors are empty.
struct Mode {
  /// 1-based, lowest first, within its plane.
  int index = 0;
  /// Natural frequency [rad/s]; for a damped line the damped frequency omega_d = Im lambda.
  double omega_rad_s = 0.0;
  /// delta = -Re lambda [1/s]: the amplitude decays as e^(-delta t); 0 when undamped.
  double decay_rate_1_s = 0.0;
  /// zeta = delta / |lambda| [-]; 0 when undamped, 1 for an overdamped (real) root.
  double damping_ratio = 0.0;
  /// Estimated relative error of decay_rate_1_s on its own, |delta - delta_exact| / delta (the
  /// solver's own estimate; -1: none, or an undamped line).
  double decay_rate_error_estimate = -1.0;
  double frequency_hz = 0.0;
  /// kL/pi with k = omega / sqrt(T0/M).
  double k_l_over_pi = 0.0;
  /// omega / sqrt(g/a) (Gale), when defined.
  std::optional<double> gale_ratio;
  /// Estimated relative error of omega (the solver's own estimate; -1: none).
  double relative_error_estimate = -1.0;
  /// > 1 when this mode belongs to a multiple root whose multiplicity the solver proved by a
  /// count (e.g. shooting's conjugate-point count rising by 2 across a bracket narrower than its
  /// tolerance): the modes of that root share one frequency. Equal frequencies are accepted only
  /// within such a root.
  int multiplicity = 1;
  /// False when relative_error_estimate exceeds the accuracy target of the plane's summary
  /// (SolverSummary::accuracy_target), or there is no estimate to compare: the solver was asked
  /// for an accuracy and does not claim it for this mode (the summary lists it in missed_modes).
  bool meets_target = true;

  /// Present when shapes were asked: stations s [m] and the normalised displacements there.
  Vector s_m;
  /// In-plane: tangential u = Phi . t and normal w = Phi . n [m per unit normalised amplitude].
  Vector u;
  Vector w;
  /// Out-of-plane displacement.
  Vector v;
  /// "w", "u" or "v": which component fixed the scale.
  std::string normalised_by;
  /// Dynamic tension tau(s_j) = t . A Phi' [N], present when tension and shapes were asked.
  Vector tension_n;
  /// Imaginary parts of u, w, v and tension_n for a damped mode (same sizes); empty otherwise.
  Vector u_imag;
  Vector w_imag;
  Vector v_imag;
  Vector tension_imag_n;
  /// max_s |tau| for the normalised mode [N], when tension was asked (-1 otherwise).
  double max_abs_tension_n = -1.0;
  /// int (m u^2 + M w^2) ds (in-plane) or int M v^2 ds (out of plane) for the normalised
  /// shape [kg], when shapes were asked (-1 otherwise).
  double modal_mass_kg = -1.0;
};

/// The modes of one plane.
struct ModalResult {
  Plane plane = Plane::InPlane;
  std::vector<Mode> modes;
  /// Number of eigenvalues proved to lie below (or at) the highest returned frequency, by a
  /// counting argument (Sylvester inertia, conjugate points, Sturm); -1 when the method has none.
  int proved_count_below_top = -1;
  /// Damped lines: the overdamped roots (real lambda = -delta, no oscillation) among the roots of
  /// smallest |lambda| the solver found, listed apart from `modes` (never dropped), ascending in
  /// delta, indexed 1, 2, ...; each has omega_rad_s = 0 and damping_ratio = 1.
  std::vector<Mode> overdamped;
  SolverSummary summary;
};

/// Response to one forcing frequency.
///
/// Resonance is decided by each solver relative to its own accuracy at that frequency, never by a
/// fixed threshold on a determinant (docs/explanation/methods/<solver>.md, "Forced response"): a
/// forcing frequency is at resonance (`at_resonance`, a diagnostic and no fields) only when it lies
/// within the error estimate of a natural frequency the solver computed, |omega - omega_n| <= c
/// omega_n estimate_n, or when the solver's boundary determinant (or pivot), scaled by its
/// condition, is at the level of the solver's own error in it. A finite response that the nearness
/// of a natural frequency amplifies is flagged `near_resonance` (and its error estimate grows). A
/// frequency the method cannot resolve (e.g. too high for its series or mesh) is declined with a
/// diagnostic that says so, with at_resonance false.
struct ForcedResponse {
  double omega_rad_s = 0.0;
  /// Stations [m] and the displacement amplitude there [m] (u, w in plane; v out of plane).
  Vector s_m;
  Vector u;
  Vector w;
  Vector v;
  /// Dynamic tension amplitude [N] (signed: in phase with the forcing).
  Vector tension_n;
  /// Damped lines: the quadrature parts (the response is Re[(x + i x_imag) e^(i omega t)] for a
  /// forcing A cos(omega t)): same sizes as u, w, v and tension_n; empty when undamped.
  Vector u_imag;
  Vector w_imag;
  Vector v_imag;
  Vector tension_imag_n;
  double max_abs_tension_n = 0.0;
  /// Estimated relative error of max_abs_tension_n (the solver's own estimate; -1: none). Near a
  /// resonance the response is sensitive to the natural frequencies, and this estimate grows.
  double relative_error_estimate = -1.0;
  /// Empty when fine; otherwise why this frequency has no finite answer (e.g. "forcing within
  /// 1e-12 of natural frequency 3 (resonance)").
  std::string diagnostic;
  /// True when `diagnostic` is a resonance (no finite response within the solver's accuracy);
  /// false for a frequency declined for another reason.
  bool at_resonance = false;
  /// True for a finite response near a natural frequency (resonance-amplified, sensitive to omega).
  bool near_resonance = false;
};

/// Tension and motion at one end of the line under a motion request.
struct DynamicTensionEnd {
  double s_m = 0.0;
  /// Static (mean) tension [N].
  double mean_n = 0.0;
  /// Regular motion: dynamic tension amplitude |tau| [N] and its phase [deg] relative to the
  /// motion of end b (tau = amplitude cos(omega t + phase)); -1 and 0 when irregular.
  double amplitude_n = -1.0;
  double phase_deg = 0.0;
  /// Irregular motion: standard deviation of the dynamic tension [N], the mean zero up-crossing
  /// period of the tension, 2 pi sqrt(m0 / m2) [s], and the most probable maximum tension in the
  /// request's duration D, mean + sigma sqrt(2 ln N) with N = D / Tz [N] (mean + sigma when N < e);
  /// -1 when regular.
  double std_n = -1.0;
  double zero_upcrossing_period_s = -1.0;
  double most_probable_max_n = -1.0;
};

/// The dynamic tension of one excitation (one period of a regular motion, or the irregular
/// motion), with the Morison drag linearised about the response and iterated to its fixed point
/// (docs/explanation/dynamic-tension.md). Vectors are over the request's stations s_m.
struct DynamicTension {
  bool irregular = false;
  /// Regular: the period [s] and omega = 2 pi / T [rad/s]; 0 when irregular.
  double period_s = 0.0;
  double omega_rad_s = 0.0;
  Vector s_m;
  /// Static tension T0(s) [N].
  Vector mean_n;
  /// Regular: |tau(s)| [N] and its phase [deg]; empty when irregular.
  Vector amplitude_n;
  Vector phase_deg;
  /// Irregular: sigma_tau(s) [N]; empty when regular.
  Vector std_n;
  /// Displacement amplitude |x(s)| (regular) or its standard deviation (irregular) [m].
  Vector motion_m;
  /// The linearised drag at the stations [N s/m per m]: normal c_n(s) and tangential c_t(s) (on
  /// top of the sections' own linear damping).
  Vector normal_damping_n_s_per_m2;
  Vector tangential_damping_n_s_per_m2;
  DynamicTensionEnd fairlead;
  DynamicTensionEnd anchor;
  /// Irregular: the frequency grid [rad/s] and the tension spectra at the ends [N^2 s/rad].
  Vector spectrum_omega_rad_s;
  Vector fairlead_spectrum_n2_s_per_rad;
  Vector anchor_spectrum_n2_s_per_rad;
  /// The fixed point: iterations (linear solves of every frequency), the relative residual
  /// max_s |V(x) - V| / max_s |V(x)| of the velocity scales V (recomputed from the final
  /// response), and whether it reached the request's tolerance.
  int iterations = 0;
  double residual = -1.0;
  bool converged = false;
  /// Estimated relative error of the tension (the linear solves' estimate plus the residual).
  double relative_error_estimate = -1.0;
  /// Empty when converged; otherwise why not (no fixed point within the iterations, a linear
  /// solve that failed, ...).
  std::string diagnostic;
};

/// Everything one solver produced for one problem and request.
struct SolverOutput {
  std::string solver;
  std::optional<ModalResult> inplane;
  std::optional<ModalResult> outofplane;
  std::vector<ForcedResponse> forced;
  /// One per period of a regular motion request, or one for an irregular one.
  std::vector<DynamicTension> dynamic_tension;
  /// Overall summary (NotApplicable with the reason when the solver declined).
  SolverSummary summary;
};

}  // namespace catena
