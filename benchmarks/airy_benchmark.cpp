// SPDX-License-Identifier: MIT
// Benchmarks of the `airy` solver (Triantafyllou's Airy determinant): time for the first 6
// in-plane frequencies against the scan step (target <= 1 ms, issue 6), one determinant, and a
// stress scene with huge Airy arguments (phi = 0.01 deg, lambda^2 = 1e4). Counters: determinant
// evaluations, and the largest relative difference of the 6 roots from a fine-step (0.01) run,
// which shows that coarse steps lose nothing (close pairs come from the |det| minimum search).
//
// benchmarks/CMakeLists.txt is shared; to build by hand from the repository root:
// clang-format off
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -Isrc -I/usr/include/eigen3 benchmarks/airy_benchmark.cpp build/libcatena.a -lfmt -lbenchmark -lpthread -o build/airy_benchmark
// clang-format on
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "catena/solvers/airy_solver.hpp"
#include "catena/statics/problem_builders.hpp"

namespace {

struct Scene {
  explicit Scene(double eps = 0.18, double phi_deg = 23.46, double lambda2 = 38.0)
      : problem(catena::make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0)),
        statics(catena::solve_statics(problem)),
        groups(catena::compute_dimensionless_groups(problem, statics)) {}
  catena::Problem problem;
  catena::StaticSolution statics;
  catena::DimensionlessGroups groups;
};

double max_difference(const catena::SolverOutput& a, const catena::SolverOutput& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.inplane->modes.size(), b.inplane->modes.size()); ++i) {
    worst = std::max(
        worst, std::abs(a.inplane->modes[i].omega_rad_s / b.inplane->modes[i].omega_rad_s - 1.0));
  }
  return worst;
}

void run(benchmark::State& state, const Scene& scene) {
  catena::SolveRequest request;
  request.inplane_modes = 6;
  catena::AirySolverOptions options;
  options.scan_step_k_l_over_pi = static_cast<double>(state.range(0)) / 1000.0;
  catena::AirySolverOptions fine;
  fine.scan_step_k_l_over_pi = 0.01;
  const catena::SolverOutput reference =
      catena::solve_airy(scene.problem, scene.statics, scene.groups, request, fine);
  catena::SolverOutput out;
  for (auto _ : state) {
    out = catena::solve_airy(scene.problem, scene.statics, scene.groups, request, options);
    benchmark::DoNotOptimize(out.inplane);
  }
  state.counters["determinants"] = static_cast<double>(out.summary.operations);
  state.counters["max_rel_diff_vs_fine"] = max_difference(out, reference);
  state.counters["modes"] = static_cast<double>(out.inplane->modes.size());
}

void BM_AiryFrequencies(benchmark::State& state) { run(state, Scene()); }
BENCHMARK(BM_AiryFrequencies)->Arg(25)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);

void BM_AiryFrequenciesStress(benchmark::State& state) { run(state, Scene(0.05, 0.01, 1e4)); }
BENCHMARK(BM_AiryFrequenciesStress)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_AiryDeterminant(benchmark::State& state) {
  const Scene scene;
  double kl = 5.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        catena::airy_frequency_determinant(scene.problem, scene.statics, scene.groups, kl));
    kl += 1e-9;
  }
}
BENCHMARK(BM_AiryDeterminant)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
