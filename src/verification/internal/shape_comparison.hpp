// SPDX-License-Identifier: MIT
#pragma once
// Comparing another program's mode shape (at its stations) with Catena's (at Catena's stations):
// MAC, and the dynamic tension after scaling the other mode to Catena's (docs/how-to/check.md,
// "Shapes").

#include <optional>
#include <string>

#include "catena/verification/external_check.hpp"

namespace catena::internal {

struct ShapeComparison {
  double mac = 0.0;
  /// max |alpha tau_other - tau_Catena| / max |tau_Catena| at the other's stations, alpha the
  /// least-squares factor taking the other's displacements to Catena's; absent without tensions.
  std::optional<double> tension_relative;
};

/// Checks that `shape` is well formed for `plane` (InvalidInput naming `origin`): stations
/// ascending within [0, length_m], components of the plane only (in-plane u and/or w, out-of-plane
/// v), every given vector as long as the stations, not all zero.
void validate_external_shape(const ExternalShape& shape,
                             Plane plane,
                             double length_m,
                             const std::string& origin);

/// MAC and tension difference of `shape` against `reference`, whose shape must be present.
ShapeComparison compare_shape(const ExternalShape& shape,
                              Plane plane,
                              const ReferenceMode& reference);

}  // namespace catena::internal
