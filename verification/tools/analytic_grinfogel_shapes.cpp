// SPDX-License-Identifier: MIT
// Regenerates two comparison tables of Grinfogel's closed-form modes against the Airy model
// (Triantafyllou's solution, the paper's own 'exact' reference, solved by catena's airy solver):
//
// 1. verification/comparisons/grinfogel-shapes-34-vs-airy.csv: max |w - w_airy| over the cable
//    (both normalised to max|w| = 1, modal_result.hpp) for the transverse shapes of eq. (34),
//    eq. (34) with its second-order bracket multiplied by eps^2 sin(phi) as printed (instead of
//    eps^2 sin^2(phi) as in eqs. 29, 32), and eq. (28); same for u from eq. (37); and the dynamic
//    tension of eq. (38) vs the Airy model's m w^2 v (per unit max normal amplitude).
// 2. verification/comparisons/grinfogel-fig-4-3-2-tension.csv: the first mode's dynamic tension
//    against lambda^2 through cross-over (the amplification of the paper's Fig. 4.3.2), eq. (38) vs
//    the Airy model, eps = 0.18, phi = 23.46 deg, h = 1.
//
// Usage: catena_analytic_grinfogel_shapes [REPOSITORY_ROOT] (built with -DCATENA_BUILD_TOOLS=ON).
// Uses two private headers (an exception listed in verification/tools/CMakeLists.txt): the
// printed reading of eq. (34) is not a solver option.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "catena/core/version.hpp"
#include "catena/io/csv_table.hpp"
#include "catena/solvers/airy_solver.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "common/repository_paths.hpp"
#include "solvers/asymptotic/asymptotic_formulas.hpp"
#include "solvers/common/mode_tools.hpp"

namespace {

using catena::Index;
using catena::Vector;

// The second-order near-cross-over bracket of eq. (34) (without its eps^2 sin^2 factor).
double second_order_bracket(double xi, double kl) {
  const double theta = kl * xi;
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return 3.5 * (xi - 0.5) + 1.75 * c - (7.0 / 16.0) * (xi - 0.5) * c - 7.0 / 32.0 +
         (7.0 / 16.0) * theta * (xi - 1.0) * s;
}

// Normalises (w, u) like every solver and returns the max |w - reference| (and u likewise).
std::pair<double, double> shape_difference(const Vector& w,
                                           const Vector& u,
                                           const catena::Mode& reference) {
  catena::Mode mode;
  mode.w = w;
  mode.u = u;
  catena::internal::normalise_inplane_mode(mode);
  return {(mode.w - reference.w).cwiseAbs().maxCoeff(),
          (mode.u - reference.u).cwiseAbs().maxCoeff()};
}

struct Solved {
  catena::Problem problem;
  catena::StaticSolution statics;
  catena::DimensionlessGroups groups;
};

Solved make(double eps, double phi_deg, double lambda2) {
  Solved s{catena::make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0), {}, {}};
  s.statics = catena::solve_statics(s.problem);
  s.groups = catena::compute_dimensionless_groups(s.problem, s.statics);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string directory = catena_tools::repository_paths(argc, argv).comparisons;
  catena::SolveRequest request;
  request.inplane_modes = 2;
  request.shapes = true;
  request.tension = true;
  request.points = 401;

  catena::CsvTable shapes;
  shapes.comments = {
      "verification/comparisons/grinfogel-shapes-34-vs-airy.csv",
      "source:    Grinfogel (1984) eqs. (34), (28), (37), (38) (asymptotic solver) vs "
      "Triantafyllou's Airy",
      "           model (airy solver, curvature_fit tangent); phi = 30 deg, h = 1, 401 stations",
      "generator: verification/tools/analytic_grinfogel_shapes.cpp "
      "(catena_analytic_grinfogel_shapes)",
      catena_tools::generated_line(),
      "columns:   max_abs_dw_* = max_s |w - w_airy| with both normalised to max|w| = 1 [-]:",
      "           34 = eq. (34) with eps^2 sin^2(phi) (as in eqs. 29, 32; our reading),",
      "           34_printed = eq. (34) with eps^2 sin(phi) as printed, 28 = eq. (28);",
      "           max_abs_du_37 = same for u (eq. 37 scaled by eps cos(phi)/kL);",
      "           tension_rel_diff = eq. (38) / airy max|tau| - 1 (per unit max normal amplitude).",
  };
  shapes.columns = {"eps",
                    "phi_deg",
                    "lambda2",
                    "mode",
                    "k_l_over_pi_eq21",
                    "k_l_over_pi_airy",
                    "max_abs_dw_34",
                    "max_abs_dw_34_printed",
                    "max_abs_dw_28",
                    "max_abs_du_37",
                    "tension_rel_diff"};
  const double phi_deg = 30.0;
  for (double eps : {0.02, 0.05, 0.1, 0.18}) {
    for (double lambda2 : {20.0, 30.0, 38.0, 4.0 * catena::kPi * catena::kPi, 45.0, 80.0}) {
      const Solved s = make(eps, phi_deg, lambda2);
      const catena::SolverOutput airy = catena::solve_airy(s.problem, s.statics, s.groups, request);
      const catena::SolverOutput asym =
          catena::solve_asymptotic(s.problem, s.statics, s.groups, request);
      if (!airy.inplane || airy.inplane->modes.size() < 2) continue;
      const double e1 = s.groups.eps * std::sin(s.groups.chord_angle_rad);
      for (std::size_t m = 0; m < 2; ++m) {
        const catena::Mode& reference = airy.inplane->modes[m];
        const double kl = asym.inplane->modes[m].k_l_over_pi * catena::kPi;
        const auto shape34 = catena::internal::asymptotic_mode_shape(
            reference.s_m, s.problem.cable.length_m, kl, s.groups.eps, s.groups.chord_angle_rad,
            s.groups.lambda2, catena::AsymptoticShapeFormula::Eq34);
        const auto shape28 = catena::internal::asymptotic_mode_shape(
            reference.s_m, s.problem.cable.length_m, kl, s.groups.eps, s.groups.chord_angle_rad,
            s.groups.lambda2, catena::AsymptoticShapeFormula::Eq28);
        Vector printed = shape34.w;
        for (Index j = 0; j < printed.size(); ++j) {
          printed[j] +=
              (s.groups.eps * s.groups.eps * std::sin(s.groups.chord_angle_rad) - e1 * e1) *
              second_order_bracket(reference.s_m[j] / s.problem.cable.length_m, kl);
        }
        const auto d34 = shape_difference(shape34.w, shape34.u, reference);
        const auto d34p = shape_difference(printed, shape34.u, reference);
        const auto d28 = shape_difference(shape28.w, shape28.u, reference);
        const double tension =
            asym.inplane->modes[m].max_abs_tension_n / reference.max_abs_tension_n - 1.0;
        shapes.rows.push_back(
            {fmt::format("{}", eps), fmt::format("{}", phi_deg), fmt::format("{:.6g}", lambda2),
             fmt::format("{}", m + 1), fmt::format("{:.6f}", kl / catena::kPi),
             fmt::format("{:.6f}", reference.k_l_over_pi), fmt::format("{:.3e}", d34.first),
             fmt::format("{:.3e}", d34p.first), fmt::format("{:.3e}", d28.first),
             fmt::format("{:.3e}", d34.second), fmt::format("{:+.3e}", tension)});
      }
    }
  }
  catena::write_csv_table(directory + "/grinfogel-shapes-34-vs-airy.csv", shapes);

  catena::CsvTable sweep;
  sweep.comments = {
      "verification/comparisons/grinfogel-fig-4-3-2-tension.csv",
      "source:    Grinfogel (1984) Fig. 4.3.2: dynamic tension of the first mode vs lambda^2 near "
      "cross-over;",
      "           eq. (38) (asymptotic solver) vs Triantafyllou's Airy model (airy solver), eps = "
      "0.18,",
      "           phi = 23.46 deg, h = 1, L = 1 m, T0 = 1 N, M = 1 kg/m",
      "generator: verification/tools/analytic_grinfogel_shapes.cpp "
      "(catena_analytic_grinfogel_shapes)",
      catena_tools::generated_line(),
      "columns:   tension = max_s |tau| per unit max normal amplitude [N/m] (modal_result.hpp "
      "normalisation)",
  };
  sweep.columns = {"lambda2",          "k_l_over_pi_eq21", "tension_eq38",
                   "k_l_over_pi_airy", "tension_airy",     "tension_rel_diff"};
  catena::SolveRequest first = request;
  first.inplane_modes = 1;
  for (double lambda2 = 10.0; lambda2 <= 100.0 + 1e-9; lambda2 += 2.5) {
    const Solved s = make(0.18, 23.46, lambda2);
    const catena::SolverOutput airy = catena::solve_airy(s.problem, s.statics, s.groups, first);
    const catena::SolverOutput asym =
        catena::solve_asymptotic(s.problem, s.statics, s.groups, first);
    if (!airy.inplane || airy.inplane->modes.empty()) continue;
    const catena::Mode& a = asym.inplane->modes[0];
    const catena::Mode& b = airy.inplane->modes[0];
    sweep.rows.push_back({fmt::format("{:.1f}", lambda2), fmt::format("{:.6f}", a.k_l_over_pi),
                          fmt::format("{:.6g}", a.max_abs_tension_n),
                          fmt::format("{:.6f}", b.k_l_over_pi),
                          fmt::format("{:.6g}", b.max_abs_tension_n),
                          fmt::format("{:+.3e}", a.max_abs_tension_n / b.max_abs_tension_n - 1.0)});
  }
  catena::write_csv_table(directory + "/grinfogel-fig-4-3-2-tension.csv", sweep);
  return 0;
}
