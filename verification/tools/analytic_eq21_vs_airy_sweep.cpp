// SPDX-License-Identifier: MIT
// Regenerates verification/comparisons/grinfogel-eq21-vs-airy-sweep.csv: Grinfogel's eq. (21)
// (asymptotic solver) against Triantafyllou's Airy determinant (airy solver) over eps, phi and
// lambda^2, first 8 in-plane modes. Both are asymptotic models of the same cable, so their
// difference should be O(eps^2): the table gives, per (eps, phi), the largest relative frequency
// difference over 25 lambda^2 from 0.1 to 1e4 (log spaced), divided by eps^2, and where it
// occurs. Cases whose 8th mode reaches half the first axial frequency (which eq. 21 lacks) are
// skipped and counted. A missing Airy root would show up as a difference of order one.
//
// Usage: catena_analytic_eq21_vs_airy_sweep [REPOSITORY_ROOT] (built with -DCATENA_BUILD_TOOLS=ON).
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

int main(int argc, char** argv) {
  const catena_tools::RepositoryPaths paths = catena_tools::repository_paths(argc, argv);
  constexpr int kModes = 8;
  constexpr int kLambdaPoints = 25;
  catena::CsvTable out;
  out.comments = {
      "verification/comparisons/grinfogel-eq21-vs-airy-sweep.csv",
      "source:    eq. (21) (asymptotic solver) vs Triantafyllou's Airy determinant (airy solver, "
      "defaults)",
      "generator: verification/tools/analytic_eq21_vs_airy_sweep.cpp "
      "(catena_analytic_eq21_vs_airy_sweep)",
      catena_tools::generated_line(),
      "problem:   make_taut_inclined_problem(eps, phi_deg, lambda2, h = 1), lambda2 = 10^(-1 + 5 "
      "j/24), j = 0..24",
      "columns:   max_rel_diff_over_eps2 = max over lambda2 and modes 1..8 of |airy/eq21 - 1| / "
      "eps^2;",
      "           at_lambda2, at_mode: where; airy_short: cases where airy returned fewer than 8 "
      "modes;",
      "           skipped_axial: cases whose 8th eq. (21) root exceeds half the first axial "
      "frequency",
  };
  out.columns = {"eps",     "phi_deg",    "max_rel_diff_over_eps2", "at_lambda2",
                 "at_mode", "airy_short", "skipped_axial"};
  for (double eps : {0.01, 0.05, 0.1, 0.2, 0.3}) {
    for (double phi_deg : {1.0, 10.0, 30.0, 60.0, 85.0}) {
      double worst = 0.0, worst_lambda2 = 0.0;
      int worst_mode = 0, short_count = 0, skipped = 0;
      for (int j = 0; j < kLambdaPoints; ++j) {
        const double lambda2 = std::pow(10.0, -1.0 + 5.0 * j / (kLambdaPoints - 1));
        const catena::Problem problem =
            catena::make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0);
        const catena::StaticSolution statics = catena::solve_statics(problem);
        const catena::DimensionlessGroups groups =
            catena::compute_dimensionless_groups(problem, statics);
        catena::SolveRequest request;
        request.inplane_modes = kModes;
        const catena::SolverOutput airy = catena::solve_airy(problem, statics, groups, request);
        const auto eq21 = catena::grinfogel_eq21_roots(kModes, groups.eps, groups.chord_angle_rad,
                                                       groups.lambda2);
        if (eq21.back() > 0.5 * catena::first_axial_k_l(groups.eps, groups.chord_angle_rad,
                                                        groups.lambda2, 1.0)) {
          ++skipped;
          continue;
        }
        if (!airy.inplane || static_cast<int>(airy.inplane->modes.size()) < kModes) {
          ++short_count;
          continue;
        }
        for (int i = 0; i < kModes; ++i) {
          const double difference =
              std::abs(airy.inplane->modes[static_cast<std::size_t>(i)].k_l_over_pi /
                           (eq21[static_cast<std::size_t>(i)] / catena::kPi) -
                       1.0) /
              (eps * eps);
          if (difference > worst) {
            worst = difference;
            worst_lambda2 = lambda2;
            worst_mode = i + 1;
          }
        }
      }
      out.rows.push_back({fmt::format("{}", eps), fmt::format("{}", phi_deg),
                          fmt::format("{:.4f}", worst), fmt::format("{:.4g}", worst_lambda2),
                          fmt::format("{}", worst_mode), fmt::format("{}", short_count),
                          fmt::format("{}", skipped)});
    }
  }
  catena::write_csv_table(paths.comparisons + "/grinfogel-eq21-vs-airy-sweep.csv", out);
  return 0;
}
