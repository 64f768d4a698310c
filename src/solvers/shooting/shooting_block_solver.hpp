// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// CVODE's linear solver for a shot that carries the frequency derivative
/// (shooting_integrator.hpp, "Frequency derivative"). The state is [Y, phase, S] with Y and S of
/// `block` components each; the Jacobian is block lower triangular (Y does not depend on S, the
/// phase row and column are zero, S' = A S + dA Y), so the Newton matrix M = I - gamma J is
///
///     [ M_YY  0  0    ]
///     [ 0     1  0    ]
///     [ M_SY  0  M_SS ],
///
/// and a solve needs the LU factors of the two diagonal blocks only (8 x 8 in plane) instead of
/// the full 17 x 17 matrix, which made a shot with the slope 1.3-1.6x dearer than a plain one.

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

namespace catena::internal {

/// A SUNLinearSolver (direct, on CVODE's dense matrix) for the layout above; free it with
/// SUNLinSolFree. Null when SUNDIALS cannot allocate it.
SUNLinearSolver make_block_linear_solver(SUNContext context, int block);

}  // namespace catena::internal
