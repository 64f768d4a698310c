// SPDX-License-Identifier: MIT
// Regenerates verification/comparisons/grinfogel-table-2-2-comparison.csv: every row of Grinfogel
// (1984)'s tables after Fig. 2.2 (verification/reference/published/grinfogel-1984-table-2-2-
// frequencies.csv) beside our `asymptotic` value (eq. 21; vs the 'approx' column) and our `airy`
// value (Triantafyllou's Airy determinant; vs the 'exact' column), with the differences and
// whether they exceed half a unit of the last printed digit (5e-5 in kL/pi).
//
// Usage: catena_analytic_grinfogel_table [REPOSITORY_ROOT] (built with -DCATENA_BUILD_TOOLS=ON).
//
// The paper gives no mass ratio for these tables; h = m/M = 1 (no added mass) is used (eq. 21
// does not depend on h; the Airy model does, weakly, through Q = h (M w^2/EA - alpha^2)), and a
// second airy column with h = 0.5 shows that sensitivity.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "catena/core/version.hpp"
#include "catena/io/csv_table.hpp"
#include "catena/solvers/airy_solver.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"
#include "common/repository_paths.hpp"

namespace {

constexpr double kHalfLastDigit = 5e-5;

// Number of digit positions in which two numbers printed to 4 decimals differ: one differing
// digit with the rest equal is the signature of an OCR (or typing) error.
int differing_digits(double a, double b) {
  const std::string x = fmt::format("{:.4f}", a);
  const std::string y = fmt::format("{:.4f}", b);
  if (x.size() != y.size()) return 99;
  int count = 0;
  for (std::size_t i = 0; i < x.size(); ++i) count += x[i] != y[i];
  // A difference in the final digit alone is a size question, not a substitution.
  if (count == 1 && x.back() != y.back()) return 0;
  return count;
}

double airy_mode(const catena::Problem& problem,
                 const catena::StaticSolution& statics,
                 const catena::DimensionlessGroups& groups,
                 int mode,
                 catena::AiryCurvatureFit fit) {
  catena::SolveRequest request;
  request.inplane_modes = mode;
  catena::AirySolverOptions options;
  options.curvature_fit = fit;
  const catena::SolverOutput out = catena::solve_airy(problem, statics, groups, request, options);
  if (!out.inplane || static_cast<int>(out.inplane->modes.size()) < mode) return std::nan("");
  return out.inplane->modes[static_cast<std::size_t>(mode - 1)].k_l_over_pi;
}

// 'agree' within half a unit of the last printed digit; 'last-digit' within 1.5 units (rounding
// or a last-digit slip); 'one-digit' when a single non-final digit differs (OCR or typing
// suspect); else 'disagree'.
std::string verdict(double difference, int digits) {
  if (std::abs(difference) <= kHalfLastDigit) return "agree";
  if (std::abs(difference) <= 3.0 * kHalfLastDigit) return "last-digit";
  if (digits == 1) return "one-digit";
  return "disagree";
}

}  // namespace

int main(int argc, char** argv) {
  const catena_tools::RepositoryPaths paths = catena_tools::repository_paths(argc, argv);
  const catena::CsvTable published =
      catena::read_csv_table(paths.published + "/grinfogel-1984-table-2-2-frequencies.csv");
  catena::CsvTable out;
  out.comments = {
      "verification/comparisons/grinfogel-table-2-2-comparison.csv",
      "source:    Grinfogel (1984) tables after Fig. 2.2 "
      "(published/grinfogel-1984-table-2-2-frequencies.csv)",
      "           beside catena's asymptotic (eq. 21) and airy (Triantafyllou's Airy determinant) "
      "solvers",
      "generator: verification/tools/analytic_grinfogel_table.cpp "
      "(catena_analytic_grinfogel_table)",
      catena_tools::generated_line(),
      "problem:   make_taut_inclined_problem(eps, phi_deg, lambda2, h = 1); frequencies as kL/pi",
      "columns:   asymptotic_minus_approx, airy_minus_exact = ours - published; *_verdict: 'agree' "
      "when",
      "           |difference| <= 5e-5 (half a unit of the last printed digit), 'last-digit' when "
      "<= 1.5e-4,",
      "           'one-digit' when the two 4-decimal strings differ in exactly one (non-final) "
      "digit",
      "           (OCR/typing suspect), else 'disagree'.",
      "           airy = curvature_fit 'tangent' (default), airy_paper_fit = eqs. (17)-(18) "
      "linearisation,",
      "           airy_h05 = tangent with h = m/M = 0.5 (sensitivity to the unstated mass ratio).",
  };
  out.columns = {"eps",
                 "phi_deg",
                 "lambda2",
                 "mode",
                 "published_exact",
                 "published_approx",
                 "asymptotic",
                 "asymptotic_minus_approx",
                 "asymptotic_verdict",
                 "airy",
                 "airy_minus_exact",
                 "airy_verdict",
                 "airy_paper_fit",
                 "airy_h05",
                 "published_approx_minus_exact",
                 "asymptotic_minus_airy"};
  for (std::size_t row = 0; row < published.rows.size(); ++row) {
    const double eps = *published.number(row, "eps");
    const double phi_deg = *published.number(row, "phi_deg");
    const double lambda2 = *published.number(row, "lambda2");
    const int mode = static_cast<int>(*published.number(row, "mode"));
    const double exact = *published.number(row, "exact");
    const double approx = *published.number(row, "approx");

    const catena::Problem problem = catena::make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0);
    const catena::StaticSolution statics = catena::solve_statics(problem);
    const catena::DimensionlessGroups groups =
        catena::compute_dimensionless_groups(problem, statics);
    const auto roots =
        catena::grinfogel_eq21_roots(mode, groups.eps, groups.chord_angle_rad, groups.lambda2);
    const double asymptotic = roots.back() / catena::kPi;
    const double airy =
        airy_mode(problem, statics, groups, mode, catena::AiryCurvatureFit::Tangent);
    const double airy_paper =
        airy_mode(problem, statics, groups, mode, catena::AiryCurvatureFit::Paper);
    const catena::Problem half = catena::make_taut_inclined_problem(eps, phi_deg, lambda2, 0.5);
    const catena::StaticSolution half_statics = catena::solve_statics(half);
    const double airy_h05 =
        airy_mode(half, half_statics, catena::compute_dimensionless_groups(half, half_statics),
                  mode, catena::AiryCurvatureFit::Tangent);

    out.rows.push_back(
        {published.text(row, "eps"), published.text(row, "phi_deg"), published.text(row, "lambda2"),
         published.text(row, "mode"), published.text(row, "exact"), published.text(row, "approx"),
         fmt::format("{:.6f}", asymptotic), fmt::format("{:+.6f}", asymptotic - approx),
         verdict(asymptotic - approx, differing_digits(asymptotic, approx)),
         fmt::format("{:.6f}", airy), fmt::format("{:+.6f}", airy - exact),
         verdict(airy - exact, differing_digits(airy, exact)), fmt::format("{:.6f}", airy_paper),
         fmt::format("{:.6f}", airy_h05), fmt::format("{:+.4f}", approx - exact),
         fmt::format("{:+.6f}", asymptotic - airy)});
  }
  catena::write_csv_table(paths.comparisons + "/grinfogel-table-2-2-comparison.csv", out);
  return 0;
}
