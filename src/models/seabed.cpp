// SPDX-License-Identifier: MIT
#include "catena/models/seabed.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"

namespace catena {
namespace {

void require_finite_non_negative(double value, const char* field, const char* unit) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(
        fmt::format("Invalid seabed.{} = {}: must be finite and >= 0 [{}]", field, value, unit));
  }
}

}  // namespace

void Seabed::validate() const {
  if (!std::isfinite(z_m))
    throw InvalidInput(fmt::format("Invalid seabed.z = {}: must be finite [m]", z_m));
  require_finite_non_negative(friction, "friction", "-");
  require_finite_non_negative(stiffness_n_per_m2, "stiffness", "N/m per m");
  require_finite_non_negative(tangential_stiffness_n_per_m2, "tangential_stiffness", "N/m per m");
  require_finite_non_negative(damping_n_s_per_m2, "damping", "N s/m per m");
}

}  // namespace catena
