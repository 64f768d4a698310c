// SPDX-License-Identifier: MIT
#pragma once
// The results JSON of issue 30 (docs/reference/json-layout.md, "Dynamic tension in waves"): the
// request's motion and each solver's dynamic tension. The key names `stations`, `s_m`, `mean_n`,
// `amplitude_n`, `std_n`, `fairlead`, `anchor`, `most_probable_max_n`, `damping_n_s_per_m2`,
// `iterations` and `residual` are the issue's, kept so that scripts can rely on them.

#include <nlohmann/json.hpp>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"

namespace catena::internal {

/// `request.motion`: direction, vector (in plane), amplitude_m and periods_s (regular), spectrum
/// or jonswap and rao (irregular), frequencies, duration_s, tolerance, max_iterations.
nlohmann::json motion_request_json(const MotionRequest& motion);

/// One excitation's record: motion ("regular" | "irregular"), period_s and omega_rad_s (regular),
/// stations, fairlead, anchor, damping_n_s_per_m2, tangential_damping_n_s_per_m2, spectrum
/// (irregular), iterations, residual, converged, relative_error_estimate, diagnostic.
nlohmann::json dynamic_tension_json(const DynamicTension& tension);

/// The list of a solver's excitations (one record each).
nlohmann::json dynamic_tension_list_json(const std::vector<DynamicTension>& tensions);

}  // namespace catena::internal
