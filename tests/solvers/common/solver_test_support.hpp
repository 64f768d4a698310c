// SPDX-License-Identifier: MIT
#pragma once
// What every solver test does before asserting: the shared statics and groups of a problem, the
// solver's output, and a modes-only request. One place, so the solver tests stay about the solver.

#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::testing {

/// A problem with its statics and groups, and (once solved) a solver's output.
struct SolvedProblem {
  Problem problem;
  StaticSolution statics;
  DimensionlessGroups groups;
  SolverOutput output;
};

/// Statics and groups of `problem`; no solver run.
inline SolvedProblem prepare(const Problem& problem) {
  SolvedProblem solved{problem, solve_statics(problem), {}, {}};
  solved.groups = compute_dimensionless_groups(solved.problem, solved.statics);
  return solved;
}

/// prepare(), then `solve(problem, statics, groups, request, options)` (solve_fe, solve_shooting,
/// ...).
template <typename Solve, typename Options>
SolvedProblem solve_problem(Solve solve,
                            const Problem& problem,
                            const SolveRequest& request,
                            const Options& options) {
  SolvedProblem solved = prepare(problem);
  solved.output = solve(solved.problem, solved.statics, solved.groups, request, options);
  return solved;
}

/// A request for the lowest modes only (no shapes, tension or forcing).
/// The mooring line (L = 1000 m, W0 = 1000 N/m, EA = 5e8 N, m = 120 kg/m, added mass
/// 80 kg/m) anchored at the origin, its fairlead at `b` [m]; (900, 300) is
/// verification/scenes/physical/mooring-line-900m.toml.
inline Problem mooring_line(Vec2 b) {
  Problem problem;
  problem.cable.length_m = 1000.0;
  problem.cable.weight_n_per_m = 1000.0;
  problem.cable.axial_stiffness_n = 5e8;
  problem.cable.mass_kg_per_m = 120.0;
  problem.cable.added_mass_kg_per_m = 80.0;
  problem.supports.b_m = b;
  return problem;
}

inline SolveRequest modes_request(int inplane, int outofplane) {
  SolveRequest request;
  request.inplane_modes = inplane;
  request.outofplane_modes = outofplane;
  return request;
}

/// The frequencies of one plane's modes, lowest first [rad/s].
inline std::vector<double> omegas(const ModalResult& result) {
  std::vector<double> out;
  for (const Mode& mode : result.modes) out.push_back(mode.omega_rad_s);
  return out;
}

}  // namespace catena::testing
