// Generates verification/reference/shooting-issue4-cases.csv: the six lowest in-plane and
// out-of-plane natural frequencies, by the `shooting` solver at rtol 1e-12, of the cases issue 4
// names for the cross-check against `fe` (Richardson, N = 2000, expected agreement 1e-7):
//   - the mooring line L = 1000 m, W0 = 1000 N/m, EA = 5e8 N, m = 120 kg/m, ma = 80 kg/m,
//     ends (0, 0) and (900, 300) m;
//   - taut inclined cables (make_taut_inclined_problem) with eps in {0.05, 0.49},
//     phi in {10, 45, 80} deg, lambda^2 in {1, 40, 400}, mass ratio 1.
// Each frequency carries the solver's relative error estimate and the conjugate-point count that
// proves no mode below it was skipped.
//
// Build and run from the repository root after building the library (Release):
//   g++ -O2 -std=c++20 -Iinclude -Isrc -I/usr/include/eigen3 \
//       verification/tools/shooting_reference_cases.cpp -o build/shooting_reference_cases \
//       -Lbuild -lcatena -lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixdense \
//       -lsundials_sunlinsoldense -lfmt
//   build/shooting_reference_cases verification/reference
#include <cstdio>
#include <fmt/format.h>
#include <string>

#include "catena/io/csv_table.hpp"
#include "catena/models/problem_builders.hpp"
#include "catena/solvers/shooting_solver.hpp"

int main(int argc, char** argv) {
  using namespace catena;
  const std::string reference = argc > 1 ? argv[1] : "verification/reference";
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
      "verification/reference/shooting-issue4-cases.csv",
      "source:    shooting solver (CVODE Adams, rtol 1e-12, conjugate-point counting), issue 4 "
      "cross-check cases",
      "columns:   case, plane (in/out), mode, omega [rad/s], kL/pi [-], relative error estimate, "
      "count (eigenvalues proved below the top bracket of the plane)",
      "generator: verification/tools/shooting_reference_cases.cpp (build command in its header)",
  };
  out.columns = {"case", "plane", "mode", "omega_rad_s", "k_l_over_pi", "relative_error_estimate",
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
  write_csv_table(reference + "/shooting-issue4-cases.csv", out);
  std::printf("%zu cases written\n", cases.size());
  return 0;
}
