// SPDX-License-Identifier: MIT
// Time against error for every solver (issue 8): for each scene and solver, sweep the solver's
// resolution knob, time the solve (median of repeats), and measure the largest relative error of
// the first six in-plane frequencies against `shooting` at its tightest tolerance. Writes a CSV
// and prints, per scene, the time each solver needs to reach 1e-3, 1e-6 and 1e-9.
//
//   build/benchmarks/catena_time_vs_error [--out benchmarks/results/time-vs-error.csv] [--quick]
//
// Not a Google Benchmark: each point is a different configuration, and the error is the point.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"

namespace {

using namespace catena;

struct BenchScene {
  std::string name;
  Problem problem;
};

std::vector<BenchScene> scenes() {
  Problem mooring;
  mooring.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
  mooring.supports.b_m = Vec2(900.0, 300.0);
  return {
      {"shallow (eps 0.05, phi 0, lambda2 10)", make_taut_inclined_problem(0.05, 0.0, 10.0, 1.0)},
      {"inclined (eps 0.18, phi 23.46, lambda2 38)",
       make_taut_inclined_problem(0.18, 23.46, 38.0, 1.0)},
      {"deep sag (Gale xi = +-3, inextensible)", make_gale_xi_problem(-3.0, 3.0)},
      {"mooring (SI, L 1000 m)", mooring}};
}

struct Setting {
  std::string label;
  SolverKnobs knobs;
};

std::vector<Setting> settings(const std::string& solver, bool quick) {
  std::vector<Setting> out;
  if (solver == "fe") {
    for (long n : {25L, 50L, 100L, 200L, 400L, 800L, 1600L, 3200L, 6400L}) {
      if (quick && n > 800) break;
      out.push_back({fmt::format("N={}", n), {{"elements", n}, {"richardson", false}}});
      out.push_back({fmt::format("N={}+R", n), {{"elements", n}, {"richardson", true}}});
    }
  } else if (solver == "shooting") {
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12})
      out.push_back({fmt::format("rtol={:g}", rtol), {{"rtol", rtol}}});
  } else if (solver == "frobenius") {
    for (double tol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14}) {
      out.push_back({fmt::format("tol={:g}", tol), {{"tolerance", tol}}});
    }
  } else {
    out.push_back({"default", {}});
  }
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path = "benchmarks/results/time-vs-error.csv";
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc)
      out_path = argv[++i];
    else if (arg == "--quick")
      quick = true;
    else {
      std::fprintf(stderr, "usage: %s [--out FILE] [--quick]\n", argv[0]);
      return 2;
    }
  }
  std::ofstream csv(out_path);
  if (!csv) {
    std::fprintf(stderr, "cannot write %s\n", out_path.c_str());
    return 2;
  }
  csv << "# Time against error, first 6 in-plane frequencies vs shooting at rtol 1e-13.\n"
      << "# Machine: 2 cores; time = median wall time of repeated solves [s].\n"
      << "scene,solver,setting,time_s,max_rel_error,status\n";
  SolveRequest request;
  request.inplane_modes = 6;
  for (const auto& scene : scenes()) {
    const StaticSolution statics = solve_statics(scene.problem);
    const DimensionlessGroups groups = compute_dimensionless_groups(scene.problem, statics);
    const SolveContext context{scene.problem, statics, groups, request};
    const SolverEntry* shooting = find_solver("shooting");
    const SolverOutput reference = run_solver(*shooting, context, {{"rtol", 1e-13}});
    if (!reference.inplane || reference.inplane->modes.size() < 6) {
      std::printf("%s: no reference (%s)\n", scene.name.c_str(),
                  reference.summary.brief_report().c_str());
      continue;
    }
    std::printf("\n%s\n  reference: %s\n", scene.name.c_str(),
                reference.summary.brief_report().c_str());
    std::map<std::string, std::map<double, double>> fastest;  // solver -> target -> time
    for (const auto& entry : solver_registry()) {
      const SolverOutput probe = run_solver(entry, context, {});
      if (probe.summary.termination == Termination::NotApplicable) {
        std::printf("  %-10s not applicable: %s\n", entry.name.c_str(),
                    probe.summary.message.c_str());
        continue;
      }
      for (const auto& setting : settings(entry.name, quick)) {
        std::vector<double> times;
        SolverOutput output;
        const auto budget_start = std::chrono::steady_clock::now();
        while (times.size() < 3 || (times.size() < 15 && seconds_since(budget_start) < 0.3)) {
          const auto start = std::chrono::steady_clock::now();
          output = run_solver(entry, context, setting.knobs);
          times.push_back(seconds_since(start));
          if (seconds_since(budget_start) > 5.0) break;
        }
        std::sort(times.begin(), times.end());
        const double median = times[times.size() / 2];
        double error = std::nan("");
        if (output.inplane && output.inplane->modes.size() >= 6) {
          error = 0.0;
          for (int k = 0; k < 6; ++k) {
            const double a = output.inplane->modes[static_cast<std::size_t>(k)].omega_rad_s;
            const double b = reference.inplane->modes[static_cast<std::size_t>(k)].omega_rad_s;
            error = std::max(error, std::abs(a - b) / std::abs(b));
          }
        }
        csv << fmt::format("\"{}\",{},{},{:.6e},{:.6e},{}\n", scene.name, entry.name, setting.label,
                           median, error, to_string(output.summary.termination));
        std::printf("  %-10s %-12s %10.3f ms  error %.2e\n", entry.name.c_str(),
                    setting.label.c_str(), median * 1e3, error);
        for (double target : {1e-3, 1e-6, 1e-9}) {
          if (error <= target) {
            auto& best = fastest[entry.name];
            if (!best.count(target) || median < best[target]) best[target] = median;
          }
        }
      }
    }
    std::printf("  time to reach:        1e-3        1e-6        1e-9\n");
    for (const auto& [solver, best] : fastest) {
      std::printf("  %-12s", solver.c_str());
      for (double target : {1e-3, 1e-6, 1e-9}) {
        if (best.count(target))
          std::printf("  %8.3f ms", best.at(target) * 1e3);
        else
          std::printf("  %11s", "cannot");
      }
      std::printf("\n");
    }
  }
  std::printf("\nwrote %s\n", out_path.c_str());
  return 0;
}
