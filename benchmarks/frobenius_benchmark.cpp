// SPDX-License-Identifier: MIT
// Benchmarks of the frobenius solver (Google Benchmark). Target: six in-plane frequencies of a
// Table B-3 row in at most 5 ms. Built with -DCATENA_BUILD_BENCHMARKS=ON (target
// catena_frobenius_benchmark).
// Measured 2026-11-23 on the shared 2-core machine, load ~0.9 (other helpers idle), tolerance
// 1e-12: B-3 row h/b=0.25, sag 0.90: 5.0 ms (140 determinant evaluations); tolerance 1e-8: 4.0 ms;
// h/b=0, sag 0.50: 6.4 ms; xi=+-8: 8.4 ms; six out-of-plane (B-4 row): 1.8 ms.
#include <benchmark/benchmark.h>

#include "catena/solvers/frobenius_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"

namespace {

using namespace catena;

void run(benchmark::State& state,
         const Problem& problem,
         int inplane,
         int outofplane,
         FrobeniusSolverOptions options) {
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  SolveRequest request;
  request.inplane_modes = inplane;
  request.outofplane_modes = outofplane;
  long evaluations = 0;
  for (auto _ : state) {
    SolverOutput output = solve_frobenius(problem, statics, groups, request, options);
    evaluations = output.summary.operations;
    benchmark::DoNotOptimize(output);
  }
  state.counters["det_evaluations"] = static_cast<double>(evaluations);
}

// Table B-3 row h/b = 0.25, sag 0.90 (xi = -0.173 .. 0.575): the 5 ms target above.
void BM_InPlaneSixB3Row(benchmark::State& state) {
  run(state, make_gale_sag_problem(0.25, 0.90), 6, 0, {});
}
BENCHMARK(BM_InPlaneSixB3Row)->Unit(benchmark::kMillisecond);

// A deeper B-3 row (h/b = 0, sag 0.50, xi = +-3.468: three expansion centres).
void BM_InPlaneSixB3DeepRow(benchmark::State& state) {
  run(state, make_gale_sag_problem(0.0, 0.50), 6, 0, {});
}
BENCHMARK(BM_InPlaneSixB3DeepRow)->Unit(benchmark::kMillisecond);

// Same row, coarser root scan (a quarter of the mode spacing) and looser tolerance.
void BM_InPlaneSixB3RowCoarseScan(benchmark::State& state) {
  FrobeniusSolverOptions options;
  options.scan_fraction = 0.25;
  run(state, make_gale_sag_problem(0.25, 0.90), 6, 0, options);
}
BENCHMARK(BM_InPlaneSixB3RowCoarseScan)->Unit(benchmark::kMillisecond);

void BM_InPlaneSixB3RowTolerance1e8(benchmark::State& state) {
  FrobeniusSolverOptions options;
  options.tolerance = 1e-8;
  run(state, make_gale_sag_problem(0.25, 0.90), 6, 0, options);
}
BENCHMARK(BM_InPlaneSixB3RowTolerance1e8)->Unit(benchmark::kMillisecond);

void BM_OutOfPlaneSixB4Row(benchmark::State& state) {
  run(state, make_gale_sag_problem(0.25, 0.90), 0, 6, {});
}
BENCHMARK(BM_OutOfPlaneSixB4Row)->Unit(benchmark::kMillisecond);

// Beyond the thesis: xi = +-8, six in-plane frequencies.
void BM_InPlaneSixDeepSagXi8(benchmark::State& state) {
  run(state, make_gale_xi_problem(-8.0, 8.0), 6, 0, {});
}
BENCHMARK(BM_InPlaneSixDeepSagXi8)->Unit(benchmark::kMillisecond);

}  // namespace
