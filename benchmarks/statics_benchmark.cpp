// SPDX-License-Identifier: MIT
// Statics: the (H, V_A) Newton solve of the elastic catenary, and the closed-form evaluation of
// the static state along the cable. Counters: Newton iterations and the closure error reached.
#include <benchmark/benchmark.h>

#include "catena/statics/elastic_catenary.hpp"
#include "catena/statics/problem_builders.hpp"

namespace {

using namespace catena;

Problem mooring() {
  Problem p;
  p.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
  p.supports.b_m = Vec2(900.0, 300.0);
  return p;
}

Problem deep_sag() {
  Problem p = make_gale_xi_problem(-6.0, 6.0);
  p.prescribed_forces.reset();  // make Newton do the work
  return p;
}

Problem taut_inclined() {
  Problem p = make_taut_inclined_problem(0.05, 30.0, 40.0, 1.0);
  p.prescribed_forces.reset();
  return p;
}

template <Problem (*make)()>
void BM_SolveStatics(benchmark::State& state) {
  const Problem problem = make();
  StaticSolution solution;
  for (auto _ : state) {
    solution = solve_statics(problem);
    benchmark::DoNotOptimize(solution);
  }
  state.counters["newton_iterations"] = solution.iterations;
  state.counters["closure_error_m"] = solution.closure_error_m;
}
BENCHMARK(BM_SolveStatics<mooring>)->Name("BM_SolveStatics/mooring")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveStatics<deep_sag>)
    ->Name("BM_SolveStatics/deep_sag_xi6")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolveStatics<taut_inclined>)
    ->Name("BM_SolveStatics/taut_inclined")
    ->Unit(benchmark::kMicrosecond);

void BM_EvaluateStaticState(benchmark::State& state) {
  const StaticSolution solution = solve_statics(mooring());
  double s = 0.0;
  for (auto _ : state) {
    s = s > 999.0 ? 0.0 : s + 0.37;
    benchmark::DoNotOptimize(solution.position_m(s));
    benchmark::DoNotOptimize(solution.tangent(s));
  }
}
BENCHMARK(BM_EvaluateStaticState)->Unit(benchmark::kNanosecond);

}  // namespace
