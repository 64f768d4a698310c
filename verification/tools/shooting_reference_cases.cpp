// SPDX-License-Identifier: MIT
// Generates verification/comparisons/shooting-issue4-cases.csv: the six lowest in-plane and
// out-of-plane natural frequencies, by the `shooting` solver at rtol 1e-12, of the cases issue 4
// names for the cross-check against `fe` (Richardson, N = 2000, expected agreement 1e-7):
//   - the mooring line L = 1000 m, W0 = 1000 N/m, EA = 5e8 N, m = 120 kg/m, ma = 80 kg/m,
//     ends (0, 0) and (900, 300) m;
//   - taut inclined cables (make_taut_inclined_problem) with eps in {0.05, 0.49},
//     phi in {10, 45, 80} deg, lambda^2 in {1, 40, 400}, mass ratio 1.
// Each frequency carries the solver's relative error estimate and the conjugate-point count that
// proves no mode below it was skipped.
// Also writes verification/comparisons/shooting-grinfogel-2-2-comparison.csv: Grinfogel's (1984)
// 'exact' (Triantafyllou's Airy solution, asymptotic in eps) and 'approx' (his eq. 21) kL/pi
// beside the exact linear solution by shooting.
//
// Usage: catena_shooting_reference_cases [REPOSITORY_ROOT] (built with -DCATENA_BUILD_TOOLS=ON).
#include <fmt/format.h>

#include <cstdio>
#include <string>

#include "catena/io/csv_table.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "common/repository_paths.hpp"

int main(int argc, char** argv) {
  using namespace catena;
  const catena_tools::RepositoryPaths paths = catena_tools::repository_paths(argc, argv);
  struct Case {
    std::string name;
    Problem problem;
  };
  std::vector<Case> cases;
  Problem mooring;
  mooring.cable.length_m = 1000.0;
  mooring.cable.weight_n_per_m = 1000.0;
  mooring.cable.axial_stiffness_n = 5e8;
  mooring.cable.mass_kg_per_m = 120.0;
  mooring.cable.added_mass_kg_per_m = 80.0;
  mooring.supports.b_m = Vec2(900.0, 300.0);
  cases.push_back({"mooring-900-300", mooring});
  for (double eps : {0.05, 0.49}) {
    for (double phi : {10.0, 45.0, 80.0}) {
      for (double lambda2 : {1.0, 40.0, 400.0}) {
        cases.push_back({fmt::format("taut-eps{}-phi{}-lambda2-{}", eps, phi, lambda2),
                         make_taut_inclined_problem(eps, phi, lambda2, 1.0)});
      }
    }
  }
  CsvTable out;
  out.comments = {
      "verification/comparisons/shooting-issue4-cases.csv",
      "source:    shooting solver (CVODE Adams, rtol 1e-12, conjugate-point counting), issue 4 "
      "cross-check cases",
      "columns:   case, plane (in/out), mode, omega [rad/s], kL/pi [-], relative error estimate, "
      "count (eigenvalues proved below the top bracket of the plane)",
      "generator: verification/tools/shooting_reference_cases.cpp "
      "(catena_shooting_reference_cases)",
  };
  out.columns = {"case",        "plane",       "mode",
                 "omega_rad_s", "k_l_over_pi", "relative_error_estimate",
                 "proved_count"};
  for (const Case& c : cases) {
    const StaticSolution statics = solve_statics(c.problem);
    const DimensionlessGroups groups = compute_dimensionless_groups(c.problem, statics);
    SolveRequest request;
    request.inplane_modes = 6;
    request.outofplane_modes = 6;
    ShootingSolverOptions options;
    options.relative_tolerance = 1e-12;
    const SolverOutput output = solve_shooting(c.problem, statics, groups, request, options);
    if (output.summary.termination != Termination::Converged) {
      std::fprintf(stderr, "%s: %s\n", c.name.c_str(), output.summary.brief_report().c_str());
    }
    for (const auto* plane : {&output.inplane, &output.outofplane}) {
      if (!*plane) continue;
      for (const Mode& mode : (*plane)->modes) {
        out.rows.push_back({c.name, plane == &output.inplane ? "in" : "out",
                            std::to_string(mode.index), fmt::format("{:.15g}", mode.omega_rad_s),
                            fmt::format("{:.15g}", mode.k_l_over_pi),
                            fmt::format("{:.1e}", mode.relative_error_estimate),
                            std::to_string((*plane)->proved_count_below_top)});
      }
    }
  }
  write_csv_table(paths.comparisons + "/shooting-issue4-cases.csv", out);

  const CsvTable grinfogel =
      read_csv_table(paths.published + "/grinfogel-1984-table-2-2-frequencies.csv");
  CsvTable comparison;
  comparison.comments = {
      "verification/comparisons/shooting-grinfogel-2-2-comparison.csv",
      "source:    Grinfogel (1984) tables after Fig. 2.2 (published/grinfogel-1984-table-2-2-"
      "frequencies.csv): 'exact' = Triantafyllou's Airy solution (asymptotic in eps), 'approx' = "
      "eq. (21)",
      "method:    shooting solver, rtol 1e-12, make_taut_inclined_problem(eps, phi, lambda2, 1)",
      "columns:   eps, phi_deg, lambda2, mode, published exact and approx kL/pi, shooting kL/pi, "
      "exact - shooting, approx - shooting",
      "generator: verification/tools/shooting_reference_cases.cpp "
      "(catena_shooting_reference_cases)",
  };
  comparison.columns = {"eps",
                        "phi_deg",
                        "lambda2",
                        "mode",
                        "exact",
                        "approx",
                        "shooting",
                        "exact_minus_shooting",
                        "approx_minus_shooting"};
  for (std::size_t row = 0; row < grinfogel.rows.size(); ++row) {
    const double eps = *grinfogel.number(row, "eps");
    const double phi = *grinfogel.number(row, "phi_deg");
    const double lambda2 = *grinfogel.number(row, "lambda2");
    const int mode = static_cast<int>(*grinfogel.number(row, "mode"));
    const Problem problem = make_taut_inclined_problem(eps, phi, lambda2, 1.0);
    const StaticSolution statics = solve_statics(problem);
    const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
    SolveRequest request;
    request.inplane_modes = mode;
    request.outofplane_modes = 0;
    ShootingSolverOptions options;
    options.relative_tolerance = 1e-12;
    const SolverOutput output = solve_shooting(problem, statics, groups, request, options);
    const double ours = output.inplane->modes[static_cast<std::size_t>(mode - 1)].k_l_over_pi;
    comparison.rows.push_back({grinfogel.text(row, "eps"), grinfogel.text(row, "phi_deg"),
                               grinfogel.text(row, "lambda2"), grinfogel.text(row, "mode"),
                               grinfogel.text(row, "exact"), grinfogel.text(row, "approx"),
                               fmt::format("{:.6f}", ours),
                               fmt::format("{:+.4f}", *grinfogel.number(row, "exact") - ours),
                               fmt::format("{:+.4f}", *grinfogel.number(row, "approx") - ours)});
  }
  write_csv_table(paths.comparisons + "/shooting-grinfogel-2-2-comparison.csv", comparison);
  std::printf("%zu cases written\n", cases.size());
  return 0;
}
