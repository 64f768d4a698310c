// SPDX-License-Identifier: MIT
#include "catena/solvers/solve_request.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"

namespace catena {

std::string to_string(CableEnd end) { return end == CableEnd::A ? "a" : "b"; }

std::string to_string(ForcingDirection direction) {
  switch (direction) {
    case ForcingDirection::Tangential:
      return "tangential";
    case ForcingDirection::Normal:
      return "normal";
    case ForcingDirection::GivenVector:
      return "vector";
    case ForcingDirection::OutOfPlane:
      return "out_of_plane";
  }
  return "?";
}

void SolveRequest::validate() const {
  auto require_in = [](const char* field, long value, long low, long high) {
    if (value < low || value > high) {
      throw InvalidInput(fmt::format("Invalid SolveRequest::{} = {}: must be in [{}, {}]", field,
                                     value, low, high));
    }
  };
  require_in("inplane_modes", inplane_modes, 0, kMaxRequestModes);
  require_in("outofplane_modes", outofplane_modes, 0, kMaxRequestModes);
  require_in("points", points, 2, kMaxRequestPoints);
  const long shape_values = shapes ? long(points) * (inplane_modes + outofplane_modes) : 0;
  if (shape_values > kMaxShapeValues) {
    throw InvalidInput(
        fmt::format("Invalid SolveRequest: points x modes = {} x {} = {} shape values: must be <= "
                    "{} (ask for fewer "
                    "points or modes)",
                    points, inplane_modes + outofplane_modes, shape_values, kMaxShapeValues));
  }
  if (forced && forced->omegas_rad_s.size() > kMaxForcingFrequencies) {
    throw InvalidInput(fmt::format(
        "Invalid ForcedRequest::omegas_rad_s: {} forcing frequencies, at most {} per request",
        forced->omegas_rad_s.size(), kMaxForcingFrequencies));
  }
  if (forced) {
    if (!std::isfinite(forced->amplitude_m) || forced->amplitude_m <= 0.0) {
      throw InvalidInput(
          fmt::format("Invalid ForcedRequest::amplitude_m = {}: must be finite and > 0 [m]",
                      forced->amplitude_m));
    }
    if (forced->omegas_rad_s.empty()) {
      throw InvalidInput(
          "Invalid ForcedRequest::omegas_rad_s: at least one forcing frequency needed");
    }
    for (double omega : forced->omegas_rad_s) {
      if (!std::isfinite(omega) || omega < 0.0) {
        throw InvalidInput(fmt::format(
            "Invalid ForcedRequest forcing frequency {} rad/s: must be finite and >= 0", omega));
      }
    }
    if (forced->direction == ForcingDirection::GivenVector &&
        (!forced->vector.allFinite() || forced->unit_vector().isZero(0.0))) {
      throw InvalidInput("Invalid ForcedRequest::vector: must be finite and non-zero");
    }
  }
  if (motion) motion->validate();
}

Vec2 ForcedRequest::unit_vector() const {
  const double largest = vector.cwiseAbs().maxCoeff();
  if (!std::isfinite(largest) || largest == 0.0) return Vec2::Zero();
  const Vec2 scaled = vector / largest;  // components in [-1, 1], one of them +-1
  return scaled / scaled.norm();
}

Vector SolveRequest::stations_m(double length_m) const {
  return Vector::LinSpaced(points, 0.0, length_m);
}

}  // namespace catena
