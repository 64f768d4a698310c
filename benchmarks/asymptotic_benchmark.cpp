// SPDX-License-Identifier: MIT
// Benchmarks of the `asymptotic` solver (Grinfogel 1984): time for the first 6 in-plane
// frequencies (target <= 20 us, issue 6), with shapes and tension, and the bare eq. (21) roots.
// Scene: eps = 0.18, phi = 23.46 deg, lambda^2 = 38 (the paper's hybrid-region case).
//
// benchmarks/CMakeLists.txt is shared; to build by hand from the repository root:
// clang-format off
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -Isrc -I/usr/include/eigen3 benchmarks/asymptotic_benchmark.cpp build/libcatena.a -lfmt -lbenchmark -lpthread -o build/asymptotic_benchmark
// clang-format on
#include <benchmark/benchmark.h>

#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/statics/problem_builders.hpp"

namespace {

struct Scene {
  catena::Problem problem = catena::make_taut_inclined_problem(0.18, 23.46, 38.0, 1.0);
  catena::StaticSolution statics = catena::solve_statics(problem);
  catena::DimensionlessGroups groups = catena::compute_dimensionless_groups(problem, statics);
};

void BM_AsymptoticEq21Roots(benchmark::State& state) {
  const Scene scene;
  const int count = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto roots = catena::grinfogel_eq21_roots(count, scene.groups.eps, scene.groups.chord_angle_rad,
                                              scene.groups.lambda2);
    benchmark::DoNotOptimize(roots.data());
  }
}
BENCHMARK(BM_AsymptoticEq21Roots)->Arg(6)->Arg(24)->Unit(benchmark::kMicrosecond);

void BM_AsymptoticSolver(benchmark::State& state) {
  const Scene scene;
  catena::SolveRequest request;
  request.inplane_modes = static_cast<int>(state.range(0));
  request.outofplane_modes = static_cast<int>(state.range(1));
  request.shapes = state.range(2) != 0;
  request.tension = state.range(2) != 0;
  catena::SolverOutput out;
  for (auto _ : state) {
    out = catena::solve_asymptotic(scene.problem, scene.statics, scene.groups, request);
    benchmark::DoNotOptimize(out.inplane);
  }
  state.counters["iterations"] = static_cast<double>(out.summary.iterations);
  state.counters["error_estimate"] = out.summary.max_error_estimate;
}
BENCHMARK(BM_AsymptoticSolver)
    ->Args({6, 0, 0})
    ->Args({6, 6, 0})
    ->Args({6, 0, 1})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
