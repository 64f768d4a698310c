// SPDX-License-Identifier: MIT
#pragma once
// Boundary problems for the tests of the frobenius solver's internal parts, in Gale's units.
#include <algorithm>
#include <cmath>

#include "solvers/frobenius/frobenius_boundary.hpp"

namespace catena::testing {

// The boundary problem of a catenary from sigma1 to sigma2 (sigma = V/H) with mass ratio mu, the
// series cut like the solver's at tolerance 1e-12.
inline internal::PlaneSetup frobenius_plane(bool inplane,
                                            double sigma1,
                                            double sigma2,
                                            double mu = 1.0) {
  internal::PlaneSetup setup;
  setup.inplane = inplane;
  setup.sigma1 = sigma1;
  setup.sigma2 = sigma2;
  setup.mu = mu;
  const double xi1 = std::sqrt(1.0 + sigma1 * sigma1) - 1.0,
               xi2 = std::sqrt(1.0 + sigma2 * sigma2) - 1.0;
  setup.eta_max = std::max(xi1, xi2) * (1.0 + 1e-12) + 1e-12;
  setup.settings.term_tolerance = 1e-15;
  setup.settings.max_terms = 600;
  setup.settings.step_ratio = 0.5;
  return setup;
}

}  // namespace catena::testing
