// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `asymptotic` solver: Grinfogel's perturbation solution for a taut, inclined, elastic cable
/// (L. Grinfogel, "Dynamics of elastic taut inclined cables", MIT M.S. thesis, 1984;
/// docs/reference/references.md), docs/explanation/methods/asymptotic.md.
///
/// Notation (the paper's): \f$\varepsilon = W_0 L / T_0\f$, \f$\phi_a\f$ the chord inclination,
/// \f$\lambda^2 = EA\,\varepsilon^2\cos^2\phi_a / T_0\f$, \f$h = m/M\f$,
/// \f$k = \omega/\sqrt{T_0/M}\f$, \f$x = kL/2\f$, \f$\xi = s/L\f$ (s from support a),
/// \f$\theta = kL\,\xi\f$, \f$B = \sin kL + kL(k^2L^2/\lambda^2 - 1)\f$,
/// \f$S_2 = 2\sin^2(kL/2)\f$, \f$e_1 = \varepsilon\sin\phi_a\f$.
///
/// In-plane natural frequencies are the roots of eq. (21),
/// \f[ \sin x\,[x\cos x\,(4x^2/\lambda^2 - 1) + \sin x] - \tfrac{49}{64}\,e_1^2 \cos 2x = 0, \f]
/// which for \f$\phi_a = 0\f$ is Irvine's eq. (11): \f$\sin x = 0\f$ (antisymmetric, kL = 2 n pi)
/// or \f$\tan x = x - (4/\lambda^2)x^3\f$ (symmetric). Dividing by \f$\cos^2 x\f$ (never zero at a
/// root when \f$e_1 \ne 0\f$) turns eq. (21) into a quadratic in \f$t = \tan x\f$:
/// \f$(1+c)t^2 + p(x)t - c = 0\f$ with \f$p = 4x^3/\lambda^2 - x\f$, \f$c = \tfrac{49}{64}e_1^2\f$.
/// Its two roots \f$t_-(x) < 0 \le t_+(x)\f$ are smooth in x with \f$|t_\pm'| < 1 \le \sec^2 x\f$,
/// so \f$\tan x - t_\pm(x)\f$ is strictly increasing on every branch of tan: eq. (21) has exactly
/// one root of each family per branch, \f$x_{n,-} \in ((n-\tfrac12)\pi, n\pi]\f$ and
/// \f$x_{n,+} \in [n\pi, (n+\tfrac12)\pi)\f$. The count of eq. (21)'s roots below any frequency
/// is therefore exact, and no root can be skipped near cross-over, where the two roots of branch n
/// straddle \f$x = n\pi\f$ (ModalResult::proved_count_below_top counts these roots). The '+'
/// root of branch 0, at \f$x \approx (c/(1/3 + 4/\lambda^2))^{1/4}\f$, is an artefact of the
/// correction term (which dominates there because the main term vanishes like \f$x^4\f$) and is
/// discarded: no in-plane mode lies below the string bound kL ~ pi. The 'symmetric-like' and
/// 'antisymmetric-like' families exchange roles at cross-over \f$kL = \lambda\f$ (p = 0).
///
/// Out-of-plane frequencies: the WKB string condition
/// \f$\omega \int_0^L \sqrt{M(1+e(s))/T(s)}\,ds = n\pi\f$ with the shared statics T(s), e(s)
/// (the (1+e) factor is the model's exact coefficient T/(1+e) of docs/explanation/physics.md; it is
/// 1 for an inextensible cable), integrated by Gauss–Legendre quadrature.
///
/// Mode shapes (when asked): transverse w from eq. (34) (uniformly valid in lambda^2; with the
/// second-order near-cross-over terms multiplied by \f$\varepsilon^2\sin^2\phi_a\f$ as in eqs.
/// (29), (32): the printed (34) shows \f$\varepsilon^2\sin\phi_a\f$, an OCR/typesetting slip) or
/// the zeroth-order eq. (28); longitudinal u from eq. (37), scaled against w by the fast-solution
/// ratio \f$u/w = \varepsilon\cos\phi_a/(kL)\f$ (i.e. \f$S_f'/S_f\f$); dynamic tension from
/// eq. (38), \f$\tau = M\omega^2 (S_2 + \tfrac74 e_1) L / (\varepsilon\cos\phi_a)\f$ per unit of
/// the same constant, uniform along the cable (quasi-static stretching). The constants
/// \f$C_4\f$, \f$S_f\f$, \f$\det A\f$ are common factors and cancel in the normalisation of
/// modal_result.hpp. The paper measures s from the lower end; for a chord falling from a to b
/// the shapes are evaluated on the mirrored cable.
///
/// Accuracy: the model error is \f$O(\varepsilon^2)\f$ (relative, in frequency); every mode reports
/// relative_error_estimate = eps^2. The formulas assume small eps (a warning is given above
/// AsymptoticSolverOptions::eps_warning_threshold) and quasi-static stretching (a warning when
/// the returned frequencies approach the first axial mode, whose absence from eq. (21) then
/// matters).
///
/// Applicability: a taut cable with a non-vertical chord (H > 0, |phi_a| < 90 deg; for a
/// vertical chord lambda^2 = 0 and eq. (21) degenerates) and eps <= max_eps. Inextensible cables
/// are covered as the limit 1/lambda^2 = 0 (Irvine's inextensible shallow cable).

#include <optional>
#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Which transverse mode-shape formula the asymptotic solver evaluates.
enum class AsymptoticShapeFormula {
  Eq34,  ///< eq. (34): first order plus the second-order near-cross-over terms (default)
  Eq28   ///< eq. (28): zeroth order, outside the hybrid region only (for comparison)
};
/// "34", "28".
std::string to_string(AsymptoticShapeFormula formula);
/// Accepts "34" or "28"; nullopt otherwise.
std::optional<AsymptoticShapeFormula> parse_asymptotic_shape_formula(const std::string& text);

/// Options of the asymptotic solver. Its error is the model's (O(eps^2)); there is no resolution
/// knob (docs/explanation/methods/README.md).
struct AsymptoticSolverOptions {
  /// Transverse shape formula (knob `shape_formula = "34" | "28"`).
  AsymptoticShapeFormula shape_formula = AsymptoticShapeFormula::Eq34;
  /// eps above which the summary warns that the expansion is not meaningful. In (0, max_eps].
  double eps_warning_threshold = 0.3;
  /// eps above which the solver declares itself not applicable. In (0, 10].
  double max_eps = 1.0;
  /// Panels of 20-point Gauss–Legendre quadrature for the WKB integral (out of plane). In
  /// [1, 1000]; T(s) is analytic, so one panel is already at machine precision for eps <= 1.
  int quadrature_panels = 4;

  /// Throws InvalidInput naming the field, its value and the constraint.
  void validate() const;
};

/// Left-hand side of Grinfogel's eq. (21) at \f$kL\f$:
/// \f$\sin(kL/2)[\cos(kL/2)(kL/2)(k^2L^2/\lambda^2 - 1) + \sin(kL/2)] - \tfrac{49}{64}
/// \varepsilon^2 \sin^2\phi_a \cos kL\f$.
/// \param kl kL [-]; \param eps W0 L / T0; \param phi_rad chord angle [rad];
/// \param lambda2 lambda^2 (+inf: inextensible).
double grinfogel_eq21(double kl, double eps, double phi_rad, double lambda2);

/// The lowest `count` physical roots kL of eq. (21), ascending, by the bracketing described in
/// the file comment (exact count; each root to full double precision by TOMS 748 on
/// \f$\sin x - t_\pm(x)\cos x\f$). `count` >= 0; lambda2 > 0 (+inf allowed); eps >= 0.
std::vector<double> grinfogel_eq21_roots(int count, double eps, double phi_rad, double lambda2);

/// kL of the first axial (longitudinal bar) mode in the same units, \f$\pi\lambda/(\varepsilon
/// \cos\phi_a\sqrt h)\f$ = pi sqrt(EA M / (T0 m)); +inf for an inextensible cable.
double first_axial_k_l(double eps, double phi_rad, double lambda2, double mass_ratio);

/// Out-of-plane natural frequencies [rad/s] from the WKB string condition
/// \f$\omega_n \int_0^L \sqrt{M(1+e)/T}\,ds = n\pi\f$, n = 1..count.
/// `quadrature_panels` >= 1 panels of 20-point Gauss–Legendre.
std::vector<double> wkb_outofplane_omegas(const StaticSolution& statics,
                                          int count,
                                          int quadrature_panels = 4);

/// Runs the asymptotic solver on a problem with its statics and groups (see the file comment).
/// Throws InvalidInput for bad options or request; numerical outcomes go in the summaries.
/// Returns NotApplicable (with the reason) for problems outside the theory.
SolverOutput solve_asymptotic(const Problem& problem,
                              const StaticSolution& statics,
                              const DimensionlessGroups& groups,
                              const SolveRequest& request,
                              const AsymptoticSolverOptions& options = {});

/// nullopt when the asymptotic theory applies to the problem; otherwise why not.
std::optional<std::string> asymptotic_not_applicable_reason(
    const Problem& problem,
    const StaticSolution& statics,
    const DimensionlessGroups& groups,
    const AsymptoticSolverOptions& options = {});

}  // namespace catena
