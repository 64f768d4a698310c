// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Each solver's registry entry, defined next to the solver (src/solvers/<name>_solver.cpp).

#include "catena/solvers/solver_registry.hpp"

namespace catena::internal {

SolverEntry make_fe_entry();
SolverEntry make_shooting_entry();
SolverEntry make_frobenius_entry();
SolverEntry make_asymptotic_entry();
SolverEntry make_airy_entry();

}  // namespace catena::internal
