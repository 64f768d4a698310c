// SPDX-License-Identifier: MIT
// Generates verification/comparisons/shooting-gale-B3-B4-comparison.csv: every printed entry of
// Gale (1976) Tables B-3 (in-plane) and B-4 (out-of-plane), w / sqrt(g/a) for the inextensible
// catenary, against the `shooting` solver run with EA = inf exactly.
//
// Each row of the tables gives the geometry twice: (h/b, sag parameter) and Gale's boundary
// coordinates (xi1, xi2). The cable is built from the geometry (make_gale_sag_problem, the
// defining input of the tables) and, separately, from the printed xi (make_gale_xi_problem); both
// frequencies are written, with the xi our geometry gives, so that a transcription error in either
// column shows up. An entry is flagged when |published - ours (geometry)| exceeds the printed
// rounding, 0.005 (two decimals).
//
// Usage: catena_shooting_gale_comparison [REPOSITORY_ROOT] (built with -DCATENA_BUILD_TOOLS=ON).
// rtol 1e-12: the frequencies are exact to ~1e-11, far below the printed two decimals.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "catena/io/csv_table.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "common/repository_paths.hpp"

namespace {

using namespace catena;

constexpr double kPrintedRounding = 0.005;

struct PlaneSolution {
  std::vector<double> ratios;
  std::vector<double> errors;
  double xi1 = 0.0, xi2 = 0.0;
};

PlaneSolution solve(const Problem& problem, bool inplane, int modes) {
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  SolveRequest request;
  request.inplane_modes = inplane ? modes : 0;
  request.outofplane_modes = inplane ? 0 : modes;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  const SolverOutput output = solve_shooting(problem, statics, groups, request, options);
  const auto& result = inplane ? output.inplane : output.outofplane;
  PlaneSolution solution;
  solution.xi1 = groups.xi1;
  solution.xi2 = groups.xi2;
  if (!result || output.summary.termination != Termination::Converged) {
    std::fprintf(stderr, "warning: %s\n", output.summary.brief_report().c_str());
  }
  if (result) {
    for (const Mode& mode : result->modes) {
      solution.ratios.push_back(mode.gale_ratio.value_or(-1.0));
      solution.errors.push_back(mode.relative_error_estimate);
    }
  }
  return solution;
}

}  // namespace

int main(int argc, char** argv) {
  const catena_tools::RepositoryPaths paths = catena_tools::repository_paths(argc, argv);
  CsvTable out;
  out.comments = {
      "verification/comparisons/shooting-gale-B3-B4-comparison.csv",
      "source:    Gale (1976) Tables B-3 (in-plane) and B-4 (out-of-plane), transcribed in "
      "published/gale-1976-table-B3-inplane.csv and published/gale-1976-table-B4-outofplane.csv",
      "method:    shooting solver (CVODE Adams, rtol 1e-12, EA = inf exactly), cable from "
      "(h_over_b, sag_param) and, separately, from the printed (xi1, xi2)",
      "columns:   table, h_over_b, sag_param, xi1/xi2 printed, xi1/xi2 from the geometry, mode, "
      "published w/sqrt(g/a), ours from the geometry, ours from the printed xi, difference "
      "(published - ours geometry), beyond_rounding (|difference| > 0.005), our relative error "
      "estimate",
      "generator: verification/tools/shooting_gale_comparison.cpp "
      "(catena_shooting_gale_comparison)",
  };
  out.columns = {"table",
                 "h_over_b",
                 "sag_param",
                 "xi1_printed",
                 "xi2_printed",
                 "xi1_geometry",
                 "xi2_geometry",
                 "mode",
                 "published",
                 "shooting_geometry",
                 "shooting_printed_xi",
                 "difference",
                 "beyond_rounding",
                 "relative_error_estimate"};
  int flagged = 0, total = 0;
  for (const auto& [name, file, inplane] :
       {std::tuple{"B-3", "gale-1976-table-B3-inplane.csv", true},
        std::tuple{"B-4", "gale-1976-table-B4-outofplane.csv", false}}) {
    const CsvTable table = read_csv_table(paths.published + "/" + file);
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
      const double h_over_b = *table.number(row, "h_over_b");
      const double sag = *table.number(row, "sag_param");
      const double xi1 = *table.number(row, "xi1");
      const double xi2 = *table.number(row, "xi2");
      int modes = 0;
      for (int n = 1; n <= 6; ++n) {
        if (table.number(row, fmt::format("w{}", n))) modes = n;
      }
      const PlaneSolution geometry = solve(make_gale_sag_problem(h_over_b, sag), inplane, modes);
      const PlaneSolution printed = solve(make_gale_xi_problem(xi1, xi2), inplane, modes);
      for (int n = 1; n <= modes; ++n) {
        const auto published = table.number(row, fmt::format("w{}", n));
        if (!published) continue;
        const std::size_t i = static_cast<std::size_t>(n - 1);
        const double ours = i < geometry.ratios.size() ? geometry.ratios[i] : -1.0;
        const double ours_xi = i < printed.ratios.size() ? printed.ratios[i] : -1.0;
        const double difference = *published - ours;
        const bool beyond = std::abs(difference) > kPrintedRounding;
        flagged += beyond;
        ++total;
        out.rows.push_back(
            {name, table.text(row, "h_over_b"), table.text(row, "sag_param"),
             table.text(row, "xi1"), table.text(row, "xi2"), fmt::format("{:.4f}", geometry.xi1),
             fmt::format("{:.4f}", geometry.xi2), std::to_string(n),
             table.text(row, fmt::format("w{}", n)), fmt::format("{:.6f}", ours),
             fmt::format("{:.6f}", ours_xi), fmt::format("{:+.6f}", difference),
             beyond ? "yes" : "no",
             fmt::format("{:.1e}", i < geometry.errors.size() ? geometry.errors[i] : -1.0)});
      }
    }
  }
  write_csv_table(paths.comparisons + "/shooting-gale-B3-B4-comparison.csv", out);
  std::printf("%d of %d published entries differ from shooting by more than %.3f\n", flagged, total,
              kPrintedRounding);
  return 0;
}
