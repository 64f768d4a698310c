// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `airy` solver: Triantafyllou's Airy-function solution of the linear dynamics of a taut
/// inclined cable, the 'exact' reference of Grinfogel (1984, chapter 1 and §2.1.2;
/// docs/reference/references.md), described in docs/explanation/methods/airy.md. It regenerates the
/// paper's 'exact' column so that it can be compared with the truly exact `shooting` solver: it is
/// itself an asymptotic model (small eps), only a more complete one than eq. (21).
///
/// Model (re-derived from the paper's eqs. 1–5; the printed eqs. 12–13 swap the labels u and w).
/// With u along the static tangent t (s increasing from support a), w along n = t rotated
/// +90 deg, alpha(s) = dphi0/ds = W0 H / T^2 the static curvature, c(s) = sqrt(T(s)/M),
/// W(s) = omega int_0^s ds / c, h = m/M:
///
/// - fast (string-like, WKB) solution, eqs. (7)–(8):
///   \f$w = c^{-1/2}(C_3\cos W + C_4\sin W)\f$,
///   \f$u = \alpha c^{1/2}\omega^{-1}(C_3\sin W - C_4\cos W)\f$;
/// - slow (chain-like) solution, eqs. (9)–(10): with the dynamic tension \f$\tau = m\omega^2 v\f$,
///   \f$v'' + Q(s) v = 0\f$, \f$Q = m\omega^2/EA - h\alpha^2\f$, \f$u = -v'\f$, \f$w = -h\alpha
///   v\f$. Q is linearised in s, \f$Q = Q_0 (s - s_0)\f$ (eqs. 14, 17), so that with \f$\kappa =
///   Q_0^{1/3}\f$ (real cube root, negative for a falling chord) and \f$z = \kappa (s - s_0) =
///   Q/\kappa^2\f$: \f$v = C_1 \mathrm{Ai}(-z) + C_2 \mathrm{Bi}(-z)\f$, \f$u =
///   \kappa(C_1\mathrm{Ai}'(-z) + C_2\mathrm{Bi}'(-z))\f$, \f$w = -h\alpha(C_1\mathrm{Ai}(-z) +
///   C_2\mathrm{Bi}(-z))\f$.
///
/// The natural frequencies are the zeros of the 4x4 determinant of u(0) = w(0) = u(L) = w(L) = 0
/// (eq. 16, in the real form of §3.1), the modes its null vectors, the dynamic tension
/// \f$\tau = m\omega^2 v\f$ (the slow part; the fast part's tension is O(eps^2) smaller).
///
/// Numerics. Ai, Bi, Ai', Bi' come from Boost.Math; for arguments above 25 their exponential
/// factors \f$e^{\mp\frac23 x^{3/2}}\f$ are split off analytically (asymptotic series, DLMF
/// 9.7.5–9.7.8), and in the determinant each Airy column is divided by its largest exponential
/// factor, so Bi's growth can neither overflow nor swamp the determinant (the scaled functions
/// are tested to x = 1e6 through their Wronskian; the solver with Airy arguments up to ~600, i.e.
/// unscaled Bi ~ e^9500, at phi = 1e-3 deg, and lambda^2 from 0.1 to 1e4). For speed, Boost's
/// values are taken once at nodes 0.5 apart on [-40, 25] and continued by Taylor series (from
/// y'' = x y), with a Maclaurin series on [-5, 3]: agreement with Boost ~2e-15 (Taylor) and
/// 2e-13 (Maclaurin), 12x faster. Rows and columns are then equilibrated (positive factors: the
/// zero set and signs are unchanged). Roots are found by a scan in kL with sign changes, plus a
/// Brent search at every grid minimum of |det| (two close roots between two samples of equal
/// sign, as in the hybrid region, show up as such a minimum), refined by TOMS 748.
/// The model has a spurious root at kL = O(eps) (where the WKB fast solution is meaningless);
/// roots below `cutoff_fraction` times the rigorous lower bound for the first in-plane mode,
/// \f$\pi\sqrt{\min_s (T/(1+e)) / T_0}\f$ (Rayleigh: A >= T/(1+e) I, Mmat <= M I), are skipped.
///
/// Out of plane the solver returns the same WKB string frequencies as `asymptotic` (the Airy
/// model is in-plane only).
///
/// Applicability: inclined (not horizontal: Q0 = 0 there and the solution degenerates into
/// Irvine's, which `asymptotic` gives exactly; not vertical: alpha = 0), eps <= max_eps.

#include <optional>
#include <string>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// How Q(s) = m omega^2/EA - h alpha(s)^2 is made linear in s.
enum class AiryCurvatureFit {
  Tangent,  ///< Taylor expansion of alpha^2 (exact statics) at s_a, where T = T0 (default;
            ///< Q0 equals eq. (17) exactly there and the paper's 'exact' column is reproduced
            ///< to ~1e-4 for eps = 0.18)
  Secant,   ///< the line through alpha(0)^2 and alpha(L)^2
  Paper     ///< eqs. (17)-(18): h eps^2 cos^2(phi)/L^2 {k^2L^2/lambda^2 - 1 + 4 eps sin(phi)(s/L -
            ///< 1/2)}
};
/// "tangent", "secant", "paper".
std::string to_string(AiryCurvatureFit fit);
std::optional<AiryCurvatureFit> parse_airy_curvature_fit(const std::string& text);

/// Options of the airy solver.
struct AirySolverOptions {
  /// Linearisation of Q(s) (knob `curvature_fit`: "tangent" | "secant" | "paper").
  AiryCurvatureFit curvature_fit = AiryCurvatureFit::Tangent;
  /// Scan step in kL/pi [-] (knob `scan_step`). In [1e-4, 0.5]. Close pairs between two samples are
  /// caught by the |det| minimum search; smaller steps only cost time.
  double scan_step_k_l_over_pi = 0.05;
  /// Roots below cutoff_fraction * pi sqrt(min(T/(1+e))/T0) (in kL) are discarded as spurious.
  /// In (0, 1). Measured: the spurious root lies at kL/pi ~ 0.05-0.4 for eps <= 0.5 and up to
  /// 0.56 at eps = 1 (phi = 10 deg, lambda^2 = 1e3), where this cutoff is 0.74.
  double cutoff_fraction = 0.75;
  /// The scan gives up above this kL/pi (0: automatic, 2 * modes + 20). >= 0.
  double max_k_l_over_pi = 0.0;
  /// Root tolerance: bits of TOMS 748 agreement in kL. In [20, 53].
  int tolerance_bits = 50;
  /// eps above which the summary warns; eps above max_eps: not applicable.
  double eps_warning_threshold = 0.3;
  double max_eps = 1.0;
  /// Panels of 20-point Gauss–Legendre for the travel time int ds / c. In [1, 1000].
  int quadrature_panels = 4;

  /// Throws InvalidInput naming the field, its value and the constraint.
  void validate() const;
};

/// The equilibrated determinant of the boundary system at kL (sign and zeros are those of
/// eq. 16). Exposed for tests and stress drivers.
double airy_frequency_determinant(const Problem& problem,
                                  const StaticSolution& statics,
                                  const DimensionlessGroups& groups,
                                  double k_l,
                                  const AirySolverOptions& options = {});

/// Runs the airy solver (see the file comment). Throws InvalidInput for bad options or request;
/// numerical outcomes go in the summaries; NotApplicable (with the reason) outside the model.
SolverOutput solve_airy(const Problem& problem,
                        const StaticSolution& statics,
                        const DimensionlessGroups& groups,
                        const SolveRequest& request,
                        const AirySolverOptions& options = {});

/// nullopt when the Airy model applies; otherwise why not.
std::optional<std::string> airy_not_applicable_reason(const Problem& problem,
                                                      const StaticSolution& statics,
                                                      const DimensionlessGroups& groups,
                                                      const AirySolverOptions& options = {});

}  // namespace catena
