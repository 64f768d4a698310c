// SPDX-License-Identifier: MIT
// Time of the `shooting` solver for the six lowest in-plane or out-of-plane frequencies at the
// default tolerance (rtol 1e-10), on three scenes: Gale's symmetric catenary (h/b = 0, sag
// parameter 0.8, inextensible), the physical mooring line of issue 4 (L = 1000 m, W0 = 1000 N/m,
// EA = 5e8 N, m = 120 kg/m, ma = 80 kg/m, ends (0,0)-(900,300) m) and a taut inclined cable
// (eps 0.05, phi 45 deg, lambda^2 40). Targets (issue 4): <= 20 ms in plane, <= 5 ms out of plane.
// Variants: without the per-mode error-estimate shot, and with fixed-point iteration instead of
// the default Newton + dense LU.
// Counters: shots (integrations), CVODE RHS evaluations, the largest error estimate.
#include <benchmark/benchmark.h>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"

namespace catena {
namespace {

Problem mooring_line() {
  Problem problem;
  problem.cable.length_m = 1000.0;
  problem.cable.weight_n_per_m = 1000.0;
  problem.cable.axial_stiffness_n = 5e8;
  problem.cable.mass_kg_per_m = 120.0;
  problem.cable.added_mass_kg_per_m = 80.0;
  problem.supports.a_m = Vec2(0.0, 0.0);
  problem.supports.b_m = Vec2(900.0, 300.0);
  return problem;
}

Problem scene(int index) {
  switch (index) {
    case 0:
      return make_gale_sag_problem(0.0, 0.8);
    case 1:
      return mooring_line();
    default:
      return make_taut_inclined_problem(0.05, 45.0, 40.0, 1.0);
  }
}

void run(benchmark::State& state, bool inplane, bool error_estimate, bool fixed_point = false) {
  const Problem problem = scene(static_cast<int>(state.range(0)));
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  SolveRequest request;
  request.inplane_modes = inplane ? 6 : 0;
  request.outofplane_modes = inplane ? 0 : 6;
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-10;
  options.error_estimate = error_estimate;
  options.fixed_point_iteration = fixed_point;
  SolverOutput output;
  for (auto _ : state) {
    output = solve_shooting(problem, statics, groups, request, options);
    benchmark::DoNotOptimize(output);
  }
  state.counters["shots"] = static_cast<double>(output.summary.iterations);
  state.counters["rhs_evals"] = static_cast<double>(output.summary.operations);
  state.counters["max_err_est"] = output.summary.max_error_estimate;
  state.counters["converged"] = output.summary.termination == Termination::Converged ? 1.0 : 0.0;
}

void BM_ShootingInPlaneSixModes(benchmark::State& state) { run(state, true, true); }
void BM_ShootingOutOfPlaneSixModes(benchmark::State& state) { run(state, false, true); }
void BM_ShootingInPlaneSixModesNoErrorEstimate(benchmark::State& state) { run(state, true, false); }
void BM_ShootingInPlaneSixModesFixedPoint(benchmark::State& state) { run(state, true, true, true); }
void BM_ShootingOutOfPlaneSixModesFixedPoint(benchmark::State& state) {
  run(state, false, true, true);
}
void BM_ShootingOutOfPlaneSixModesNoErrorEstimate(benchmark::State& state) {
  run(state, false, false);
}

// Argument: scene 0 = Gale h/b 0 sag 0.8, 1 = mooring line, 2 = taut inclined.
BENCHMARK(BM_ShootingInPlaneSixModes)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShootingOutOfPlaneSixModes)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShootingInPlaneSixModesFixedPoint)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShootingOutOfPlaneSixModesFixedPoint)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShootingInPlaneSixModesNoErrorEstimate)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShootingOutOfPlaneSixModesNoErrorEstimate)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace catena

BENCHMARK_MAIN();
