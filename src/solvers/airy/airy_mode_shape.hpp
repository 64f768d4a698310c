// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The mode shape of the Airy model at a root (docs/explanation/methods/airy.md): the null vector
/// of the boundary system gives (C1, C2, C3, C4); w, u follow from the station rows and the dynamic
/// tension from the slow solution, tau = m omega^2 v with v = C1 Ai + C2 Bi.

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/airy/airy_model.hpp"

namespace catena::internal {

/// Travel time int_0^s sqrt(M/T) ds [s] of transverse waves to each of the ascending stations
/// [m]: the fast solution's phase there is W(s) = omega times it (independent of omega).
Vector transverse_travel_times(const StaticSolution& statics,
                               double normal_mass_kg_per_m,
                               const Vector& stations_m);

/// One mode on the stations (not normalised).
struct AiryModeShape {
  Vector w;          ///< transverse displacement
  Vector u;          ///< tangential displacement
  Vector tension_n;  ///< dynamic tension, in the same scaling
  /// sigma_min / sigma_max of the boundary system: how singular it is at this omega.
  double residual = 0.0;
};

/// The shape at omega [rad/s] (a root of the determinant) on `stations_m`, with the fast phases
/// W(s_j) = `phases` (omega times transverse_travel_times).
AiryModeShape airy_mode_shape(const AiryModel& model,
                              const StaticSolution& statics,
                              double omega,
                              const Vector& stations_m,
                              const Vector& phases);

}  // namespace catena::internal
