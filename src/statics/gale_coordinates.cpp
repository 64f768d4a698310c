// SPDX-License-Identifier: MIT
#include "catena/statics/gale_coordinates.hpp"

#include <cmath>

namespace catena {

double gale_xi_from_sigma(double sigma) {
  // sqrt(1 + s^2) - 1 = s^2 / (sqrt(1 + s^2) + 1): no cancellation for small sigma.
  return std::copysign(sigma * sigma / (std::sqrt(1.0 + sigma * sigma) + 1.0), sigma);
}

double gale_sigma_from_xi(double xi) {
  const double x = std::abs(xi);
  return std::copysign(std::sqrt(x * (x + 2.0)), xi);
}

}  // namespace catena
