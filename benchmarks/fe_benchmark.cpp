// SPDX-License-Identifier: MIT
// Benchmarks of the `fe` solver: time, work and accuracy of the lowest 10 modes.
//
// BM_FeStages/<plane>/<N>: one mesh, no Richardson: discrete statics + assembly + factorisation +
//   Lanczos iterations (+ the inertia factorisation), timed separately (counters statics_ms,
//   assembly_ms, factorization_ms, eigen_ms); peak_rss_mb is the process's peak resident set so far
//   (so read it on the largest N of a run). Targets (issue 3): in plane 10 modes at N = 1000
//   <= 2 ms, out of plane <= 1 ms; N = 1e4 .. 1e6 should scale linearly.
// BM_FeSolveDefault/<plane>/<N>: the public solve_fe with its defaults (Richardson: N and 2N).
//
// Scene: taut inclined cable eps = 0.1, phi = 20 deg, lambda^2 = 10, h = 1 (Grinfogel's groups).
// Run: ./build/benchmarks/catena_fe_benchmark
// --benchmark_out=benchmarks/results/<machine>-<date>.json
//      --benchmark_out_format=json
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>

#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/fe/fe_eigen.hpp"

namespace {

using namespace catena;
using Clock = std::chrono::steady_clock;

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const Problem& scene() {
  static const Problem problem = make_taut_inclined_problem(0.1, 20.0, 10.0, 1.0);
  return problem;
}

void BM_FeStages(benchmark::State& state) {
  const auto plane = state.range(0) == 0 ? Plane::InPlane : Plane::OutOfPlane;
  const auto elements = static_cast<int>(state.range(1));
  const Problem& problem = scene();
  const StaticSolution statics = solve_statics(problem);
  double statics_ms = 0.0, assembly_ms = 0.0, factorization_ms = 0.0, eigen_ms = 0.0, omega1 = 0.0;
  long operations = 0;
  for (auto _ : state) {
    auto start = Clock::now();
    const internal::FeChain chain =
        internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
    statics_ms += ms_since(start);
    start = Clock::now();
    const internal::FeMatrices matrices = plane == Plane::InPlane
                                              ? internal::assemble_inplane(chain)
                                              : internal::assemble_outofplane(chain);
    assembly_ms += ms_since(start);
    const internal::FeEigenSolution eigen = internal::solve_lowest_modes(matrices, 10, 1e-13, 1000);
    factorization_ms += 1e3 * eigen.factorization_time_s;
    eigen_ms += 1e3 * eigen.iteration_time_s;
    operations = eigen.operations;
    omega1 = eigen.eigenvalues.size() ? std::sqrt(eigen.eigenvalues[0]) : -1.0;
    if (eigen.inertia_count != 10) state.SkipWithError("inertia count != 10");
  }
  const auto iterations = static_cast<double>(state.iterations());
  state.counters["statics_ms"] = statics_ms / iterations;
  state.counters["assembly_ms"] = assembly_ms / iterations;
  state.counters["factorization_ms"] = factorization_ms / iterations;
  state.counters["eigen_ms"] = eigen_ms / iterations;
  state.counters["operations"] = static_cast<double>(operations);
  state.counters["omega1"] = omega1;
  state.counters["peak_rss_mb"] = peak_rss_mb();
}

void BM_FeSolveDefault(benchmark::State& state) {
  const Problem& problem = scene();
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  SolveRequest request;
  request.inplane_modes = state.range(0) == 0 ? 10 : 0;
  request.outofplane_modes = state.range(0) == 0 ? 0 : 10;
  FeSolverOptions options;
  options.elements = static_cast<int>(state.range(1));
  double error = 0.0;
  for (auto _ : state) {
    const SolverOutput output = solve_fe(problem, statics, groups, request, options);
    error = output.summary.max_error_estimate;
  }
  // -log10 of the largest relative error estimate (Google Benchmark prints small counters badly).
  state.counters["digits_estimate"] = error > 0.0 ? -std::log10(error) : 16.0;
}

}  // namespace

BENCHMARK(BM_FeStages)
    ->ArgNames({"outofplane", "N"})
    ->ArgsProduct({{0, 1}, {1000, 10000, 100000}})
    ->Unit(benchmark::kMillisecond);
// N = 1e6 (2e6 unknowns in plane): one iteration; the Lanczos basis alone is 2e6 x 30 doubles.
BENCHMARK(BM_FeStages)
    ->ArgNames({"outofplane", "N"})
    ->ArgsProduct({{0, 1}, {1000000}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FeSolveDefault)
    ->ArgNames({"outofplane", "N"})
    ->ArgsProduct({{0, 1}, {500, 1000}})
    ->Unit(benchmark::kMillisecond);
