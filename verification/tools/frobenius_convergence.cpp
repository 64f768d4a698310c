// SPDX-License-Identifier: MIT
// Deep sag beyond Gale's thesis and convergence in the number of series terms.
// Writes verification/comparisons/frobenius-deep-sag.csv (h/b = 0, xi2 = -xi1 in {4, 6, 8}: six
// in-plane and six out-of-plane frequencies at tolerance 1e-12 and 1e-15, their difference, and an
// independent Boost.Odeint direct integration in sigma) and verification/comparisons/
// frobenius-convergence.csv (relative error of modes 1 and 6 vs the cap on terms per expansion,
// for a shallow case, h/b = 0, sag 0.90, and a deep one, xi = +-8).
// Usage: catena_frobenius_convergence [REPOSITORY_ROOT] (built with -DCATENA_BUILD_TOOLS=ON).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "catena/io/csv_table.hpp"
#include "catena/solvers/frobenius_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"
#include "common/repository_paths.hpp"
#include "common/sigma_ode.hpp"

using namespace catena;

namespace {

std::string fmt(double value, const char* format) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

struct Run {
  std::vector<double> in, out, in_err, out_err;
  std::string resolution_in, resolution_out;
};

Run solve(const Problem& problem, int modes, double tolerance, int max_terms) {
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  SolveRequest request;
  request.inplane_modes = modes;
  request.outofplane_modes = modes;
  FrobeniusSolverOptions options;
  options.tolerance = tolerance;
  options.max_terms = max_terms;
  const SolverOutput output = solve_frobenius(problem, statics, groups, request, options);
  Run run;
  for (const auto& m : output.inplane->modes) {
    run.in.push_back(*m.gale_ratio);
    run.in_err.push_back(m.relative_error_estimate);
  }
  for (const auto& m : output.outofplane->modes) {
    run.out.push_back(*m.gale_ratio);
    run.out_err.push_back(m.relative_error_estimate);
  }
  run.resolution_in = output.inplane->summary.resolution;
  run.resolution_out = output.outofplane->summary.resolution;
  return run;
}

// Independent: direct RKF78 integration in sigma (common/sigma_ode.hpp), bisection near a guess.
double odeint_root(bool inplane, double s1, double s2, double guess) {
  catena_tools::SigmaOdeSettings settings;
  settings.abs_tol = 1e-15;
  settings.rel_tol = 1e-14;
  settings.initial_divisions = 400.0;
  return catena_tools::bisect_natural_frequency(inplane, s1, s2, guess, 2e-3, 55, settings);
}

}  // namespace

int main(int argc, char** argv) {
  const catena_tools::RepositoryPaths paths = catena_tools::repository_paths(argc, argv);
  CsvTable deep;
  deep.comments = {
      "Deep sag beyond Gale (1976): h/b = 0, xi2 = -xi1 "
      "(verification/tools/frobenius_convergence.cpp).",
      "omega = w / sqrt(g/a). tol12 / tol15: solver tolerance 1e-12 / 1e-15 (more terms);",
      "rel_diff = |tol12 - tol15| / tol15; odeint: direct RKF78 integration in sigma (rtol 1e-14), "
      "independent."};
  deep.columns = {"xi2",      "plane",          "mode",         "omega_tol12",    "omega_tol15",
                  "rel_diff", "error_estimate", "omega_odeint", "rel_diff_odeint"};
  for (double xi : {4.0, 6.0, 8.0}) {
    const Problem problem = make_gale_xi_problem(-xi, xi);
    const double s2 = gale_sigma_from_xi(xi);
    const Run a = solve(problem, 6, 1e-12, 600);
    const Run b = solve(problem, 6, 1e-15, 2000);
    std::printf("xi = +-%.0f  (%s)\n", xi, b.resolution_in.c_str());
    for (int plane = 0; plane < 2; ++plane)
      for (int k = 0; k < 6; ++k) {
        const double x = plane == 0 ? a.in[k] : a.out[k];
        const double y = plane == 0 ? b.in[k] : b.out[k];
        const double e = plane == 0 ? a.in_err[k] : a.out_err[k];
        const double r = odeint_root(plane == 0, -s2, s2, y);
        std::printf("  %s mode %d: %.13f  %.13f  diff %.1e  est %.1e  odeint %.13f (%.1e)\n",
                    plane == 0 ? "in " : "out", k + 1, x, y, std::abs(x - y) / y, e, r,
                    std::abs(r - y) / y);
        deep.rows.push_back({fmt(xi, "%.0f"), plane == 0 ? "in" : "out", std::to_string(k + 1),
                             fmt(x, "%.13f"), fmt(y, "%.13f"), fmt(std::abs(x - y) / y, "%.1e"),
                             fmt(e, "%.1e"), fmt(r, "%.13f"), fmt(std::abs(r - y) / y, "%.1e")});
      }
  }
  write_csv_table(paths.comparisons + "/frobenius-deep-sag.csv", deep);

  CsvTable conv;
  conv.comments = {
      "Convergence of the frobenius solver in the number of series terms "
      "(verification/tools/frobenius_convergence.cpp).",
      "max_terms caps every expansion (tolerance 1e-15 so the cap binds); error relative to "
      "max_terms = 2000.",
      "Expansion centres at step_ratio 0.5 of the radius: terms decay like 0.5^N."};
  conv.columns = {"case",           "max_terms",       "in_mode1_error",
                  "in_mode6_error", "out_mode1_error", "out_mode6_error"};
  struct Case {
    std::string name;
    Problem problem;
  };
  for (const Case& c : {Case{"shallow h/b=0 sag=0.90", make_gale_sag_problem(0.0, 0.90)},
                        Case{"deep xi=+-8", make_gale_xi_problem(-8.0, 8.0)}}) {
    const Run ref = solve(c.problem, 6, 1e-15, 2000);
    std::printf(
        "%s: max_terms, relative error of in-plane modes 1, 6 and out-of-plane modes 1, 6\n",
        c.name.c_str());
    for (int terms : {8, 10, 12, 16, 20, 25, 30, 40, 50, 60, 80}) {
      const Run r = solve(c.problem, 6, 1e-15, terms);
      auto err = [](const std::vector<double>& v, const std::vector<double>& w, int k) {
        return k < static_cast<int>(v.size()) ? std::abs(v[k] - w[k]) / w[k] : NAN;
      };
      const double e1 = err(r.in, ref.in, 0), e6 = err(r.in, ref.in, 5),
                   o1 = err(r.out, ref.out, 0), o6 = err(r.out, ref.out, 5);
      std::printf("  %3d  %.1e  %.1e  %.1e  %.1e\n", terms, e1, e6, o1, o6);
      conv.rows.push_back({c.name, std::to_string(terms), fmt(e1, "%.1e"), fmt(e6, "%.1e"),
                           fmt(o1, "%.1e"), fmt(o6, "%.1e")});
    }
  }
  write_csv_table(paths.comparisons + "/frobenius-convergence.csv", conv);
  return 0;
}
