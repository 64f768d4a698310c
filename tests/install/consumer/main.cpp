// SPDX-License-Identifier: MIT
// A user of the numerics alone (catena::catena, no scene files, no harness): the statics of the
// README's mooring line built in code, then its six lowest in-plane modes by shooting. Prints one
// line for the statics and one for the modes, in the format read_scene.cpp prints for the same
// cable read from verification/scenes/physical/mooring-line-900m.toml; the install_consumer test
// (tests/install/install_consumer.cmake) checks that the two agree.
#include <cstdio>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

int main() {
  catena::Problem problem;
  problem.cable.length_m = 1000.0;        // unstretched [m]
  problem.cable.weight_n_per_m = 1000.0;  // submerged [N/m]
  problem.cable.axial_stiffness_n = 5e8;  // EA [N]
  problem.cable.mass_kg_per_m = 120.0;
  problem.cable.added_mass_kg_per_m = 80.0;
  problem.supports.b_m = {900.0, 300.0};  // a = (0, 0)

  const catena::StaticSolution statics = catena::solve_statics(problem);
  std::printf("statics: %s\n", statics.brief_report().c_str());
  if (!statics.converged) return 1;

  const catena::DimensionlessGroups groups = catena::compute_dimensionless_groups(problem, statics);
  catena::SolveRequest request;
  request.inplane_modes = 6;
  const catena::SolverOutput output = catena::solve_shooting(problem, statics, groups, request);
  std::printf("shooting in-plane [Hz]:");
  for (const catena::Mode& mode : output.inplane->modes) std::printf(" %.9g", mode.frequency_hz);
  std::printf(" (%s)\n", catena::to_string(output.inplane->summary.termination).c_str());
  return output.inplane->summary.termination == catena::Termination::Converged ? 0 : 1;
}
